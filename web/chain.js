// The mass-ratio chain's design answer on the page (docs/accuracy-and-stability.md, "The design answer"):
// a mass-ratio field adds `chain` to the tune request, and the answer's `chain.solvers` becomes one row
// per solver: its count and warm start as the request runs it, the bisected highest stable frequency, and
// the fewest iterations or substeps that stay stable with margin at the asked frequency.
import { fmt } from './results.js';

export const MAX_MASS_RATIO = 1e9;  // the tune contract's chain.mass_ratio bound

/// The request's `chain` field for the text in the mass-ratio box: undefined when empty; an Error when
/// it is not a number in [1, 1e9].
export function chainField(text) {
  const t = String(text ?? '').trim();
  if (t === '') return undefined;
  const ratio = Number(t);
  if (!Number.isFinite(ratio) || ratio < 1 || ratio > MAX_MASS_RATIO) {
    return new Error('mass ratio must be a number from 1 to 1e9');
  }
  return { mass_ratio: ratio };
}

/// One row of cells per solver of a tune answer's `chain` (none when the answer has no chain).
export function chainRows(tune) {
  const chain = tune?.chain;
  if (!chain?.solvers) return [];
  return Object.entries(chain.solvers).map(([solver, s]) => {
    const limit = s.limit === 'none_in_range' ? `none up to ${fmt(s.highest_stable_frequency_hz)}`
      : s.limit === 'unstable_at_lowest' ? 'unstable at every frequency searched' : fmt(s.highest_stable_frequency_hz);
    const verdict = s.meets_margin ? 'stable with margin' : s.stable_at_target ? 'stable, margin short' : 'blows up';
    const fewest = s.fewest_count === null ? `more than ${chain.max_count_searched}` : String(s.fewest_count);
    return [solver, `${s.count_name} = ${s.count}${s.warm_start ? ', warm start' : ''}`, limit, verdict, fewest];
  });
}

/// Fills #chain's table from the answer and shows the section only when the request asked for a chain.
export function showChain(root, tune) {
  const section = root.querySelector('#chain-section');
  if (!section) return;
  const rows = chainRows(tune);
  section.hidden = rows.length === 0;
  const body = section.querySelector('tbody');
  body.replaceChildren(...rows.map((cells) => {
    const tr = document.createElement('tr');
    for (const text of cells) {
      const td = document.createElement('td');
      td.textContent = text;
      tr.append(td);
    }
    return tr;
  }));
  const caption = section.querySelector('#chain-note');
  if (caption && tune?.chain) {
    caption.textContent = `Mass ratio ${fmt(tune.chain.mass_ratio)} at ${fmt(tune.chain.frequency_hz)} Hz; margin x${fmt(tune.chain.margin)}.`;
  }
}
