// web/summary_bar.js: the verdict reads "on target" within 3 % / 0.03 of the ask and "off by N %" past it,
// with the direction in words, at the bars' edges on both sides.
// Run: node --test tests/web/summary_bar.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { DAMPING_BAR, FREQUENCY_BAR, offBy } from '../../web/summary_bar.js';

const ask = { frequency_hz: 5, damping_ratio: 0.5 };

test('within 3 % and 0.03 of the ask reads "on target"', () => {
  assert.equal(FREQUENCY_BAR, 0.03);
  assert.equal(DAMPING_BAR, 0.03);
  assert.deepEqual(offBy(ask, { frequency_hz: 5, damping_ratio: 0.5 }), { text: 'on target', off: false });
  assert.deepEqual(offBy(ask, { frequency_hz: 5 * 1.0299, damping_ratio: 0.529 }), { text: 'on target', off: false });
  assert.deepEqual(offBy(ask, { frequency_hz: 5 * 0.9701, damping_ratio: 0.471 }), { text: 'on target', off: false });
});

test('past the bar: "off by N %" with the direction, and the bounce\'s difference', () => {
  // One decimal under 10 %, whole percents from 10 % on.
  assert.deepEqual(offBy(ask, { frequency_hz: 5 * (1 - 0.094), damping_ratio: 0.5 }), { text: 'off by 9.4 % (slower)', off: true });
  assert.deepEqual(offBy(ask, { frequency_hz: 5 * (1 - 0.106), damping_ratio: 0.5 }), { text: 'off by 11 % (slower)', off: true });
  assert.deepEqual(offBy(ask, { frequency_hz: 5 * 0.115, damping_ratio: 0.5 }), { text: 'off by 89 % (slower)', off: true });
  assert.deepEqual(offBy(ask, { frequency_hz: 5.2, damping_ratio: 0.5 }), { text: 'off by 4.0 % (faster)', off: true });
  assert.deepEqual(offBy(ask, { frequency_hz: 5, damping_ratio: 0.45 }), { text: 'bounce off by −0.05 (more bounce)', off: true });
  assert.deepEqual(offBy(ask, { frequency_hz: 4, damping_ratio: 0.6 }), { text: 'off by 20 % (slower), bounce +0.10 (less bounce)', off: true });
});

test('no verdict without a frequency to compare', () => {
  assert.equal(offBy(ask, { frequency_hz: null }), null);
  assert.equal(offBy({ frequency_hz: 0 }, { frequency_hz: 1 }), null);
  assert.equal(offBy(undefined, ask), null);
});
