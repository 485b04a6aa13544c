// web/input_check.js: the API's details read in designer words (the control's name, no request field names).
// Run: node --test tests/web/input_check.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { designerMessage } from '../../web/input_check.js';

test('API details read in designer words', () => {
  assert.equal(designerMessage('give exactly one of effective_mass or constraint', 'Effective mass'),
    'Give exactly one of the effective mass or a 2-D constraint');
  assert.equal(designerMessage('must be > 0', 'Frame rate'), 'Frame rate must be > 0');
  assert.equal(designerMessage('fps * substeps must be <= 1e6', 'Substeps per frame'), 'The frame rate * the substeps must be <= 1e6');
  // Prose words that are also field names stay prose ("No the mode of the scene..." was shown once).
  assert.equal(designerMessage('no mode of the scene moves chassis in heave', 'Heave'), 'No mode of the scene moves chassis in heave');
  assert.equal(designerMessage('each fps of the rates must be > 0', ''), 'Each fps of the rates must be > 0');
  assert.equal(designerMessage('modal_tuning.targets.0.mode is unknown', ''), 'Modal_tuning.targets.0.mode is unknown');
});
