// The page's whole state is the form: every control has a `name`, and that name is its key in the URL
// query, so a link restores a tuning exactly. Only values that differ from the page's defaults are
// written, which keeps shared links short. This module also turns the state into API requests.

import { sceneTarget, targetedScene, targetKey } from './modes.js';

/// {name: value} of every named control; radios give the checked value ('' when none), checkboxes '1'/''.
export function readForm(form) {
  const state = {};
  for (const el of form.elements) {
    if (!el.name) continue;
    if (el.type === 'radio') {
      if (!(el.name in state)) state[el.name] = '';
      if (el.checked) state[el.name] = el.value;
    } else if (el.type === 'checkbox') {
      state[el.name] = el.checked ? '1' : '';
    } else {
      state[el.name] = el.value;
    }
  }
  return state;
}

export function writeForm(form, state) {
  for (const el of form.elements) {
    if (!el.name || !(el.name in state)) continue;
    const value = state[el.name];
    if (el.type === 'radio') el.checked = el.value === value;
    else if (el.type === 'checkbox') el.checked = value === '1';
    else if (el.tagName === 'SELECT' && ![...el.options].some((o) => o.value === value)) {
      // A preset that this server does not list yet: keep it so the list can select it when it loads.
      el.dataset.pending = value;
    } else el.value = value;
  }
}

/// The URL's one form (docs/page.md, "URL state"): each control under its own name, only values that
/// differ from `defaults`, in a stable order. A fine damping ratio is `zeta=0.25` alone (no `osc`: a
/// word's ratio follows from the word, so `zeta` is written only without one); an empty value (an inertia
/// left empty, a box unticked) is `none`, so no key is ever empty; keys that are not controls with a
/// default (the identify drop's engine) are not written.
export function toQuery(state, defaults) {
  const q = new URLSearchParams();
  for (const [k, v] of Object.entries(state)) {
    if (!(k in defaults)) continue;
    if (k === 'osc' && v === '') continue;
    if (k === 'zeta' && state.osc !== '') continue;
    if (v === defaults[k] && !(k === 'zeta' && defaults.osc !== '')) continue;
    q.set(k, v === '' ? EMPTY : v);
  }
  return q.toString();
}

/// How an empty value is written in a link (never an empty key).
const EMPTY = 'none';

/// The request's field names a link may use instead of the controls' (`?damping_ratio=0.25`,
/// `?response_frames=24`); the page writes the controls' names.
export const QUERY_ALIASES = { response_frames: 'frames', basis_fps: 'basis', oscillation: 'osc', damping_ratio: 'zeta',
  effective_mass: 'mass' };

/// The state a query string describes, on top of `defaults`; unknown keys are ignored. `words` is the
/// damping ratio of each oscillation word as the server documents it (api.js oscillationWords()). A link
/// carries an oscillation word (`osc=none`, which sets the fine slider) or a fine ratio (`zeta=0.25`,
/// which means no word); with both, the word wins. `none` is an empty value except as the word.
export function fromQuery(search, defaults, words = {}) {
  const state = { ...defaults };
  const given = new Set();
  for (const [key, v] of new URLSearchParams(search)) {
    const k = QUERY_ALIASES[key] ?? key;
    if (!(k in defaults)) continue;
    state[k] = v === EMPTY && k !== 'osc' ? '' : v;
    given.add(k);
  }
  if (given.has('zeta') && !given.has('osc')) state.osc = '';
  if (state.osc in words) state.zeta = String(words[state.osc]);
  return state;
}

/// A number field: undefined when empty (the API then names it if it is required); text that is not a
/// number is sent as is, so the server's problem names the field rather than the page guessing a value.
function num(text) {
  if (text === '' || text === undefined) return undefined;
  const n = Number(text);
  return Number.isFinite(n) ? n : text;
}

function body(state, p) {
  if (state[`${p}_static`] === '1') return 'static';
  const b = { mass: num(state[`${p}_mass`]), position: [num(state[`${p}_x`]), num(state[`${p}_y`])],
    angle: num(state[`${p}_angle`]) };
  const inertia = num(state[`${p}_inertia`]);
  if (inertia !== undefined) b.inertia = inertia;
  return b;
}

/// The designer fields shared by the tune request and a scene's soft joints (docs/api.md, "softtune tune").
export function tuningFields(state) {
  const t = { response_frames: num(state.frames), basis_fps: num(state.basis), mode: state.mode };
  if (state.osc) t.oscillation = state.osc;
  else t.damping_ratio = num(state.zeta);
  return t;
}

