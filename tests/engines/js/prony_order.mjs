// Prony's method of any order, for engines whose motion is not second order (matter.js carries each pass's
// constraint impulse into the next: a third state, five on a turning body). A linear system of order N
// sampled every h seconds obeys exactly x[n] = a1 x[n-1] + ... + aN x[n-N] + b; the least-squares fit of
// (a1..aN, b) over the window (prony.mjs's fitWindow rule) gives the discrete poles, the roots of
// z^N - a1 z^(N-1) - ... - aN (Durand-Kerner), and the motion shown is read off the dominant pair as the
// engine's model reads them: the complex pair of largest modulus, unless a real pole grows (kGrowingPole) or there is no
// pair: then the two largest real poles (the one twice when it is alone); s = ln(z)/h
// through prony.mjs's fromPoles. The least squares runs through modified Gram-Schmidt QR on the centred,
// scaled columns.
import { fitWindow, fromPoles, kFitFloor } from './prony.mjs';

const kMinSamples = 8;
/** A real pole above this per step is the motion shown (matter_js.cpp kGrowingPole). */
export const kGrowingPole = 1.01;

// min |A p - y| for the columns `cols` of A, by modified Gram-Schmidt; null when A is rank deficient.
function leastSquares(cols, y) {
  const m = cols.length;
  const q = cols.map((c) => c.slice());
  const r = Array.from({ length: m }, () => new Array(m).fill(0));
  for (let j = 0; j < m; ++j) {
    for (let i = 0; i < j; ++i) {
      let d = 0;
      for (let k = 0; k < y.length; ++k) d += q[i][k] * q[j][k];
      r[i][j] = d;
      for (let k = 0; k < y.length; ++k) q[j][k] -= d * q[i][k];
    }
    let norm = 0;
    for (let k = 0; k < y.length; ++k) norm += q[j][k] * q[j][k];
    r[j][j] = Math.sqrt(norm);
    if (r[j][j] > 0) for (let k = 0; k < y.length; ++k) q[j][k] /= r[j][j];
  }
  const diagonal = r.map((row, i) => Math.abs(row[i]));
  if (!(Math.max(...diagonal) > 0) || Math.min(...diagonal) <= 1e-12 * Math.max(...diagonal)) return null;
  const p = new Array(m).fill(0);
  for (let i = m - 1; i >= 0; --i) {
    let s = 0;
    for (let k = 0; k < y.length; ++k) s += q[i][k] * y[k];
    for (let j = i + 1; j < m; ++j) s -= r[i][j] * p[j];
    p[i] = s / r[i][i];
  }
  return p;
}

// The roots of z^N - a[0] z^(N-1) - ... - a[N-1] (Durand-Kerner), as [re, im] pairs.
function roots(a) {
  const n = a.length;
  const coeff = [1, ...a.map((v) => -v)];  // highest power first
  const evaluate = (re, im) => {
    let pr = 0, pi = 0;
    for (const c of coeff) [pr, pi] = [pr * re - pi * im + c, pr * im + pi * re];
    return [pr, pi];
  };
  let z = Array.from({ length: n }, (_, k) => {
    const angle = (2 * Math.PI * k) / n + 0.4;
    return [0.9 * Math.cos(angle), 0.9 * Math.sin(angle)];
  });
  for (let iteration = 0; iteration < 500; ++iteration) {
    let moved = 0;
    z = z.map(([re, im], i) => {
      const [pr, pi] = evaluate(re, im);
      let dr = 1, di = 0;
      for (let j = 0; j < n; ++j) {
        if (j === i) continue;
        const [ur, ui] = [re - z[j][0], im - z[j][1]];
        [dr, di] = [dr * ur - di * ui, dr * ui + di * ur];
      }
      const den = dr * dr + di * di;
      const [qr, qi] = [(pr * dr + pi * di) / den, (pi * dr - pr * di) / den];
      moved = Math.max(moved, Math.hypot(qr, qi));
      return [re - qr, im - qi];
    });
    if (moved < 1e-15) break;
  }
  return z;
}

/**
 * Fits samples spaced h apart with a recurrence of `order`: {frequencyHz, dampingRatio, poles, residual,
 * samplesUsed} or null.
 */
export function fitResponseOrder(x, h, order, floor = kFitFloor) {
  if (x.length < kMinSamples || !(h > 0) || !x.every(Number.isFinite)) return null;
  const n = fitWindow(x, floor);
  if (n < Math.max(kMinSamples, 2 * order + 3)) return null;  // order + 3 equations at least
  let mean = 0;
  for (let i = 0; i < n; ++i) mean += x[i];
  mean /= n;
  let scale = 0;
  for (let i = 0; i < n; ++i) scale = Math.max(scale, Math.abs(x[i] - mean));
  if (!(scale > 0)) return null;
  const cols = Array.from({ length: order + 1 }, () => []);
  const y = [];
  for (let i = order; i < n; ++i) {
    for (let j = 0; j < order; ++j) cols[j].push((x[i - 1 - j] - mean) / scale);
    cols[order].push(1);
    y.push((x[i] - mean) / scale);
  }
  const p = leastSquares(cols, y);
  if (!p) return null;
  let res = 0, norm = 0;
  for (let i = 0; i < y.length; ++i) {
    let e = -y[i];
    for (let j = 0; j <= order; ++j) e += p[j] * cols[j][i];
    res += e * e;
    norm += y[i] * y[i];
  }
  const z = roots(p.slice(0, order)).sort((u, v) => Math.hypot(...v) - Math.hypot(...u));
  const isReal = ([re, im]) => Math.abs(im) <= 1e-9 * Math.hypot(re, im);
  let z1 = z[0], z2 = [z[0][0], -z[0][1]];
  const pair = z.find((p) => !isReal(p));
  if (isReal(z1) && (Math.hypot(...z1) > kGrowingPole || !pair)) {
    z1 = [z1[0], 0];
    const next = z.slice(1).find(isReal);
    z2 = next ? [next[0], 0] : z1;
  } else if (isReal(z1)) {
    z1 = pair;
    z2 = [pair[0], -pair[1]];
  }
  // The pair as z^2 - a1 z - a2: a1 = z1 + z2, a2 = -z1 z2 (real for a conjugate or a real pair).
  const a1 = z1[0] + z2[0], a2 = -(z1[0] * z2[0] - z1[1] * z2[1]);
  const poles = fromPoles(a1, a2, h);
  if (!poles) return null;
  return { ...poles, poles: z, residual: Math.sqrt(res / Math.max(norm, 1e-300)), samplesUsed: n };
}

/**
 * The fit of the order, 2 .. maxOrder, that leaves the smallest residual: a higher order than the motion
 * needs leaves its extra coefficients undetermined (the least squares loses them to round-off, its residual
 * grows and a root of 1e4 appears in a decaying trajectory), a lower one misses a mode.
 */
export function fitBestOrder(x, h, maxOrder, floor = kFitFloor) {
  let best = null;
  for (let order = 2; order <= maxOrder; ++order) {
    const fit = fitResponseOrder(x, h, order, floor);
    if (fit && (!best || fit.residual < best.residual)) best = fit;
  }
  return best;
}
