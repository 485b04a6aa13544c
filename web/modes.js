// A Box2D preset's modes (POST /api/v1/modes, docs/scenes.md "Modes"): a list with each mode's frequency and
// damping ratio at the scene's step and a small arrow drawing of its shape; picking one makes the sliders tune
// that mode (the scene's modal_tuning target) instead of each spring on its own mass.
const SVG = 'http://www.w3.org/2000/svg';
/// The `target` control's value for "each spring on its own mass" (no modal tuning).
export const SPRINGS = 'springs';
const TUNING_KEYS = ['response_frames', 'basis_fps', 'frequency_hz', 'oscillation', 'damping_ratio', 'mode'];

const fmtHz = (p) => (p ? `${p.frequency_hz.toFixed(3)} Hz, ζ ${p.damping_ratio.toFixed(3)}` : '—');

/// The body and motion a mode is named by: its largest component.
export function modeTarget(mode) {
  const top = mode.components?.[0];
  return top ? { body: top.body, mode: top.motion } : null;
}

/// The `target` control's value for a pick: "body.motion" ("chassis.heave"), or SPRINGS for none.
export function targetKey(target) {
  return target ? `${target.body}.${target.mode}` : SPRINGS;
}

/// The pick a `target` value names (a body may have dots in its id: the motion follows the last one).
export function parseTarget(key) {
  const dot = key.lastIndexOf('.');
  return key === SPRINGS || dot <= 0 ? null : { body: key.slice(0, dot), mode: key.slice(dot + 1) };
}

/// The mode target a scene states itself (its modal_tuning's first target), or null.
export function sceneTarget(scene) {
  const t = scene?.modal_tuning?.targets?.[0];
  return t?.body && t?.mode ? { body: t.body, mode: t.mode } : null;
}

/// The scene as the `target` control asks for it: the scene's own modal tuning when the pick is the
/// scene's own target; without modal_tuning for SPRINGS; else the sliders' tuning on the picked mode.
export function targetedScene(scene, tuning, key) {
  if (key === targetKey(sceneTarget(scene))) return scene;
  const picked = parseTarget(key);
  if (picked) return modalScene(scene, tuning, picked);
  const s = structuredClone(scene);
  delete s.modal_tuning;
  return s;
}

/// The scene with the sliders' tuning on the picked mode: every designer-tuned joint in one group, solved so that
/// the mode has the asked frequency and damping (exact mode: at the scene's step). No pick: the scene as given.
export function modalScene(scene, tuning, picked) {
  if (!picked) return scene;
  const s = structuredClone(scene);
  const joints = (s.joints ?? []).filter((j) => TUNING_KEYS.some((k) => k in j)).map((j) => j.id);
  if (joints.length === 0) return scene;
  const { mode, ...ask } = tuning;  // the page's standard | exact is the solve's; a target's "mode" is its motion
  const target = { ...ask, body: picked.body, mode: picked.mode };
  s.modal_tuning = { mode: mode ?? 'standard', groups: [{ id: 'tuned', joints }], targets: [target] };
  return s;
}

/// The drawing of one mode's shape: per body a box, an arrow for its translation and an arc for its rotation,
/// scaled by the component amplitudes (the largest is 1). Returns an <svg> element.
export function modeArrows(mode, doc = document) {
  const bodies = [];
  for (const c of mode.components ?? []) {
    let b = bodies.find((x) => x.id === c.body);
    if (!b) bodies.push((b = { id: c.body, x: 0, y: 0, angle: 0 }));
    b[c.coordinate] = c.amplitude;
  }
  const shown = bodies.slice(0, 4);
  const w = 64 * Math.max(1, shown.length), h = 64;
  const svg = doc.createElementNS(SVG, 'svg');
  svg.setAttribute('viewBox', `0 0 ${w} ${h}`);
  svg.setAttribute('width', String(w));
  svg.setAttribute('height', String(h));
  svg.setAttribute('class', 'mode-shape');
  const add = (name, attrs, parent = svg) => {
    const e = doc.createElementNS(SVG, name);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
    parent.appendChild(e);
    return e;
  };
  shown.forEach((b, i) => {
    const cx = 32 + 64 * i, cy = 32;
    add('rect', { x: cx - 10, y: cy - 6, width: 20, height: 12, class: 'mode-body' });
    const len = 24, dx = len * b.x, dy = -len * b.y;  // SVG y points down
    if (Math.hypot(dx, dy) > 1) add('line', { x1: cx, y1: cy, x2: cx + dx, y2: cy + dy, class: 'mode-arrow', 'marker-end': 'url(#mode-head)' });
    if (Math.abs(b.angle) > 0.04) {
      const r = 16, sweep = Math.max(-2.5, Math.min(2.5, b.angle * 0.8));
      const x2 = cx + r * Math.cos(-sweep), y2 = cy + r * Math.sin(-sweep);
      add('path', { d: `M ${cx + r} ${cy} A ${r} ${r} 0 0 ${sweep > 0 ? 0 : 1} ${x2} ${y2}`, class: 'mode-arrow mode-turn', 'marker-end': 'url(#mode-head)' });
    }
    add('text', { x: cx, y: h - 2, 'text-anchor': 'middle', class: 'mode-label' }).textContent = b.id;
  });
  const defs = add('defs', {});
  const marker = add('marker', { id: 'mode-head', markerWidth: 6, markerHeight: 6, refX: 5, refY: 3, orient: 'auto' }, defs);
  add('path', { d: 'M0,0 L6,3 L0,6 z', class: 'mode-head' }, marker);
  return svg;
}

