// Natural frequency and damping ratio fitted to a sampled trajectory: the JavaScript twin of softtune's
// fit_response (core/src/response_fit.cpp), for the engines that run under node (Jolt, Rapier).
//
// Prony's method of order 2 with a constant term: a linear second-order system sampled every h seconds obeys
// exactly x[n] = a1 x[n-1] + a2 x[n-2] + b; a least-squares fit of (a1, a2, b) over the window gives the
// discrete poles z (roots of z^2 - a1 z - a2), and s = ln(z) / h gives omega = |s|, zeta = -Re(s) / |s|
// (softtune's achieved_from_poles). The window stops where the motion has decayed below kFitFloor of its
// largest distance from the final value (as fit_response does), so round-off in the tail does not enter.
// The least squares runs through modified Gram-Schmidt QR on the three centred, scaled columns.

export const kFitFloor = 1e-3;
const kMinSamples = 8;

export function fitWindow(x, floor) {
  const last = x[x.length - 1];
  let largest = 0;
  for (const v of x) largest = Math.max(largest, Math.abs(v - last));
  let end = 0;
  for (let n = 0; n < x.length; ++n) if (Math.abs(x[n] - last) > floor * largest) end = n;
  return Math.min(x.length, end + 3);
}

// Least squares min |A p - y| for A with three columns (arrays), by modified Gram-Schmidt.
function leastSquares3(cols, y) {
  const q = cols.map((c) => c.slice());
  const r = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
  for (let j = 0; j < 3; ++j) {
    for (let i = 0; i < j; ++i) {
      let d = 0;
      for (let k = 0; k < y.length; ++k) d += q[i][k] * q[j][k];
      r[i][j] = d;
      for (let k = 0; k < y.length; ++k) q[j][k] -= d * q[i][k];
    }
    let norm = 0;
    for (let k = 0; k < y.length; ++k) norm += q[j][k] * q[j][k];
    norm = Math.sqrt(norm);
    r[j][j] = norm;
    if (norm > 0) for (let k = 0; k < y.length; ++k) q[j][k] /= norm;
  }
  const largest = Math.max(...[0, 1, 2].map((i) => Math.abs(r[i][i])));
  if (!(largest > 0) || Math.min(...[0, 1, 2].map((i) => Math.abs(r[i][i]))) <= 1e-10 * largest) return null;
  const qty = [0, 1, 2].map((i) => {
    let d = 0;
    for (let k = 0; k < y.length; ++k) d += q[i][k] * y[k];
    return d;
  });
  const p = [0, 0, 0];
  for (let i = 2; i >= 0; --i) {
    let s = qty[i];
    for (let j = i + 1; j < 3; ++j) s -= r[i][j] * p[j];
    p[i] = s / r[i][i];
  }
  return p;
}

/** softtune's achieved_from_poles for the roots of z^2 - a1 z - a2: {frequencyHz, dampingRatio} or null. */
export function fromPoles(a1, a2, h) {
  const disc = a1 * a1 + 4 * a2;
  let sRe, sIm;
  if (disc < 0) {
    const re = a1 / 2, im = Math.sqrt(-disc) / 2;
    sRe = Math.log(Math.hypot(re, im)) / h;
    sIm = Math.atan2(im, re) / h;
  } else {
    const z1 = a1 / 2 + Math.sqrt(disc) / 2, z2 = a1 / 2 - Math.sqrt(disc) / 2;
    if (z1 > 0 && z2 > 0) {
      const s1 = Math.log(z1) / h, s2 = Math.log(z2) / h;
      if (!(s1 * s2 > 0)) return null;
      const omega = Math.sqrt(s1 * s2);
      return { frequencyHz: omega / (2 * Math.PI), dampingRatio: -(s1 + s2) / (2 * omega) };
    }
    const r = Math.sqrt(Math.abs(z1 * z2));
    if (!(r > 0)) return null;
    sRe = Math.log(r) / h;
    sIm = Math.PI / h;
  }
  const omega = Math.hypot(sRe, sIm);
  if (!(omega > 0) || !Number.isFinite(omega)) return null;
  return { frequencyHz: omega / (2 * Math.PI), dampingRatio: sRe === 0 ? 0 : -sRe / omega };
}

/**
 * Fits samples spaced h apart: {frequencyHz, dampingRatio, residual, samplesUsed} or null. `floor` (default
 * kFitFloor, as fit_response) is where the window stops; single-precision engines released from a few cm
 * carry noise near 1e-6 of the motion, so the conformance tests pass 1e-4 to keep fast decays fittable.
 */
export function fitResponse(x, h, floor = kFitFloor) {
  if (x.length < kMinSamples || !(h > 0) || !x.every(Number.isFinite)) return null;
  const n = fitWindow(x, floor);
  if (n < kMinSamples) return null;
  let mean = 0;
  for (let i = 0; i < n; ++i) mean += x[i];
  mean /= n;
  let scale = 0;
  for (let i = 0; i < n; ++i) scale = Math.max(scale, Math.abs(x[i] - mean));
  if (!(scale > 0)) return null;
  const rows = n - 2;
  const c0 = [], c1 = [], c2 = [], y = [];
  for (let i = 0; i < rows; ++i) {
    c0.push((x[i + 1] - mean) / scale);
    c1.push((x[i] - mean) / scale);
    c2.push(1);
    y.push((x[i + 2] - mean) / scale);
  }
  const p = leastSquares3([c0, c1, c2], y);
  if (!p) return null;
  let res = 0, norm = 0;
  for (let i = 0; i < rows; ++i) {
    const e = p[0] * c0[i] + p[1] * c1[i] + p[2] - y[i];
    res += e * e;
    norm += y[i] * y[i];
  }
  const poles = fromPoles(p[0], p[1], h);
  if (!poles) return null;
  return { ...poles, residual: Math.sqrt(res / Math.max(norm, 1e-300)), samplesUsed: n };
}

/**
 * The slow pole of an over-damped motion whose fast pole has died within the first samples: a first-order
 * fit x[n] = a x[n-1] + b over samples `skip`.. the window's end gives z = a; its rate is -ln(a) / h (1/s).
 * Returns {rate, samplesUsed} or null.
 */
export function fitSlowPole(x, h, skip = 2, floor = kFitFloor) {
  const n = fitWindow(x, floor);
  if (n - skip < 4) return null;
  // Least squares on (x[i-1], 1) -> x[i], i = skip + 1 .. n - 1, centred.
  let sx = 0, sy = 0, sxx = 0, sxy = 0, count = 0;
  for (let i = skip + 1; i < n; ++i) {
    sx += x[i - 1]; sy += x[i]; sxx += x[i - 1] * x[i - 1]; sxy += x[i - 1] * x[i]; ++count;
  }
  const mx = sx / count, my = sy / count;
  const vxx = sxx / count - mx * mx, vxy = sxy / count - mx * my;
  if (!(vxx > 0)) return null;
  const a = vxy / vxx;
  if (!(a > 0 && a < 1)) return null;
  return { rate: -Math.log(a) / h, samplesUsed: count };
}
