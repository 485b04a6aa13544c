// Real-engine conformance for the engines that run under node (docs/engines.md, issue 15): for each case the real
// `softtune tune --request -` answers, the engine's report (engines.<name>: settings, parameters, predicted,
// exact, exact_predicted, warnings) is read, the oscillator is built in the real engine from those numbers
// alone, stepped, and fitted (prony.mjs); the fit is held against `predicted` and, for `exact`, against the
// request. Shared by tests/engines/jolt and tests/engines/rapier.
import { spawnSync } from 'node:child_process';

import { fitResponse, fitSlowPole } from './prony.mjs';

export const kFrequencyTolerance = 0.01;  // relative
export const kDampingTolerance = 0.02;    // absolute
/** Fit window floor for single-precision engines (prony.mjs). */
export const kEngineFitFloor = 1e-4;
/**
 * An over-damped response whose fast pole is below this per step call has lost it by the second sample:
 * step samples carry only the slow pole, so only its rate omega (zeta - sqrt(zeta^2 - 1)) is held (1 %).
 */
export const kUnobservablePole = 0.02;

// The two poles over one step call of a response (f, zeta): for zeta > 1, {slowRate, fast} with the fast
// pole's modulus; otherwise null.
function overDamped(frequencyHz, zeta, dt) {
  if (!(zeta > 1)) return null;
  const omega = 2 * Math.PI * frequencyHz, root = Math.sqrt(zeta * zeta - 1);
  return { slowRate: omega * (zeta - root), fast: Math.exp(-omega * (zeta + root) * dt) };
}

// Measures a trajectory against a response (f, zeta): {frequency (relative), damping (absolute)} for a
// fittable pair of poles, {slowRate (relative)} where the fast pole is unobservable, or null.
function measureAgainst(x, dt, frequencyHz, zeta, floor, fit = fitResponse) {
  const od = overDamped(frequencyHz, zeta, dt);
  if (od && od.fast < kUnobservablePole) {
    const slow = fitSlowPole(x, dt, 2, floor);
    return slow && { slowRate: slow.rate / od.slowRate - 1 };
  }
  const fitted = fit(x, dt, floor);
  return fitted && { frequency: fitted.frequencyHz / frequencyHz - 1, damping: fitted.dampingRatio - zeta,
                     measured: `${fitted.frequencyHz} Hz zeta ${fitted.dampingRatio}` };
}


/**
 * A refused plain export (engine_refuses) is still run: its `predicted` is what the engine does with it. With
 * no frequency it is either rigid (stable, spectral radius 1: the stretch holds within kRigid of x0) or lost
 * (unstable: the motion turns non-finite or leaves kGrown x0); a growing response (stable false) must leave
 * kGrown x0 where its spectral radius says it does within the run, and its start, up to kFitLimit x0 (the
 * plank's turn stays near linear), is fitted against the prediction when it holds kMinGrowthSamples samples.
 */
export const kRigid = 1e-3;
export const kGrown = 2;
export const kFitLimit = 4;
const kMinGrowthSamples = 24;

function grew(x) {
  return x.some((v) => !Number.isFinite(v) || Math.abs(v) > kGrown * Math.abs(x[0]));
}

function measureUnpredictable(x, p) {
  if (p.stable) return { rigid: Math.max(...x.map((v) => (Number.isFinite(v) ? Math.abs(v - x[0]) : Infinity))) / Math.abs(x[0]) };
  return { lost: grew(x) };
}

function measureGrowing(x, dt, p, floor, fitter = fitResponse) {
  // The envelope grows by the spectral radius per step: where that stays below 2 kGrown over the run (a
  // slow growth), the run need not leave kGrown x0, and the fit holds it instead.
  const visible = p.spectral_radius ** (x.length - 1) >= 2 * kGrown;
  const out = { grows: grew(x) || !visible };
  let end = x.findIndex((v) => !Number.isFinite(v) || Math.abs(v) > kFitLimit * Math.abs(x[0]));
  if (end < 0) end = x.length;
  if (end >= kMinGrowthSamples) {
    // The window grows to its end: the fit's floor, measured from the last sample, never cuts it.
    const fit = fitter(x.slice(0, end), dt, floor);
    if (fit) {
      out.frequency = fit.frequencyHz / p.frequency_hz - 1;
      out.damping = fit.dampingRatio - p.damping_ratio;
      out.measured = `${fit.frequencyHz} Hz zeta ${fit.dampingRatio}`;
    }
  }
  if (!visible && out.frequency === undefined) out.grows = false;  // neither seen to grow nor fitted
  return out;
}