/// POST /api/v1/tune body. `jointMass` (kg, or kg m^2): the effective mass of the preset joint the numbers
/// describe, which its scene's bodies give (the page's own body controls then do not apply).
export function tuneRequest(state, jointMass) {
  const q = { fps: num(state.fps), substeps: num(state.substeps), ...tuningFields(state) };
  if (jointMass !== undefined) {
    q.effective_mass = jointMass;
  } else if (state.body === 'constraint') {
    q.constraint = {
      dimension: 2, type: state.ctype, body_a: body(state, 'a'), body_b: body(state, 'b'),
      anchor_a: [num(state.anchor_a_x), num(state.anchor_a_y)],
      anchor_b: [num(state.anchor_b_x), num(state.anchor_b_y)],
      axis: [num(state.axis_x), num(state.axis_y)],
    };
  } else {
    q.effective_mass = num(state.mass);
  }
  return JSON.parse(JSON.stringify(q));  // drops undefined fields
}

const TUNING_KEYS = ['response_frames', 'basis_fps', 'frequency_hz', 'oscillation', 'damping_ratio'];

/// The page's tuning of a preset's own joints: `tuning` of POST /api/v1/simulate and /preview (docs/api.md):
/// the world's step and the designer fields; the server gives it to every designer-tuned joint and
/// oscillator of the scene (server/app/scene_tuning.h).
export function sceneTuning(state) {
  return JSON.parse(JSON.stringify({ fps: num(state.fps), substeps: num(state.substeps), ...tuningFields(state) }));
}

/// The preset as the page tunes it: a request `softtune simulate --request` and POST /api/v1/simulate take.
/// By name while the `target` control asks what the preset's own scene does; otherwise its scene (`scene`,
/// once loaded) with the picked mode as the modal target, or without modal tuning (modes.js targetedScene).
export function presetRequest(state, scene) {
  const tuning = sceneTuning(state);
  const asked = scene && state.target ? targetedScene(scene, tuningFields(state), state.target) : scene;
  return asked === scene ? { preset: state.preset, tuning } : { scene: asked, tuning };
}

/// Controls a preset scene sets: the step, the mode pick, and the tuning of its modal target or else of its
/// first designer-tuned joint or oscillator (`words` as in fromQuery).
export function stateFromScene(scene, words = {}) {
  const out = {};
  if (scene.world?.fps !== undefined) out.fps = String(scene.world.fps);
  out.substeps = String(scene.world?.substeps ?? 1);
  out.target = targetKey(sceneTarget(scene));
  // A scene tuned by its modes: its target holds the designer's ask, its modal_tuning the soft mode (a
  // target's own "mode" names its motion).
  const target = scene.modal_tuning?.targets?.[0];
  const tuned = target && TUNING_KEYS.some((k) => k in target) ? { ...target, mode: scene.modal_tuning.mode }
    : [...(scene.oscillators ?? []), ...(scene.joints ?? [])].find((j) => TUNING_KEYS.some((k) => k in j));
  if (!tuned) return out;
  const basis = tuned.basis_fps ?? 60;
  out.basis = String(basis);
  if (tuned.response_frames !== undefined) out.frames = String(tuned.response_frames);
  else if (tuned.frequency_hz > 0) out.frames = String(Math.round(basis / tuned.frequency_hz));
  if (tuned.oscillation) {
    out.osc = tuned.oscillation;
    if (tuned.oscillation in words) out.zeta = String(words[tuned.oscillation]);
  } else if (tuned.damping_ratio !== undefined) {
    out.osc = '';
    out.zeta = String(tuned.damping_ratio);
  }
  out.mode = tuned.mode ?? 'standard';
  if (tuned.effective_mass !== undefined) {
    out.body = 'mass';
    out.mass = String(tuned.effective_mass);
  }
  return out;
}

/// The size the page asks previews in, and the cap on frames (render/include/softtune/render/frame_pipeline.h).
export const PREVIEW_SIZE = '480x270';
export const MAX_PREVIEW_FRAMES = 600;
/// Frames a browser shows per second at most: a scene is sampled at up to this rate for real-time playback.
export const PREVIEW_RATE = 30;

/// Frames of a preview covering `duration_s` at up to `rate` frames per second (both ends included).
export function previewFrames(durationS, rate) {
  return Math.max(2, Math.min(MAX_PREVIEW_FRAMES, Math.round(durationS * rate) + 1));
}

/// POST /api/v1/preview body. A Box2D preset: by name with the page's `tuning`, frames over its whole
/// duration at up to PREVIEW_RATE per second. The oscillator (a custom body, or the oscillator preset): the
/// tune fields with the effective mass the tune answer computed, one frame per game frame over at least
/// 1 s and three periods (`exact_motion.duration_s`). `wait: false` answers at once, so the progress bar
/// can follow the render.
export function previewRequest(state, tune, scene) {
  const settings = { size: PREVIEW_SIZE, wait: false };
  if (state.preset && state.preset !== 'oscillator') {
    const duration = scene?.world?.duration_s ?? 2;
    return { ...presetRequest(state, scene), frames: previewFrames(duration, Math.min(PREVIEW_RATE, num(state.fps) || PREVIEW_RATE)), ...settings };
  }
  const { constraint, ...fields } = tuneRequest(state);
  const duration = Math.max(1, tune.exact_motion?.duration_s ?? 1);
  return { ...fields, effective_mass: tune.effective_mass, frames: previewFrames(duration, num(state.fps)), ...settings };
}
