// The summary bar's verdict in a designer's words, and its pending state. The verdict compares what the
// step (or, for a preset tuned by its modes, the simulation) does against the ask: "on target" within 3 %
// of the frequency and 0.03 of the damping ratio, else "off by N %" (and the damping's difference), in
// amber. While a preset tuned by its modes waits for its scene's solve, the bar keeps the last solved
// values marked pending: a tune answer (one spring on its own mass) never flashes its k and c there first.

/// How far a result may be from the ask and still read "on target": 3 % of the frequency, 0.03 of zeta.
export const FREQUENCY_BAR = 0.03;
export const DAMPING_BAR = 0.03;

const SPANS = ['summary-frequency', 'summary-damping', 'summary-k', 'summary-c', 'summary-off'];

/// {text, off} for a result `got` against `requested` ({frequency_hz, damping_ratio} each); null when
/// either lacks a frequency.
export function offBy(requested, got) {
  const f0 = requested?.frequency_hz, f = got?.frequency_hz;
  if (typeof f0 !== 'number' || typeof f !== 'number' || !(f0 > 0)) return null;
  const rel = (f - f0) / f0;
  const z0 = requested.damping_ratio, z = got.damping_ratio;
  const dz = typeof z0 === 'number' && typeof z === 'number' ? z - z0 : 0;
  const parts = [];
  if (Math.abs(rel) > FREQUENCY_BAR) {
    const p = 100 * Math.abs(rel);
    parts.push(`off by ${p < 10 ? p.toFixed(1) : Math.round(p)} % (${rel > 0 ? 'faster' : 'slower'})`);
  }
  if (Math.abs(dz) > DAMPING_BAR) parts.push(`${parts.length ? 'bounce' : 'bounce off by'} ${dz > 0 ? '+' : '−'}${Math.abs(dz).toFixed(2)} (${dz > 0 ? 'less' : 'more'} bounce)`);
  return parts.length ? { text: parts.join(', '), off: true } : { text: 'on target', off: false };
}

/// Writes the verdict of `got` against `requested` into the bar.
export function showOffBy(root, requested, got) {
  const el = root.querySelector('[data-testid="summary-off"]');
  const v = offBy(requested, got);
  el.textContent = v?.text ?? '';
  el.classList.toggle('is-off', Boolean(v?.off));
  el.title = v ? `within ${100 * FREQUENCY_BAR} % of the frequency and ${DAMPING_BAR} of the damping ratio reads "on target"` : '';
}

/// The bar's values as they are (before a tune answer rewrites them).
export function holdSummary(root) {
  return Object.fromEntries(SPANS.map((id) => {
    const el = root.querySelector(`[data-testid="${id}"]`);
    return [id, { text: el.textContent, className: el.className }];
  }));
}

/// Puts `held` values back, marked pending until the scene's answer replaces them (an empty value shows
/// the mark alone).
export function markPending(root, held) {
  for (const id of SPANS) {
    const el = root.querySelector(`[data-testid="${id}"]`);
    el.textContent = held[id].text;
    el.className = held[id].className;
    el.classList.add('pending');
  }
  root.dataset.pending = 'scene';
}

/// The scene's answer is in: no mark.
export function clearPending(root) {
  for (const id of SPANS) root.querySelector(`[data-testid="${id}"]`).classList.remove('pending');
  delete root.dataset.pending;
}
