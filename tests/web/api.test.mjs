// web/api.js: a stale answer never overwrites a fresh one, refusals carry the field they name, and a
// missing route reads as "unavailable".
// Run: node --test tests/web/api.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { ApiError, Latest } from '../../web/api.js';

const later = (ms, value) => new Promise((r) => setTimeout(() => r(value), ms));

test('a slow older answer is dropped when a newer call started, and its request is aborted', async () => {
  const channel = new Latest();
  let firstSignal;
  // The older call ignores its abort signal on purpose, like a server that answers anyway.
  const first = channel.run((signal) => { firstSignal = signal; return later(60, 'old'); });
  const second = channel.run(() => later(10, 'new'));
  assert.equal(await second, 'new');
  assert.equal(await first, Latest.stale);
  assert.equal(firstSignal.aborted, true);
});

test('an error from an older call is dropped too; the newest call\'s error reaches the caller', async () => {
  const channel = new Latest();
  const first = channel.run(() => later(30).then(() => { throw new ApiError(422, { field: 'fps', detail: 'old' }); }));
  const second = channel.run(() => later(5).then(() => { throw new ApiError(422, { field: 'substeps', detail: 'new' }); }));
  await assert.rejects(second, (e) => e.field === 'substeps' && e.message === 'new');
  assert.equal(await first, Latest.stale);
});

test('problem documents: field, detail and which statuses mean the route is missing', () => {
  const e = new ApiError(422, { field: 'constraint.body_b.mass', detail: 'must be positive', title: 'Invalid field' });
  assert.equal(e.field, 'constraint.body_b.mass');
  assert.equal(e.message, 'must be positive');
  assert.equal(e.unavailable, false);
  for (const status of [404, 405, 501]) assert.equal(new ApiError(status, null).unavailable, true);
  assert.equal(new ApiError(500, null).message, 'HTTP 500');
});

test('cancel makes the call in flight stale and aborts it, without starting another', async () => {
  const channel = new Latest();
  let signal;
  const first = channel.run((s) => { signal = s; return later(20, 'answer of a refused input'); });
  channel.cancel();
  assert.equal(signal.aborted, true);
  assert.equal(await first, Latest.stale);
  assert.equal(await channel.run(() => later(1, 'next')), 'next', 'the channel serves the next call');
});
