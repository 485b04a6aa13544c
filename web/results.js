// The numbers of a tune response: the constants, requested against achieved, the warnings, a verdict
// per integrator with a suggested fix, and each engine's settings with a copy button.
import { METHODS, METHOD_LABELS } from './oscillator.js';

/// Six significant digits, exponent form for very large or small magnitudes; null (undefined in the
/// math, e.g. gamma with zero damping in exact mode) shows as a dash.
export function fmt(v) {
  if (v === null || v === undefined) return '—';
  if (typeof v !== 'number') return String(v);
  const a = Math.abs(v);
  if (a !== 0 && (a >= 1e6 || a < 1e-4)) return v.toExponential(5).replace(/\.?0+e/, 'e');
  return String(Number(v.toPrecision(6)));
}

/// (achieved - requested) / requested in percent, or null when the request is zero.
export function percentError(requested, achieved) {
  if (requested === null || achieved === null || requested === undefined || achieved === undefined) return null;
  if (requested === 0) return achieved === 0 ? 0 : null;
  return (100 * (achieved - requested)) / requested;
}

function setValue(root, testid, value, title) {
  const el = root.querySelector(`[data-testid="${testid}"]`);
  el.textContent = fmt(value);
  el.dataset.value = value === null || value === undefined ? '' : String(value);
  el.title = title ?? (value === null ? 'not defined for this tuning' : String(value));
}

/// A percentage with its sign and two decimals, rounded first so round-off reads 0.00 %, not -0.00 %.
export function formatPercent(p) {
  if (p === null || p === undefined) return '—';
  const shown = Math.round(p * 100) / 100 || 0;
  return `${shown > 0 ? '+' : ''}${shown.toFixed(2)} %`;
}

function setPercent(el, p) {
  el.textContent = formatPercent(p);
  el.className = p === null ? '' : Math.abs(p) < 2 ? 'err-small' : Math.abs(p) > 10 ? 'err-big' : '';
}

export function showNumbers(root, tune) {
  setValue(root, 'effective-mass', tune.effective_mass);
  setValue(root, 'k', tune.k, tune.mode === 'exact' ? "k' (exact mode)" : undefined);
  setValue(root, 'c', tune.c, tune.mode === 'exact' ? "c' (exact mode)" : undefined);
  setValue(root, 'gamma', tune.gamma);
  setValue(root, 'beta', tune.beta);
  setValue(root, 'erp', tune.erp);
  setValue(root, 'cfm', tune.cfm);
  setValue(root, 'gamma-impulse', tune.gamma_impulse);
  const req = tune.requested ?? {}, got = tune.achieved ?? {};
  setValue(root, 'requested-frequency', req.frequency_hz);
  setValue(root, 'achieved-frequency', got.frequency_hz);
  setValue(root, 'requested-damping', req.damping_ratio);
  setValue(root, 'achieved-damping', got.damping_ratio);
  setPercent(root.querySelector('[data-testid="frequency-error"]'), percentError(req.frequency_hz, got.frequency_hz));
  setPercent(root.querySelector('[data-testid="damping-error"]'), percentError(req.damping_ratio, got.damping_ratio));
  const list = root.querySelector('#warnings');
  list.replaceChildren(...(tune.warnings ?? []).filter((w) => !w.engine).map((w) => {
    const li = document.createElement('li');
    li.textContent = w.message;
    li.dataset.code = w.code;
    return li;
  }));
}

/// Smallest substep count n with 1 / (fps n) < h_max (the integrator's largest stable step).
export function substepsForStability(fps, maxStableH) {
  return Math.floor(1 / (fps * maxStableH)) + 1;
}

/// What a designer should do about one integrator, in plain words.
export function suggestion(name, s, tune, fps, substeps) {
  if (!s) return '';
  const requested = tune.requested?.frequency_hz ?? 0;
  if (!s.stable) {
    if (s.max_stable_h > 0) {
      return `blows up at this step: needs ${substepsForStability(fps, s.max_stable_h)} substeps, or use the soft constraint`;
    }
    return 'blows up at any step: use the soft constraint';
  }
  if (s.steps_per_period !== null && s.steps_per_period < 4) {
    const n = Math.ceil((4 * substeps) / s.steps_per_period);
    return `fewer than 4 steps per oscillation: needs ${n} substeps, or ask for a slower response`;
  }
  const err = percentError(requested, s.achieved_frequency_hz);
  if (err !== null && Math.abs(err) >= 5) {
    const how = err < 0 ? 'slow' : 'fast';
    if (name === 'soft' || name === 'implicit_euler') return `runs ${Math.abs(err).toFixed(0)} % ${how}: use exact mode or more substeps`;
    return `runs ${Math.abs(err).toFixed(0)} % ${how}: use more substeps`;
  }
  if (s.verdict === 'marginal') return 'never settles: it keeps oscillating at the same size';
  return 'fine';
}

