// The preset picker: the server's list of scenes, the picked scene's document, and the joint picker that
// says which of the scene's tuned joints the numbers describe (their effective masses come from the
// scene's bodies, as the simulation reports them).
import { ApiError, callJson, hasRoute } from './api.js';

/// Fills the <select> from GET /api/v1/presets; the text of a note when the list is unavailable.
export async function fillPresetList(select) {
  if (!hasRoute('GET', '/api/v1/presets')) return 'Presets are not available on this server: tune a custom body.';
  try {
    const doc = await callJson('GET', 'api/v1/presets');
    const list = Array.isArray(doc) ? doc : doc.presets ?? [];
    for (const item of list) {
      const name = typeof item === 'string' ? item : item.name;
      const option = new Option(typeof item === 'string' ? item : item.title ?? item.name, name);
      if (item.description) option.title = item.description;
      select.append(option);
    }
    return '';
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    select.disabled = e.unavailable;
    return e.unavailable ? 'Presets are not available on this server: tune a custom body.' : e.message;
  }
}

/// The preset's scene document, or null (with the reason) when the server cannot send it.
export async function fetchPresetScene(name) {
  if (!hasRoute('GET', '/api/v1/presets/{name}')) return { scene: null, note: 'This server cannot send preset scenes; the preset is simulated by name.' };
  try {
    const doc = await callJson('GET', `api/v1/presets/${encodeURIComponent(name)}`);
    return { scene: doc.scene ?? doc, note: '' };
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    return { scene: null, note: e.message };
  }
}

/// Whether a scene is drawn from Box2D (it has bodies), as against the 1-D oscillator preset.
export function isBox2dScene(scene) {
  return Array.isArray(scene?.bodies) && scene.bodies.length > 0;
}

/// Fills the joint picker with the scene's tuned joints, keeping `wanted` (a link's choice) when it is one.
export function fillJointPicker(select, joints, wanted) {
  const ids = joints.map((j) => j.id);
  if (select.options.length !== ids.length || [...select.options].some((o, i) => o.value !== ids[i])) {
    select.replaceChildren(...joints.map((j) => new Option(`${j.id} (${j.type})`, j.id)));
  }
  select.value = ids.includes(wanted) ? wanted : ids[0] ?? '';
  return select.value;
}
