// "As typed": a Box2D preset run with the values a designer has in the game, pasted per joint under the
// names the engine table's Box2D 2.4 row uses ({"rear_suspension": {"b2WheelJointDef::stiffness": ...}}).
// The scene's joints then carry `typed` (docs/scenes.md, "What to type") instead of their tuning, the
// modal tuning goes, and the server runs and measures them as they are. Pure functions first (tested by
// tests/web/typed.test.mjs), then the panel.
import { fmt } from './results.js';

const DESIGNER_KEYS = ['response_frames', 'basis_fps', 'frequency_hz', 'oscillation', 'damping_ratio', 'mode'];

/// What a simulate answer tells the designer to type, per tuned joint: its engines.box2d_v2_4.parameters.
export function valuesToType(doc) {
  const out = {};
  for (const j of doc?.joints ?? []) {
    const values = j.tuned ? j.engines?.box2d_v2_4?.parameters : j.typed ? j.as_typed : null;
    if (values) out[j.id] = values;
  }
  return out;
}

/// `scene` with each joint named in `values` run as typed: its designer fields replaced by `typed`, and
/// without the modal tuning (nothing is solved). Oscillators that copy a typed joint's tuning, and their
/// probes, go (a typed joint has no tuning to copy). Throws an Error naming the joint that is not the scene's.
export function typedScene(scene, values) {
  const s = structuredClone(scene);
  const ids = new Set((s.joints ?? []).map((j) => j.id));
  for (const id of Object.keys(values)) {
    if (!ids.has(id)) throw new Error(`"${id}" is not a joint of ${s.name ?? 'this scene'}`);
  }
  for (const j of s.joints ?? []) {
    if (!(j.id in values)) continue;
    for (const k of DESIGNER_KEYS) delete j[k];
    j.typed = values[j.id];
  }
  delete s.modal_tuning;
  delete s.expectations;
  const dropped = new Set((s.oscillators ?? []).filter((o) => o.joint in values).map((o) => o.id));
  if (s.oscillators) s.oscillators = s.oscillators.filter((o) => !dropped.has(o.id));
  if (s.probes) s.probes = s.probes.filter((p) => !dropped.has(p.oscillator));
  return s;
}

/// The pasted text as {joint: {name: number}}; an Error saying what is wrong with it.
export function parseTyped(text) {
  let v;
  try {
    v = JSON.parse(text);
  } catch (e) {
    throw new Error(`not JSON: ${e.message}`);
  }
  if (!v || typeof v !== 'object' || Array.isArray(v)) throw new Error('give an object: {"joint id": {"b2…JointDef::stiffness": number, …}}');
  return v;
}

/// The panel: prefilled with what the last answer says to type; "Run as typed" simulates the preset with it
/// and lists each probe's measured frequency and damping ratio. `simulate(scene)` posts and returns the answer.
export function installTyped(root, simulate) {
  const area = root.querySelector('#typed-values');
  const note = root.querySelector('#typed-note');
  const body = root.querySelector('#typed-probes tbody');
  let scene = null;
  const panel = {
    /// A new answer of the preset `preset` (its scene document): the values it says to type, unless edited.
    show(presetScene, doc) {
      if (scene?.name !== presetScene?.name) delete area.dataset.edited;  // another preset: its own values
      scene = presetScene;
      root.hidden = !presetScene?.bodies?.length || Object.keys(valuesToType(doc)).length === 0;
      if (!area.dataset.edited) area.value = JSON.stringify(valuesToType(doc), null, 1);
    },
  };
  area.addEventListener('input', () => { area.dataset.edited = '1'; });
  root.querySelector('#typed-run').addEventListener('click', async () => {
    body.replaceChildren();
    try {
      const doc = await simulate(typedScene(scene, parseTyped(area.value)));
      note.textContent = `Run as typed: ${(doc.joints ?? []).filter((j) => j.typed).map((j) => j.id).join(', ')}; nothing tuned or solved.`;
      body.replaceChildren(...(doc.probes ?? []).filter((p) => p.measured?.frequency_hz !== null).map((p) => {
        const tr = document.createElement('tr');
        tr.dataset.probe = p.id;
        for (const text of [p.id, fmt(p.measured.frequency_hz), fmt(p.measured.damping_ratio)]) {
          const td = document.createElement('td');
          td.textContent = text;
          tr.append(td);
        }
        return tr;
      }));
    } catch (e) {
      note.textContent = `Not run: ${e.field ? `${e.field}: ` : ''}${e.message}`;
    }
  });
  return panel;
}