export function showStability(root, tune, fps, substeps) {
  const body = root.querySelector('#stability tbody');
  body.replaceChildren(...METHODS.filter((m) => tune.stability?.[m]).map((m) => {
    const s = tune.stability[m];
    const tr = document.createElement('tr');
    tr.dataset.method = m;
    const labels = ['', 'verdict', 'steps per period', 'frequency (Hz)', 'damping', 'what to do'];
    const cells = [METHOD_LABELS[m], s.verdict, fmt(s.steps_per_period), fmt(s.achieved_frequency_hz),
      fmt(s.achieved_damping_ratio), suggestion(m, s, tune, fps, substeps)];
    for (const [i, text] of cells.entries()) {
      const td = document.createElement(i === 0 ? 'th' : 'td');
      if (i === 0) td.scope = 'row';
      else td.dataset.label = labels[i];
      td.textContent = text;
      if (i === 1) td.className = `verdict-${s.verdict}`;
      if (i === 5) td.dataset.testid = 'fix';
      tr.append(td);
    }
    return tr;
  }));
}

const n = (v) => (v === null || v === undefined ? 'null /* not representable */' : String(v));

/// Engine key -> [display name, settings text to paste]. Numbers at full precision.
const ENGINES = {
  box2d_v2_4: ['Box2D 2.4', (e) => [
    `jointDef.stiffness = ${n(e.stiffness)};  // N/m`,
    `jointDef.damping = ${n(e.damping)};  // N s/m`,
    ...(e.b2LinearStiffness?.stiffness != null
      ? [`// b2LinearStiffness would give stiffness ${e.b2LinearStiffness.stiffness}, damping ${e.b2LinearStiffness.damping}`,
        `// (reduced mass without rotation: ${fmt(100 * e.b2LinearStiffness.frequency_error)} % frequency error)`]
      : [])].join('\n')],
  box2d_v3: ['Box2D v3', (e) => [
    'def.enableSpring = true;',
    `def.hertz = ${n(e.hertz)};`,
    `def.dampingRatio = ${n(e.damping_ratio)};`,
    `// stays below the joint clamp of 0.25 / h = ${fmt(e.max_hertz)} Hz (headroom ${fmt(e.headroom)}x)`].join('\n')],
  jolt: ['Jolt', (e) => [
    `SpringSettings(ESpringMode::FrequencyAndDamping, ${n(e.frequency_and_damping?.frequency)}f, ${n(e.frequency_and_damping?.damping)}f)`,
    `SpringSettings(ESpringMode::StiffnessAndDamping, ${n(e.stiffness_and_damping?.stiffness)}f, ${n(e.stiffness_and_damping?.damping)}f)`].join('\n')],
  mujoco: ['MuJoCo', (e) => `solref="${(e.solref ?? []).map(n).join(' ')}"  <!-- ${e.form} form -->`],
  ode_bullet: ['ODE / Bullet', (e) => [
    `dJointSetParam(joint, dParamERP, ${n(e.erp)});`,
    `dJointSetParam(joint, dParamCFM, ${n(e.cfm)});`,
    `// Bullet: setParam(BT_CONSTRAINT_ERP, ${n(e.erp)}); setParam(BT_CONSTRAINT_CFM, ${n(e.cfm)});`].join('\n')],
  physx: ['PhysX', (e) => [
    `PxD6JointDrive(${n(e.acceleration?.stiffness)}f, ${n(e.acceleration?.damping)}f, PX_MAX_F32, true);  // acceleration drive`,
    `PxD6JointDrive(${n(e.force?.stiffness)}f, ${n(e.force?.damping)}f, PX_MAX_F32, false);  // force drive`].join('\n')],
  rapier: ['Rapier', (e) => [
    `.motor_model(axis, MotorModel::AccelerationBased).motor_position(axis, target, ${n(e.acceleration_based?.stiffness)}, ${n(e.acceleration_based?.damping)})`,
    `.motor_model(axis, MotorModel::ForceBased).motor_position(axis, target, ${n(e.force_based?.stiffness)}, ${n(e.force_based?.damping)})`].join('\n')],
};

async function copyText(text) {
  try {
    await navigator.clipboard.writeText(text);
    return true;
  } catch {
    // No clipboard permission (plain http on another host): select a hidden copy and use the old command.
    const area = document.createElement('textarea');
    area.value = text;
    area.setAttribute('readonly', '');
    area.style.position = 'fixed';
    area.style.opacity = '0';
    document.body.append(area);
    area.select();
    const ok = document.execCommand('copy');
    area.remove();
    return ok;
  }
}

export function showEngines(root, tune) {
  const body = root.querySelector('#engines tbody');
  const notes = (tune.warnings ?? []).filter((w) => w.engine);
  body.replaceChildren(...Object.entries(tune.engines ?? {}).map(([key, e]) => {
    const [label, snippet] = ENGINES[key] ?? [key, (x) => JSON.stringify(x, null, 1)];
    const text = snippet(e);
    const tr = document.createElement('tr');
    tr.dataset.engine = key;
    const th = document.createElement('th');
    th.scope = 'row';
    th.textContent = label;
    const td = document.createElement('td');
    const pre = document.createElement('pre');
    pre.textContent = text;
    td.append(pre);
    for (const w of notes.filter((w) => w.engine === key)) {
      const p = document.createElement('p');
      p.className = 'note';
      p.textContent = w.message;
      td.append(p);
    }
    const copy = document.createElement('td');
    const button = document.createElement('button');
    button.type = 'button';
    button.textContent = 'Copy';
    button.setAttribute('aria-label', `Copy the ${label} settings`);
    button.addEventListener('click', async () => {
      button.textContent = (await copyText(text)) ? 'Copied' : 'Copy failed';
      setTimeout(() => { button.textContent = 'Copy'; }, 1500);
    });
    copy.append(button);
    tr.append(th, td, copy);
    return tr;
  }));
}

export { copyText };