function within(m) {
  if (m.rigid !== undefined) return m.rigid <= kRigid;
  if (m.lost !== undefined) return m.lost;
  if (m.grows !== undefined) {
    return m.grows && (m.frequency === undefined ||
                       (Math.abs(m.frequency) <= kFrequencyTolerance && Math.abs(m.damping) <= kDampingTolerance));
  }
  if (m.deadBeat !== undefined) return m.deadBeat;
  if (m.slowRate !== undefined) return Math.abs(m.slowRate) <= kFrequencyTolerance;
  return Math.abs(m.frequency) <= kFrequencyTolerance && Math.abs(m.damping) <= kDampingTolerance;
}

/** The tune answer of the real CLI (SOFTTUNE_BIN) for a request object. */
export function tune(request) {
  const bin = process.env.SOFTTUNE_BIN;
  if (!bin) throw new Error('SOFTTUNE_BIN is not set (ctest sets it to the softtune binary)');
  const out = spawnSync(bin, ['tune', '--request', '-'], { input: JSON.stringify(request), encoding: 'utf8' });
  if (out.status !== 0) throw new Error(`softtune tune failed (${out.status}): ${out.stderr}\n${JSON.stringify(request)}`);
  return JSON.parse(out.stdout);
}

/** The identify answer of the real CLI (SOFTTUNE_BIN) for a request object (docs/identify.md). */
export function identify(request) {
  const bin = process.env.SOFTTUNE_BIN;
  if (!bin) throw new Error('SOFTTUNE_BIN is not set (ctest sets it to the softtune binary)');
  const out = spawnSync(bin, ['identify', '--request', '-'], { input: JSON.stringify(request), encoding: 'utf8' });
  if (out.status !== 0) throw new Error(`softtune identify failed (${out.status}): ${out.stderr}`);
  return JSON.parse(out.stdout);
}

/** The fit of a trajectory sampled every dt: {frequencyHz, dampingRatio} or null (prony.mjs). */
export function fit(x, dt, floor = kEngineFitFloor) {
  return fitResponse(x, dt, floor);
}

/**
 * A deterministic grid of `count` cases: each dimension cycles with its own stride so every value of every
 * dimension appears and the combinations spread. `extra(i)` adds engine-specific fields (settings, body...).
 */
export function grid(count, extra) {
  const ratios = [0.005, 0.02, 0.05, 0.1, 0.2, 0.3];  // f / fps
  const zetas = [0, 0.02, 0.1, 0.3, 0.7, 1, 1.5, 2];
  const masses = [1e-3, 0.05, 1, 20, 1e3];
  const fpss = [30, 60, 120];
  const substeps = [1, 2, 3, 4, 8];
  const cases = [];
  for (let i = 0; i < count; ++i) {
    const fps = fpss[(i * 7) % fpss.length];
    const ratio = ratios[i % ratios.length];
    const request = {
      fps,
      substeps: substeps[(i * 3) % substeps.length],
      frequency_hz: ratio * fps,
      damping_ratio: zetas[(i * 5) % zetas.length],
      mode: Math.floor(i / 3) % 2 === 0 ? 'standard' : 'exact',
      effective_mass: masses[(i * 11) % masses.length],
    };
    cases.push({ index: i, request, ...extra(i, request) });
  }
  return cases;
}

/**
 * The refused plain exports' grid: exact mode at small damping ratios, where softtune's k', c' (matched at
 * the step 1 / (fps substeps)) have c' + h k' = 0 (zeta 0) or, at an engine substep shorter than that step,
 * below 0: what the engine does with them is its `predicted`. `extra(i)` adds the engine's settings.
 */
export function refusedGrid(count, extra) {
  const ratios = [0.02, 0.05, 0.1, 0.2];
  const zetas = [0, 0.01, 0.05];
  const masses = [0.05, 1, 20];
  const fpss = [30, 60, 120];
  const cases = [];
  for (let i = 0; i < count; ++i) {
    const fps = fpss[(i * 5) % fpss.length];
    const request = {
      fps,
      substeps: (i * 7) % 4 === 3 ? 2 : 1,
      frequency_hz: ratios[i % ratios.length] * fps,
      damping_ratio: zetas[(i * 7 + Math.floor(i / 12)) % zetas.length],
      mode: 'exact',
      effective_mass: masses[(i * 11 + Math.floor(i / 9)) % masses.length],
    };
    cases.push({ index: i, request, ...extra(i, request) });
  }
  return cases;
}

/**
 * Steps long enough for the fit: about 8 periods, within [120, maxSteps] step calls (Prony's fit is exact on a
 * linear recurrence, so a part of a slow period still fits when the engine's noise is small).
 */
