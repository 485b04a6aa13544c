// The response and error plots, computed in the browser from a tune response.
//
// This is real data, not an illustration: every method's trajectory is the server's own step map.
// Each integrator in core/ is linear in the state (x, v), so one step is exactly
// [x1, v1] = A [x0, v0], and the tune response carries A as `stability[method].step_matrix` (built by the
// server stepping the unit states through that very integrator, at h = 1 / (fps * substeps)). Iterating A
// from x0 = 1, v0 = 0 therefore replays explicit Euler, semi-implicit Euler, implicit Euler, the soft
// constraint and the exact soft constraint step by step. The exact motion is the closed-form solution of
// m x'' + c x' + k x = 0 at the requested omega and zeta (core/src/analytic.cpp, same cases).

export const METHODS = ['explicit_euler', 'semi_implicit_euler', 'implicit_euler', 'soft', 'soft_exact'];

export const METHOD_LABELS = {
  explicit_euler: 'Explicit Euler',
  semi_implicit_euler: 'Semi-implicit Euler',
  implicit_euler: 'Implicit Euler',
  soft: 'Soft constraint',
  soft_exact: 'Soft constraint (exact)',
};

/// Past this |x| (x0 = 1) a trajectory has blown up; later samples are left out of the plots (null).
export const BLOWUP_LIMIT = 1e6;
/// Samples kept per curve: a long run at a small step is replayed in full but drawn every `stride` steps.
export const MAX_SAMPLES = 4000;
/// Steps replayed at most (a few tens of ms in a browser), so no step size can freeze the page.
export const MAX_STEPS = 2e7;

/// Position x(t) of m x'' + c x' + k x = 0 from x(0) = x0, x'(0) = v0, for natural angular frequency
/// omega (rad/s) and damping ratio zeta (SPEC.md 1; under-damped: decaying cosine/sine at
/// omega_d = omega sqrt(1 - zeta^2); critical: (x0 + (v0 + omega x0) t) e^(-omega t); over-damped: two
/// real roots, the slow one written as -omega / (zeta + sqrt(zeta^2 - 1)) to avoid cancellation).
export function analyticPosition(x0, v0, omega, zeta, t) {
  if (omega === 0) return x0 + v0 * t;
  if (zeta < 1) {
    const wd = omega * Math.sqrt(1 - zeta * zeta);
    const b = (v0 + zeta * omega * x0) / wd;
    return Math.exp(-zeta * omega * t) * (x0 * Math.cos(wd * t) + b * Math.sin(wd * t));
  }
  if (zeta === 1) return Math.exp(-omega * t) * (x0 + (v0 + omega * x0) * t);
  const root = Math.sqrt(zeta * zeta - 1);
  const r1 = -omega / (zeta + root);
  const r2 = -omega * (zeta + root);
  const a = (v0 - r2 * x0) / (r1 - r2);
  return a * Math.exp(r1 * t) + (x0 - a) * Math.exp(r2 * t);
}

/// x_(n stride) for n = 0..samples of the linear map [x, v] <- A [x, v] from (x0, v0), every step taken;
/// null once |x| passes BLOWUP_LIMIT or stops being finite (and for every later sample).
export function replay(matrix, x0, v0, samples, stride = 1) {
  const [[a, b], [c, d]] = matrix;
  const out = new Array(samples + 1);
  let x = x0, v = v0, blown = false;
  for (let n = 0; n <= samples; ++n) {
    if (!blown && !(Math.abs(x) <= BLOWUP_LIMIT)) blown = true;
    out[n] = blown ? null : x;
    if (blown) continue;
    for (let k = 0; k < stride; ++k) {
      const x1 = a * x + b * v;
      v = c * x + d * v;
      x = x1;
    }
  }
  return out;
}

function usableMatrix(m) {
  return Array.isArray(m) && m.length === 2 && m.every((row) => Array.isArray(row) && row.length === 2 &&
    row.every((e) => typeof e === 'number' && Number.isFinite(e)));
}

/// Seconds to show: three periods of the requested natural frequency, or 1 s without a spring.
export function plotDuration(frequencyHz) {
  return frequencyHz > 0 ? 3 / frequencyHz : 1;
}

/// Points of the smooth exact curve: a method takes few steps per period, the true motion is drawn finely.
export const EXACT_POINTS = 600;

/// Plot data from a tune response: {t, exact, methods: {name: x[]}, error: {name: |x - exact|[]},
/// smooth: {t, x} (the exact motion on a fine grid), stride, truncated}. Methods whose step matrix is
/// missing (or not finite) are left out.
export function responseSeries(tune) {
  const h = tune.h;
  const omega = tune.omega ?? 0;
  const zeta = tune.damping_ratio ?? 0;
  const wanted = Math.ceil(plotDuration(tune.requested?.frequency_hz ?? tune.frequency_hz ?? 0) / h);
  const steps = Math.max(1, Math.min(MAX_STEPS, wanted));
  const stride = Math.ceil(steps / MAX_SAMPLES);
  const samples = Math.floor(steps / stride);
  const t = Array.from({ length: samples + 1 }, (_, n) => n * stride * h);
  const exact = t.map((ti) => analyticPosition(1, 0, omega, zeta, ti));
  const methods = {}, error = {};
  for (const name of METHODS) {
    const matrix = tune.stability?.[name]?.step_matrix;
    if (!usableMatrix(matrix)) continue;
    const xs = replay(matrix, 1, 0, samples, stride);
    methods[name] = xs;
    // Log-scale plot: an exact zero (t = 0) has no place on it, so it is left out.
    error[name] = xs.map((x, n) => {
      if (x === null) return null;
      const e = Math.abs(x - exact[n]);
      return e > 0 ? e : null;
    });
  }
  const end = t[t.length - 1];
  const fine = t.length >= EXACT_POINTS ? t : Array.from({ length: EXACT_POINTS + 1 }, (_, i) => (end * i) / EXACT_POINTS);
  const smooth = { t: fine, x: fine.map((ti) => analyticPosition(1, 0, omega, zeta, ti)) };
  return { t, exact, methods, error, smooth, stride, truncated: wanted > MAX_STEPS };
}
