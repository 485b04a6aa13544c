// The numbers of a tune response: the constants, requested against achieved, the warnings, a verdict
// per integrator with a suggested fix, and the clipboard (web/engine_table.js draws the engines).
import { formatDifference } from './engines.js';
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
  // The damping error is the difference of ratios (zeta may be asked 0), as in every table of the page.
  const dz = typeof req.damping_ratio === 'number' && typeof got.damping_ratio === 'number' ? got.damping_ratio - req.damping_ratio : null;
  const dampingError = root.querySelector('[data-testid="damping-error"]');
  dampingError.textContent = formatDifference(dz);
  dampingError.className = dz === null ? '' : Math.abs(dz) < 0.02 ? 'err-small' : Math.abs(dz) > 0.1 ? 'err-big' : '';
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
    // An unstable method has no frequency to speak of: its motion grows without bound.
    const blows = s.stable === false;
    const cells = [METHOD_LABELS[m], s.verdict, blows ? '—' : fmt(s.steps_per_period), blows ? 'blows up' : fmt(s.achieved_frequency_hz),
      blows ? 'blows up' : fmt(s.achieved_damping_ratio), suggestion(m, s, tune, fps, substeps)];
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

/// Puts text on the clipboard; true when it got there.
export async function copyText(text) {
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


/// The verdict of the soft method the request's mode chose, at this step ('' when unknown).
export function chosenVerdict(tune) {
  return tune?.stability?.[tune.mode === 'exact' ? 'soft_exact' : 'soft']?.verdict ?? '';
}

function putSummary(root, testid, text, title) {
  const el = root.querySelector(`[data-testid="${testid}"]`);
  el.textContent = text;
  if (title) el.title = title;
}

/// The summary bar beside the sliders: requested against achieved frequency and damping ratio, k, c, and
/// the chosen soft method's verdict at this step; `what` names the joint the numbers describe.
export function showSummary(root, tune, what) {
  const req = tune.requested ?? {}, got = tune.achieved ?? {};
  const put = (testid, text, title) => putSummary(root, testid, text, title);
  put('summary-frequency', `${fmt(req.frequency_hz)} → ${fmt(got.frequency_hz)} Hz`, 'requested → achieved at this step');
  put('summary-damping', `${fmt(req.damping_ratio)} → ${fmt(got.damping_ratio)}`, 'requested → achieved damping ratio');
  put('summary-k', fmt(tune.k), tune.mode === 'exact' ? "k' (exact mode)" : 'stiffness');
  put('summary-c', fmt(tune.c), tune.mode === 'exact' ? "c' (exact mode)" : 'damping');
  const verdict = chosenVerdict(tune);
  const el = root.querySelector('[data-testid="summary-verdict"]');
  el.textContent = `${verdict}${what ? ` · ${what}` : ''}`;
  el.className = verdict ? `verdict-${verdict}` : '';
}

/// The summary bar of a preset tuned by its modes: the picked mode's requested against measured (in the
/// Box2D run) frequency and damping ratio, and the first group's solved k and c, so that what stays in view
/// is the motion the designer tunes rather than one spring on its own mass.
export function showModalSummary(root, modal, verdict) {
  const t = modal?.targets?.[0];
  const g = modal?.groups?.[0];
  if (!t) return;
  const req = t.requested ?? {}, got = t.measured ?? {};
  const put = (testid, text, title) => putSummary(root, testid, text, title);
  put('summary-frequency', `${fmt(req.frequency_hz)} → ${fmt(got.frequency_hz)} Hz`, `${t.mode}: requested → measured in the simulation`);
  put('summary-damping', `${fmt(req.damping_ratio)} → ${fmt(got.damping_ratio)}`, `${t.mode}: requested → measured damping ratio`);
  put('summary-k', fmt(g?.stiffness), `each joint of ${g?.id ?? 'the group'}, solved for the mode`);
  put('summary-c', fmt(g?.damping), `each joint of ${g?.id ?? 'the group'}, solved for the mode`);
  // Honest: a mode measured more than 3 % or 0.03 off the request, or not measured, is not a plain "stable".
  const el = root.querySelector('[data-testid="summary-verdict"]');
  const df = percentError(req.frequency_hz, got.frequency_hz);
  const dz = typeof got.damping_ratio === 'number' && typeof req.damping_ratio === 'number' ? got.damping_ratio - req.damping_ratio : null;
  const off = df !== null && dz !== null && (Math.abs(df) > 3 || Math.abs(dz) > 0.03);
  const shown = df === null ? 'not measured' : off ? `off ${formatPercent(df)}, Δζ ${formatDifference(dz)}` : verdict ?? '';
  el.textContent = `${shown}${shown ? ' · ' : ''}${t.mode}`;
  el.className = df === null || off ? 'verdict-marginal' : verdict ? `verdict-${verdict}` : '';
  if (df === null && t.unmeasured) el.title = t.unmeasured;
}