export function stepsFor(request, maxSteps = 3000) {
  const perPeriod = (request.fps * request.substeps) / request.frequency_hz;
  return Math.max(120, Math.min(maxSteps, Math.ceil(8 * perPeriod)));
}

/**
 * A response whose every pole is below this per step call is dead within a few samples (a stiff spring at
 * zeta >= 1 near f/fps = 0.3): no trajectory fit can read it. Such a run is held to what the spectral radius
 * says instead: |x[n]| <= max(4 (n + 1) rho^n, 1e-5) x0 for n = 1..6, i.e. the engine does not ring.
 */
export const kDeadBeat = 0.1;

function deadBeatHolds(x, rho) {
  for (let n = 1; n <= 6 && n < x.length; ++n) {
    if (!(Math.abs(x[n]) <= Math.max(4 * (n + 1) * rho ** n, 1e-5) * Math.abs(x[0]))) return false;
  }
  return true;
}

function hasWarning(report, code) {
  return (report.warnings ?? []).some((w) => w.code === code);
}

/**
 * Runs every case through `run(caseObject, report, parameters, dt, steps)` (returns the trajectory) and
 * returns {rows, failures, table}. A row per case: what was measured for the plain export and for exact.
 * `fit(c)` gives the fit for a case's trajectories (x, dt, floor) -> {frequencyHz, dampingRatio} or null:
 * prony.mjs's second-order fitResponse unless the engine's motion is of higher order. `runRefused(c)` says
 * whether a case's refused plain export is run against its prediction (default all); one that is not is
 * counted in the table as not run.
 */
export function conform(engineName, cases, run,
                        { maxSteps = 3000, fitFloor = () => kEngineFitFloor, fit = () => fitResponse,
                          runRefused = () => true } = {}) {
  const rows = [];
  const failures = [];
  for (const c of cases) {
    const answer = tune(c.request);
    const report = answer.engines[engineName];
    if (!report || !report.parameters) throw new Error(`no engines.${engineName} report in the tune answer`);
    const dt = 1 / (c.request.fps * c.request.substeps);
    const steps = stepsFor(c.request, maxSteps);
    const row = { case: c, report };
    const label = `${engineName} #${c.index} ${JSON.stringify(c.request)} ${c.label ?? ''}`;
    // The plain export, against the model's prediction; a refused one too (what the engine does with it).
    const p = report.predicted;
    if (hasWarning(report, 'engine_refuses')) row.refused = true;
    if (row.refused && !runRefused(c)) {
      row.refusedNotRun = true;
    } else if (p.frequency_hz === null && !row.refused) {
      failures.push(`${label}: no prediction and no engine_refuses`);
    } else {
      const x = run(c, report, report.parameters, dt, steps);
      let m;
      if (p.frequency_hz === null) m = measureUnpredictable(x, p);
      else if (!p.stable) m = measureGrowing(x, dt, p, fitFloor(c), fit(c));
      else if (p.spectral_radius < kDeadBeat) m = { deadBeat: deadBeatHolds(x, p.spectral_radius) };
      else m = measureAgainst(x, dt, p.frequency_hz, p.damping_ratio, fitFloor(c), fit(c));
      if (!m) failures.push(`${label}: the plain run could not be fitted`);
      else {
        row.plain = m;
        if (!within(m)) {
          failures.push(`${label}: plain ${JSON.stringify(m)}, predicted ` +
                        `${p.frequency_hz} Hz zeta ${p.damping_ratio} radius ${p.spectral_radius} stable ${p.stable}` +
                        (row.refused ? ` (refused ${JSON.stringify(report.parameters)})` : ''));
        }
      }
    }
    // Exact, against the request.
    if (report.exact === null) {
      if (!hasWarning(report, 'engine_inexact')) failures.push(`${label}: exact is null without engine_inexact`);
      row.inexact = true;
    } else {
      // The nearest legal value (engine_inexact beside a non-null exact): its prediction is within 1 % / 0.02
      // of the request, and the engine runs that prediction.
      const ep = report.exact_predicted;
      row.nearest = hasWarning(report, 'engine_inexact');
      if (row.nearest && !(Math.abs(ep.frequency_hz / c.request.frequency_hz - 1) <= kFrequencyTolerance &&
                           Math.abs(ep.damping_ratio - c.request.damping_ratio) <= kDampingTolerance && ep.stable)) {
        failures.push(`${label}: the nearest exact's prediction ${JSON.stringify(ep)} is off the request`);
      }
      const aim = row.nearest ? ep : { frequency_hz: c.request.frequency_hz, damping_ratio: c.request.damping_ratio };
      const x = run(c, report, report.exact, dt, steps);
      const m = ep.spectral_radius < kDeadBeat
        ? { deadBeat: deadBeatHolds(x, ep.spectral_radius) }
        : measureAgainst(x, dt, aim.frequency_hz, aim.damping_ratio, fitFloor(c), fit(c));
      if (!m) failures.push(`${label}: the exact run could not be fitted`);
      else {
        row.exact = m;
        if (!within(m)) {
          failures.push(`${label}: exact ${JSON.stringify(m)}, asked ${c.request.frequency_hz} Hz zeta ` +
                        `${c.request.damping_ratio} (exact ${JSON.stringify(report.exact)})`);
        }
      }
    }
    rows.push(row);
  }
  return { rows, failures, table: table(engineName, rows) };
}

