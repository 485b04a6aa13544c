// web/input_flow.js: a refused input makes every earlier answer stale, an accepted one makes only the
// newest generation's answers showable, typing waits for the next key while a drag sends at once, and the
// debounced call runs once with the newest arguments after its own wait.
// Run: node --test tests/web/input_flow.test.mjs
import { test, mock } from 'node:test';
import assert from 'node:assert/strict';
import { Debounced, GESTURE_WAIT_MS, InputGenerations, TYPING_WAIT_MS, waitFor } from '../../web/input_flow.js';

test('an answer belongs only to the newest accepted input, and to none after a refusal', () => {
  const g = new InputGenerations();
  const typed1 = g.accept();       // "1" typed: its request goes out
  assert.ok(g.belongs(typed1));
  g.refuse();                      // "1e": refused, nothing sent
  assert.equal(g.belongs(typed1), false, 'the answer for "1" must not clear the refusal of "1e"');
  assert.equal(g.refused, true);
  const typed10 = g.accept();      // "10": accepted again
  assert.equal(g.belongs(typed1), false, 'nor overwrite the numbers of "10"');
  assert.ok(g.belongs(typed10));
  const slid = g.accept();
  assert.equal(g.belongs(typed10), false);
  assert.ok(g.belongs(slid));
});

test('typing in a number field waits for the next key; its commit, sliders and radios send after a short wait', () => {
  const number = { type: 'number' }, range = { type: 'range' }, radio = { type: 'radio' };
  assert.equal(waitFor({ type: 'input', target: number }), TYPING_WAIT_MS);
  assert.equal(waitFor({ type: 'change', target: number }), GESTURE_WAIT_MS);
  assert.equal(waitFor({ type: 'input', target: range }), GESTURE_WAIT_MS);
  assert.equal(waitFor({ type: 'change', target: radio }), GESTURE_WAIT_MS);
  assert.equal(waitFor(undefined), GESTURE_WAIT_MS);
  // Two keys of "60" at a typist's pace (about 100-200 ms apart) fall inside one wait.
  assert.ok(TYPING_WAIT_MS > 200 && GESTURE_WAIT_MS <= 50);
});

test('the debounced call runs once, with the newest arguments, after the newest call\'s own wait', () => {
  mock.timers.enable({ apis: ['setTimeout'] });
  try {
    const calls = [];
    let armed = 0;
    const d = new Debounced((x) => calls.push(x), { onArm: () => ++armed, onRelease: () => --armed });
    d.call(TYPING_WAIT_MS, '6');
    mock.timers.tick(150);
    d.call(TYPING_WAIT_MS, '60');  // the next key restarts the wait
    mock.timers.tick(TYPING_WAIT_MS - 1);
    assert.deepEqual(calls, []);
    assert.equal(armed, 1, 'the wait counts as pending work once');
    mock.timers.tick(1);
    assert.deepEqual(calls, ['60'], 'one request, for 60 fps, never one for 6 fps');
    assert.equal(armed, 0);
    // A shorter wait after a longer one: the newest call's wait counts.
    d.call(TYPING_WAIT_MS, 'a');
    d.call(GESTURE_WAIT_MS, 'b');
    mock.timers.tick(GESTURE_WAIT_MS);
    assert.deepEqual(calls, ['60', 'b']);
  } finally {
    mock.timers.reset();
  }
});

test('a cancelled call never runs, and releases its pending count once', () => {
  mock.timers.enable({ apis: ['setTimeout'] });
  try {
    const calls = [];
    let armed = 0;
    const d = new Debounced(() => calls.push('ran'), { onArm: () => ++armed, onRelease: () => --armed });
    d.call(GESTURE_WAIT_MS);
    d.cancel();
    d.cancel();
    assert.equal(armed, 0);
    mock.timers.tick(1000);
    assert.deepEqual(calls, []);
    assert.equal(d.armed, false);
  } finally {
    mock.timers.reset();
  }
});
