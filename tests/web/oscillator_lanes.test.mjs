// web/oscillator_lanes.js: a lane's position at a time is the simulation's sample, and "blew up" once past five
// amplitudes, for good.
// Run: node --test tests/web/oscillator_lanes.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { laneValue, oscillatorLanes } from '../../web/oscillator_lanes.js';

test('an oscillator lane blows up once it passes five amplitudes, and stays blown up', () => {
  const [lane] = oscillatorLanes([{ id: 'e', kind: 'oscillator', series: { time: [0, 1, 2, 3], value: [0.1, -0.3, 0.6, 0.2] } }]);
  assert.equal(laneValue(lane, 0.5), 0.1);
  assert.equal(laneValue(lane, 1), -0.3);
  assert.equal(laneValue(lane, 2.5), null, '0.6 is six amplitudes');
  assert.equal(laneValue(lane, 3), null, 'a blow-up does not come back');
});