/// Fills `panel` with the modes of `answer` (the POST /api/v1/modes body): one row per mode that moves, each a
/// radio of the form's `target` control (state.js targetKey: "body.motion", or SPRINGS for each spring on its
/// own mass), `pickedKey` the one checked. The form's change handler takes a pick like any other control.
export function showModes(panel, answer, pickedKey, doc = document) {
  panel.replaceChildren();
  const title = doc.createElement('h3');
  title.textContent = `Modes at rest (t = ${answer.at_s.toFixed(2)} s${answer.settled ? '' : ', still moving'})`;
  panel.appendChild(title);
  const list = doc.createElement('ul');
  list.className = 'modes';
  const choice = (label, key) => {
    const li = doc.createElement('li');
    const input = doc.createElement('input');
    input.type = 'radio';
    input.name = 'target';
    input.value = key;
    input.checked = key === pickedKey;
    const text = doc.createElement('label');
    text.append(input, ` ${label}`);
    li.appendChild(text);
    list.appendChild(li);
    return li;
  };
  choice('each spring on its own mass', SPRINGS);
  let listed = pickedKey === SPRINGS;
  const seen = new Set();
  for (const m of answer.modes ?? []) {
    if (m.free || m.unstable) continue;
    const target = modeTarget(m);
    if (!target) continue;
    const key = targetKey(target);
    // A target names a body and its motion, so a second mode led by the same ("plank_7 heave 2") would pick
    // the same solve: only the first (the slowest) is offered.
    if (seen.has(key)) continue;
    seen.add(key);
    listed ||= key === pickedKey;
    // The label names what the pick asks for (the body and motion of the target it makes), so a mode named
    // for another body by its energy ("plank_2 heave") never stands for a pick of plank_1.
    const li = choice(`${target.body} ${target.mode}: ${fmtHz(m.discrete ?? m.continuous)}`, key);
    li.dataset.testid = 'mode';
    li.appendChild(modeArrows(m, doc));
  }
  // A target named by the scene (or a link) whose body is not the largest mover of any mode stays pickable.
  const picked = parseTarget(pickedKey);
  if (!listed && picked) choice(`${picked.body} ${picked.mode} (the scene's target)`, pickedKey).dataset.testid = 'mode';
  panel.appendChild(list);
}

/// The modes listing a simulate answer carries: a modal tuning's modes of the solved system ({at_s, settled,
/// modes}, as POST /api/v1/modes answers), or null when it has none.
export function modesOfAnswer(doc) {
  const m = doc?.modal_tuning;
  return m && Array.isArray(m.modes) ? { at_s: m.at_s ?? 0, settled: !!m.settled, modes: m.modes } : null;
}

/// The tune-shaped answer of joint `id` (or of the first solved joint) in a simulate answer of a modally tuned
/// scene: its solved k, c, the target asked, the mode measured, and each engine's values (the joint's
/// `engines`, which the server sends once, beside its `answer`); null when none.
export function solvedAnswer(doc, id) {
  const joints = (doc?.joints ?? []).filter((j) => j.answer);
  const j = joints.find((x) => x.id === id) ?? joints[0];
  return j ? { ...j.answer, engines: j.engines } : null;
}
