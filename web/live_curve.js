// The response at the slider: a small curve of the asked response, redrawn in the browser on every input
// event (no server round trip), with a dot that moves along it at the preview's time. Once the tune answer
// is in, the same canvas draws the answer's own step data (its step matrix, replayed by oscillator.js), so
// what the designer sees while dragging is what the numbers then confirm.
//
// The input-time curve steps the asked motion x'' = -omega^2 x - 2 zeta omega x' (x0 = 1, v0 = 0) the way
// the chosen soft method does (Catto, "Soft Constraints", GDC 2011):
// - standard: the soft constraint is implicit Euler on the spring, x1 = x0 + h v1 and
//   v1 = v0 + h (-omega^2 x1 - 2 zeta omega v1), so one step is (I - h A)^-1 with A = [[0, 1], [-omega^2, -2 zeta omega]];
// - exact: the same implicit step with k', c' chosen so that its two poles are the continuous motion's
//   poles at the step (docs/math.md, "Exact softness"): trace S and determinant P of e^(h A). An implicit
//   step with determinant P = 1 / D and trace S is [[S - P, h P], [-(1 + P - S) / h, P]].
// e^(h A) is computed numerically (scaling and squaring of its Taylor series), so the page holds no copy of
// the closed-form motion. tests/web/live_curve.test.mjs holds both steps equal to the server's step matrices.
import { replay } from './oscillator.js';

/// Samples drawn at most: the curve is small, and a redraw must fit in a frame (16 ms).
export const LIVE_SAMPLES = 400;
/// The band a response has settled in (of x0 = 1): the words say when it stays inside.
export const SETTLED_BAND = 0.02;

/// The asked response from the controls: omega (rad/s), zeta, h (s), mode, frames per second, or null when a
/// field is empty, not a number or out of range (the page then keeps the last curve). `words` maps an
/// oscillation word to its damping ratio (api.js oscillationWords()).
export function askedResponse(state, words = {}) {
  const basis = Number(state.basis), frames = Number(state.frames), fps = Number(state.fps), substeps = Number(state.substeps);
  const zeta = state.osc ? words[state.osc] : Number(state.zeta);
  const fine = [basis, frames, fps, substeps, zeta].every((v) => typeof v === 'number' && Number.isFinite(v));
  if (!fine || state.basis === '' || state.frames === '' || state.fps === '' || state.substeps === '' || (!state.osc && state.zeta === '') ||
      basis <= 0 || frames <= 0 || fps <= 0 || substeps < 1 || zeta < 0) return null;
  const frequencyHz = basis / frames;
  return { omega: 2 * Math.PI * frequencyHz, zeta, h: 1 / (fps * Math.round(substeps)), mode: state.mode === 'exact' ? 'exact' : 'standard',
    fps, frequencyHz, durationS: 3 / frequencyHz };
}

const mul = (a, b) => [[a[0][0] * b[0][0] + a[0][1] * b[1][0], a[0][0] * b[0][1] + a[0][1] * b[1][1]],
  [a[1][0] * b[0][0] + a[1][1] * b[1][0], a[1][0] * b[0][1] + a[1][1] * b[1][1]]];

/// e^M of a 2x2 matrix: M scaled by 2^-s until its norm is under 1/2, a 16-term Taylor series, squared s times.
export function expm2(m) {
  const norm = Math.max(Math.abs(m[0][0]) + Math.abs(m[0][1]), Math.abs(m[1][0]) + Math.abs(m[1][1]));
  const s = norm > 0.5 ? Math.ceil(Math.log2(norm / 0.5)) : 0;
  const scale = 2 ** -s;
  const a = m.map((row) => row.map((e) => e * scale));
  let term = [[1, 0], [0, 1]];
  let sum = [[1, 0], [0, 1]];
  for (let n = 1; n <= 16; ++n) {
    term = mul(term, a).map((row) => row.map((e) => e / n));
    sum = sum.map((row, i) => row.map((e, j) => e + term[i][j]));
  }
  for (let k = 0; k < s; ++k) sum = mul(sum, sum);
  return sum;
}

/// One step [x1, v1] = M [x0, v0] of the chosen soft method for the asked response (see the top).
export function liveStepMatrix({ omega, zeta, h, mode }) {
  if (mode === 'exact') {
    const e = expm2([[0, h], [-omega * omega * h, -2 * zeta * omega * h]]);
    const S = e[0][0] + e[1][1];
    const P = e[0][0] * e[1][1] - e[0][1] * e[1][0];
    return [[S - P, h * P], [-(1 + P - S) / h, P]];
  }
  const d = 1 + 2 * zeta * omega * h + omega * omega * h * h;
  return [[1 - (h * h * omega * omega) / d, h / d], [-(h * omega * omega) / d, 1 / d]];
}

