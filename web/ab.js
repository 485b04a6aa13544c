// A/B: "Pin as A" keeps the current tuning's answer and preview; from then on every change is B, shown
// against A: each number with A's beside it, A's chosen method overlaid (grey, dashed) on the response
// plot, and A's preview frames playing beside B's, frame for frame at the same scene time.
import { fmt } from './results.js';

const NUMBERS = { 'effective-mass': 'effective_mass', k: 'k', c: 'c', gamma: 'gamma', beta: 'beta', erp: 'erp', cfm: 'cfm',
  'gamma-impulse': 'gamma_impulse' };

export class Comparison {
  pinned = null;  // {tune, series: {t, x, label}, frames, dt, what}

  constructor(root, previewImg, pinnedImg) {
    this.root = root;
    this.preview = previewImg;
    this.img = pinnedImg;
    // A's frame follows B's: the same scene time, looping over A's own frames.
    new MutationObserver(() => this.#follow()).observe(previewImg, { attributes: true, attributeFilter: ['data-frame'] });
  }

  /// Pins `tune` (with its plot series for the chosen method) and the preview shown now.
  pin(tune, series, chosen, preview, what) {
    this.pinned = {
      tune, what, series: series.methods[chosen] ? { t: series.t, x: series.methods[chosen], label: what } : null,
      frames: preview.frames, dt: preview.dt,
    };
    this.root.dataset.ab = 'on';
    this.img.hidden = !preview.frames?.length;
    this.#follow();
  }

  unpin() {
    this.pinned = null;
    delete this.root.dataset.ab;
    this.img.hidden = true;
    this.img.removeAttribute('src');
    for (const el of this.root.querySelectorAll('.ab-a')) el.remove();
  }

  /// A's numbers beside B's (after showNumbers drew B's).
  showNumbers() {
    for (const el of this.root.querySelectorAll('.ab-a')) el.remove();
    if (!this.pinned) return;
    for (const [testid, key] of Object.entries(NUMBERS)) {
      const dd = this.root.querySelector(`.numbers [data-testid="${testid}"]`);
      if (!dd) continue;
      const a = document.createElement('dd');
      a.className = 'ab-a';
      a.dataset.testid = `a-${testid}`;
      a.dataset.value = String(this.pinned.tune[key] ?? '');
      a.textContent = `A: ${fmt(this.pinned.tune[key])}`;
      dd.after(a);
    }
    const req = this.pinned.tune.requested ?? {}, got = this.pinned.tune.achieved ?? {};
    const row = document.createElement('p');
    row.className = 'ab-a note';
    row.dataset.testid = 'a-summary';
    row.textContent = `A (${this.pinned.what}): ${fmt(req.frequency_hz)} → ${fmt(got.frequency_hz)} Hz, ζ ${fmt(req.damping_ratio)} → ${fmt(got.damping_ratio)}, k ${fmt(this.pinned.tune.k)}, c ${fmt(this.pinned.tune.c)}`;
    this.root.querySelector('.numbers').after(row);
  }

  #follow() {
    const p = this.pinned;
    if (!p?.frames?.length) return;
    const i = Number(this.preview.dataset.frame ?? 0);
    const dtB = Number(this.preview.dataset.frameSeconds) || p.dt;
    const j = Math.round((i * dtB) / (p.dt || dtB)) % p.frames.length;
    const url = p.frames[j];
    if (this.img.getAttribute('src') !== url) this.img.src = url;
    this.img.dataset.frame = String(j);
  }
}
