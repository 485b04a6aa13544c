// The page's whole state is the form: every control has a `name`, and that name is its key in the URL
// query, so a link restores a tuning exactly. Only values that differ from the page's defaults are
// written, which keeps shared links short. This module also turns the state into API requests.

/// The designer's oscillation words and the damping ratio each stands for (SPEC.md 1).
export const OSCILLATION_ZETA = { free: 0, some: 0.5, none: 1 };

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

/// The query string for `state`: the values that differ from `defaults`, in a stable order.
export function toQuery(state, defaults) {
  const q = new URLSearchParams();
  for (const [k, v] of Object.entries(state)) if (v !== defaults[k]) q.set(k, v);
  return q.toString();
}

/// The state a query string describes, on top of `defaults`; unknown keys are ignored.
export function fromQuery(search, defaults) {
  const state = { ...defaults };
  for (const [k, v] of new URLSearchParams(search)) if (k in defaults) state[k] = v;
  // A link carries either an oscillation word or a fine damping ratio; the word wins and sets the slider.
  if (state.osc in OSCILLATION_ZETA) state.zeta = String(OSCILLATION_ZETA[state.osc]);
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

/// POST /api/v1/tune body.
export function tuneRequest(state) {
  const q = { fps: num(state.fps), substeps: num(state.substeps), ...tuningFields(state) };
  if (state.body === 'constraint') {
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

/// A preset scene with the page's step and tuning applied: world fps and substeps, and the designer
/// fields of every soft joint and oscillator tuned in designer units. An item that names its own `mode`
/// keeps it (a preset may put standard and exact side by side); the others take the page's mode.
export function tunedScene(scene, state) {
  const s = structuredClone(scene);
  s.world = { ...s.world, fps: num(state.fps), substeps: num(state.substeps) };
  const { mode, ...tuning } = tuningFields(state);
  for (const item of [...(s.joints ?? []), ...(s.oscillators ?? [])]) {
    if (!TUNING_KEYS.some((k) => k in item)) continue;
    for (const k of TUNING_KEYS) delete item[k];
    Object.assign(item, tuning);
    item.mode ??= mode;
  }
  return JSON.parse(JSON.stringify(s));
}

/// Controls a preset scene sets: the step and the tuning of its first designer-tuned joint or oscillator.
export function stateFromScene(scene) {
  const out = {};
  if (scene.world?.fps !== undefined) out.fps = String(scene.world.fps);
  out.substeps = String(scene.world?.substeps ?? 1);
  const tuned = [...(scene.oscillators ?? []), ...(scene.joints ?? [])].find((j) => TUNING_KEYS.some((k) => k in j));
  if (!tuned) return out;
  const basis = tuned.basis_fps ?? 60;
  out.basis = String(basis);
  if (tuned.response_frames !== undefined) out.frames = String(tuned.response_frames);
  else if (tuned.frequency_hz > 0) out.frames = String(Math.round(basis / tuned.frequency_hz));
  if (tuned.oscillation) {
    out.osc = tuned.oscillation;
    out.zeta = String(OSCILLATION_ZETA[tuned.oscillation]);
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