/// The curve {t, x, h} of the asked response over three periods, at most LIVE_SAMPLES + 1 points (every
/// step is taken; every `stride`-th is drawn).
export function liveCurve(ask) {
  const steps = Math.max(1, Math.ceil(ask.durationS / ask.h - 1e-9));
  const stride = Math.ceil(steps / LIVE_SAMPLES);
  const samples = Math.floor(steps / stride);
  const x = replay(liveStepMatrix(ask), 1, 0, samples, stride);
  return { t: x.map((_, n) => n * stride * ask.h), x };
}

/// The two plain words of a curve: how much it bounces (the deepest swing past rest, in % of the start)
/// and how fast it settles (the last time it is outside SETTLED_BAND, in frames at `fps`; null when it
/// has not settled within the curve, or blew up).
export function feel(curve, fps) {
  let overshoot = 0, last = -1;
  for (let i = 0; i < curve.x.length; ++i) {
    const x = curve.x[i];
    if (x === null) return { bouncePercent: null, settleFrames: null, blewUp: true };
    if (-x > overshoot) overshoot = -x;
    if (Math.abs(x) > SETTLED_BAND) last = i;
  }
  const settled = last < curve.x.length - 1;
  const at = last + 1 < curve.t.length ? curve.t[last + 1] : null;
  return { bouncePercent: 100 * overshoot, settleFrames: settled && at !== null ? Math.round(at * fps) : null, blewUp: false };
}

/// The words a designer reads beside the curve ("bounces 16 %, settles in 14 frames").
export function feelWords(f) {
  if (f.blewUp) return 'blows up at this step';
  const bounce = f.bouncePercent < 0.5 ? 'no bounce' : `bounces ${Math.round(f.bouncePercent)} %`;
  const settle = f.settleFrames === null ? 'still moving after three periods' : `settles in ${f.settleFrames} frames`;
  return `${bounce}, ${settle}`;
}

/// Draws `curve` (and a dashed `ghost`, the pinned A) on `canvas`, with a dot at time `cursorS` (looped
/// over the curve). Sizes the canvas to its CSS box at the device's pixel ratio.
export function drawLive(canvas, curve, { ghost = null, cursorS = null } = {}) {
  const ratio = globalThis.devicePixelRatio || 1;
  const w = Math.max(1, Math.round(canvas.clientWidth * ratio)), hgt = Math.max(1, Math.round(canvas.clientHeight * ratio));
  if (canvas.width !== w || canvas.height !== hgt) {
    canvas.width = w;
    canvas.height = hgt;
  }
  const g = canvas.getContext('2d');
  g.clearRect(0, 0, w, hgt);
  const tEnd = curve.t.at(-1) || 1;
  const pad = 4 * ratio;
  const px = (t) => pad + ((w - 2 * pad) * t) / tEnd;
  const py = (x) => hgt / 2 - ((hgt / 2 - pad) * Math.max(-1.2, Math.min(1.2, x))) / 1.2;
  g.strokeStyle = '#d5dae0';
  g.lineWidth = ratio;
  g.beginPath();
  g.moveTo(pad, py(0));
  g.lineTo(w - pad, py(0));
  g.stroke();
  const line = (c, color, dash) => {
    g.strokeStyle = color;
    g.lineWidth = 2 * ratio;
    g.setLineDash(dash.map((d) => d * ratio));
    g.beginPath();
    let down = false;
    c.t.forEach((t, i) => {
      const x = c.x[i];
      if (x === null || t > tEnd) {
        down = false;
        return;
      }
      if (down) g.lineTo(px(t), py(x));
      else g.moveTo(px(t), py(x));
      down = true;
    });
    g.stroke();
    g.setLineDash([]);
  };
  if (ghost) line(ghost, '#8c959f', [4, 3]);
  line(curve, '#1f6feb', []);
  if (cursorS !== null && curve.t.length > 1) {
    const t = cursorS % tEnd;
    const dt = curve.t[1] - curve.t[0];
    const i = Math.min(curve.t.length - 1, Math.round(t / dt));
    const x = curve.x[i];
    if (x !== null) {
      g.fillStyle = '#d1242f';
      g.beginPath();
      g.arc(px(curve.t[i]), py(x), 4 * ratio, 0, 2 * Math.PI);
      g.fill();
    }
  }
}
