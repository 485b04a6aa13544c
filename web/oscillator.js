// The response and error plots, computed in the browser from a tune response.
//
// This is real data, not an illustration: every method's trajectory is the server's own step map.
// Each integrator in core/ is linear in the state (x, v), so one step is exactly
// [x1, v1] = A [x0, v0], and the tune response carries A as `stability[method].step_matrix` (built by the
// server stepping the unit states through that very integrator, at h = 1 / (fps * substeps)). Iterating A
// from x0 = 1, v0 = 0 therefore replays explicit Euler, semi-implicit Euler, implicit Euler, the soft
// constraint and the exact soft constraint step by step. The exact motion comes from the answer too
// (`exact_motion`, core/src/analytic.cpp): its one-step flow, replayed the same way, gives the closed form
// on the step grid, and its fine samples draw the smooth curve; the page keeps no copy of the formula.

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

/// Plot data from a tune response: {t, exact, methods: {name: x[]}, error: {name: |x - exact|[]},
/// smooth: {t, x} (the exact motion on a fine grid), stride, truncated}, over the answer's
/// `exact_motion.duration_s` (three periods of the requested frequency). Methods whose step matrix is
/// missing (or not finite) are left out; without a usable `exact_motion` there is no exact curve or error.
export function responseSeries(tune) {
  const h = tune.h;
  const motion = tune.exact_motion ?? {};
  // Steps to cover the duration; 1e-9 keeps a whole number of steps (0.1 s at 60 fps) from rounding up.
  const wanted = Math.ceil((motion.duration_s ?? 1) / h - 1e-9);
  const steps = Math.max(1, Math.min(MAX_STEPS, wanted));
  const stride = Math.ceil(steps / MAX_SAMPLES);
  const samples = Math.floor(steps / stride);
  const t = Array.from({ length: samples + 1 }, (_, n) => n * stride * h);
  const exact = usableMatrix(motion.step_matrix) ? replay(motion.step_matrix, 1, 0, samples, stride) : null;
  const methods = {}, error = {};
  for (const name of METHODS) {
    const matrix = tune.stability?.[name]?.step_matrix;
    if (!usableMatrix(matrix)) continue;
    const xs = replay(matrix, 1, 0, samples, stride);
    methods[name] = xs;
    if (!exact) continue;
    // Log-scale plot: an exact zero (t = 0) has no place on it, so it is left out.
    error[name] = xs.map((x, n) => {
      if (x === null) return null;
      const e = Math.abs(x - exact[n]);
      return e > 0 ? e : null;
    });
  }
  const fine = motion.smooth;
  let smooth = { t: [], x: [] };
  if (exact && Array.isArray(fine?.x) && fine.x.length > t.length) {
    smooth = { t: fine.x.map((_, i) => i * fine.dt_s), x: fine.x };
  } else if (exact) {
    smooth = { t, x: exact };
  }
  return { t, exact: exact ?? [], methods, error, smooth, stride, truncated: wanted > MAX_STEPS };
}
