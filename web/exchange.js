// Export and import of the page's tuning as a JSON file that `softtune simulate --request FILE` and
// POST /api/v1/simulate take unchanged: {"preset": NAME, "tuning": {...}} for a preset as it stands, its
// scene with the picked mode target (or without modal tuning) and the tuning when another mode was picked,
// the one-body scene the page simulates for a custom body. Importing such a file (or a tune request) sets
// the controls.
import { sceneTarget, targetKey } from './modes.js';
import { stateFromScene } from './state.js';

// The controls of a preset request's `tuning` (the step and the designer fields), none it leaves out.
function stateFromTuning(t, words) {
  const state = stateFromScene({ world: { fps: t.fps, substeps: t.substeps }, joints: [t] }, words);
  if (t.fps === undefined) delete state.fps;
  if (t.substeps === undefined) delete state.substeps;
  delete state.target;  // a tuning names no mode: the preset's own target stands
  return state;
}

/// The file's name for a state: softtune-<preset or custom>.json.
export function exportName(state) {
  return `softtune-${state.preset || 'custom'}.json`;
}

/// The controls a document describes: {preset, ...controls}; throws an Error saying what it lacks.
/// Accepts a preset request with `tuning`, a scene (its world and first tuned item), or a tune request.
export function stateFromDocument(doc, words) {
  if (!doc || typeof doc !== 'object' || Array.isArray(doc)) throw new Error('the file is not a JSON object');
  if (typeof doc.preset === 'string') return { preset: doc.preset, ...stateFromTuning(doc.tuning ?? {}, words) };
  // A preset's scene exported with another mode picked: the preset by its scene's name, the pick from its
  // modal tuning (none: each spring on its own mass).
  if (doc.scene && doc.tuning && typeof doc.scene.name === 'string' && doc.scene.name) {
    return { preset: doc.scene.name, ...stateFromTuning(doc.tuning, words), target: targetKey(sceneTarget(doc.scene)) };
  }
  const scene = doc.scene ?? doc;
  if (scene.world || scene.oscillators || scene.joints) return { preset: '', ...stateFromScene(scene, words) };
  if (doc.response_frames !== undefined || doc.frequency_hz !== undefined) {
    const state = stateFromScene({ world: { fps: doc.fps, substeps: doc.substeps }, oscillators: [doc] }, words);
    if (doc.fps === undefined) delete state.fps;
    return { preset: '', ...state };
  }
  throw new Error('the file holds no preset, scene or tuning (response_frames or frequency_hz)');
}

/// Offers `doc` as a download.
export function download(doc, name) {
  const url = URL.createObjectURL(new Blob([`${JSON.stringify(doc, null, 2)}\n`], { type: 'application/json' }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