function worst(values) {
  return values.reduce((a, v) => Math.max(a, Math.abs(v)), 0);
}

/** The conformance table: cases, runs, and the worst errors against predicted and, for exact, the request. */
export function table(engineName, rows) {
  const fitted = (m) => m && m.frequency !== undefined && m.slowRate === undefined && m.deadBeat === undefined;
  const plain = rows.filter((r) => !r.refused && fitted(r.plain)).map((r) => r.plain);
  const refused = rows.filter((r) => r.refused);
  const refusedFitted = refused.filter((r) => fitted(r.plain)).map((r) => r.plain);
  const exact = rows.filter((r) => !r.nearest && fitted(r.exact)).map((r) => r.exact);
  const deadBeat = rows.filter((r) => r.plain?.deadBeat !== undefined).length +
                   rows.filter((r) => r.exact?.deadBeat !== undefined).length;
  const slowPlain = rows.filter((r) => r.plain && r.plain.slowRate !== undefined).map((r) => r.plain.slowRate);
  const slowExact = rows.filter((r) => r.exact && r.exact.slowRate !== undefined).map((r) => r.exact.slowRate);
  const fmt = (v) => (100 * v).toFixed(3) + ' %';
  return [
    `${engineName} conformance: ${rows.length} cases (${rows.filter((r) => r.case.request.mode === 'exact').length} exact mode, ` +
      `${rows.filter((r) => r.case.body === 'rotating_plank').length} rotating plank)`,
    `  plain export vs predicted: ${plain.length} runs, worst frequency ${fmt(worst(plain.map((p) => p.frequency)))}, ` +
      `worst damping ratio ${worst(plain.map((p) => p.damping)).toFixed(4)}; ${refused.length} refused (engine_refuses)`,
    `  refused exports run vs predicted: ${refusedFitted.length} fitted (worst frequency ` +
      `${fmt(worst(refusedFitted.map((p) => p.frequency)))}, worst damping ratio ` +
      `${worst(refusedFitted.map((p) => p.damping)).toFixed(4)}), ${refused.filter((r) => r.plain?.grows).length} growing ` +
      `as predicted, ${refused.filter((r) => r.plain?.rigid !== undefined).length} rigid, ` +
      `${refused.filter((r) => r.plain?.lost).length} lost (NaN) as predicted, ` +
      `${refused.filter((r) => r.case.request.mode === 'exact' && r.case.request.damping_ratio === 0).length} of them exact mode at zeta 0`,
    `  exact vs request:          ${exact.length} runs, worst frequency ${fmt(worst(exact.map((p) => p.frequency)))}, ` +
      `worst damping ratio ${worst(exact.map((p) => p.damping)).toFixed(4)}; ${rows.filter((r) => r.inexact).length} null (engine_inexact)`,
    `  nearest legal exact (engine_inexact, predicted within 1 % / 0.02): ${rows.filter((r) => r.nearest).length} runs, ` +
      `measured against their prediction (worst frequency ${fmt(worst(rows.filter((r) => r.nearest && fitted(r.exact)).map((r) => r.exact.frequency)))}, ` +
      `worst damping ratio ${worst(rows.filter((r) => r.nearest && fitted(r.exact)).map((r) => r.exact.damping)).toFixed(4)})`,
    `  over-damped, fast pole < ${kUnobservablePole} per step (slow pole only): ${slowPlain.length} plain runs, worst ` +
      `slow rate ${fmt(worst(slowPlain))}; ${slowExact.length} exact runs, worst slow rate ${fmt(worst(slowExact))}`,
    `  dead-beat (every pole < ${kDeadBeat} per step, held to the spectral radius): ${deadBeat} runs`,
    `  refused exports not run (a known gap the engine's test names): ${rows.filter((r) => r.refusedNotRun).length}`,
    `  predicted unstable, not refused (held to growing): ${rows.filter((r) => !r.refused && r.plain?.grows !== undefined).length} plain runs`,
  ].join('\n');
}
