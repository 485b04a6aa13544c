// web/results.js, the summary bar of a modally tuned preset (showModalSummary): it says what the mode measured
// against the request, and its verdict is honest -- a mode more than 3 % or 0.03 off what was asked reads
// "off", one the run could not measure "not measured" (with why), never a plain green "stable".
// Run: node --test tests/web/results.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { showModalSummary } from '../../web/results.js';

function fakeRoot() {
  const els = {};
  return {
    els,
    querySelector(sel) {
      const id = /data-testid="([^"]+)"/.exec(sel)[1];
      els[id] ??= { textContent: '', title: '', className: '' };
      return els[id];
    },
  };
}

const modal = (measured, extra = {}) => ({
  groups: [{ id: 'suspension', stiffness: 24842.07, damping: 914.75 }],
  targets: [{ mode: 'chassis heave', requested: { frequency_hz: 3, damping_ratio: 0.5 }, measured, ...extra }],
});

test('a mode on its request keeps the soft method\'s verdict, with the solved k and c', () => {
  const root = fakeRoot();
  showModalSummary(root, modal({ frequency_hz: 3.003, damping_ratio: 0.499 }), 'stable');
  assert.equal(root.els['summary-verdict'].textContent, 'stable · chassis heave');
  assert.equal(root.els['summary-verdict'].className, 'verdict-stable');
  assert.equal(root.els['summary-k'].textContent, '24842.1');
  assert.equal(root.els['summary-frequency'].textContent, '3 → 3.003 Hz');
});

test('more than 3 % or 0.03 off reads "off", not "stable"; no measurement reads "not measured" and says why', () => {
  for (const measured of [{ frequency_hz: 3.1, damping_ratio: 0.5 }, { frequency_hz: 3.0, damping_ratio: 0.54 }]) {
    const root = fakeRoot();
    showModalSummary(root, modal(measured), 'stable');
    assert.match(root.els['summary-verdict'].textContent, /^off [+−-]?\d/);
    assert.equal(root.els['summary-verdict'].className, 'verdict-marginal');
  }
  const root = fakeRoot();
  showModalSummary(root, modal(null, { unmeasured: 'no probe of the scene measures this mode' }), 'stable');
  assert.equal(root.els['summary-verdict'].textContent, 'not measured · chassis heave');
  assert.equal(root.els['summary-verdict'].title, 'no probe of the scene measures this mode');
});
