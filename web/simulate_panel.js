// "Measured in simulation": each probe's requested against measured motion, and the tuned joints of a
// preset with the effective mass, k and c each one got. Units are the same as everywhere on the page:
// frequency errors in percent of the request, damping errors as the absolute difference of damping
// ratios (zeta may be asked 0, where a percentage means nothing). A probe whose run blew up says so
// instead of a frequency fitted to the blow-up.
import { formatDifference } from './engines.js';
import { fmt, formatPercent } from './results.js';

/// The unit of a probe's value, by its kind (scene/include/softtune/scene/scene.h ProbeKind).
export function probeUnit(kind) {
  return kind === 'angle' || kind === 'joint_angle' ? 'rad' : 'm';
}

/// The cells of one probe's row (text), in the table's column order.
export function probeCells(p) {
  const blew = p.diverged === true;
  const measuredHz = blew ? 'blew up' : fmt(p.measured?.frequency_hz);
  const fErr = p.error?.frequency;
  const dErr = p.error?.damping_ratio;
  return [
    `${p.id ?? ''} (${probeUnit(p.kind)})`,
    fmt(p.requested?.frequency_hz),
    measuredHz,
    blew ? '—' : formatPercent(fErr === null || fErr === undefined ? null : 100 * fErr),
    fmt(p.requested?.damping_ratio),
    blew ? 'blew up' : fmt(p.measured?.damping_ratio),
    blew ? '—' : formatDifference(dErr),
    blew ? '—' : fmt(p.measured?.overshoot),
    blew ? '—' : fmt(p.measured?.settle_frames),
  ];
}

function row(cells, attrs = {}) {
  const tr = document.createElement('tr');
  Object.assign(tr.dataset, attrs);
  for (const [i, v] of cells.entries()) {
    const td = document.createElement(i === 0 ? 'th' : 'td');
    if (i === 0) td.scope = 'row';
    td.textContent = v;
    if (v === 'blew up') td.className = 'verdict-unstable';
    tr.append(td);
  }
  return tr;
}

export function showProbes(tbody, probes) {
  tbody.replaceChildren(...probes.map((p) => row(probeCells(p), { probe: p.id ?? '', diverged: p.diverged ? '1' : '' })));
}

/// The tuned joints of a simulate answer: [{id, type, angular, effective_mass, model_mass, k, c}].
export function tunedJoints(doc) {
  return (doc?.joints ?? []).filter((j) => j.tuned).map((j) => ({
    id: j.id, type: j.type, angular: j.angular === true, effective_mass: j.effective_mass, model_mass: j.model_mass ?? j.effective_mass,
    k: j.stiffness, c: j.damping, requested: j.requested,
  }));
}

/// The joint table: one row per tuned joint, the one the numbers describe marked.
export function showJoints(tbody, joints, picked) {
  tbody.replaceChildren(...joints.map((j) => {
    const unit = j.angular ? ['kg m²', 'N m/rad', 'N m s/rad'] : ['kg', 'N/m', 'N s/m'];
    const tr = row([`${j.id} (${j.type})`, `${fmt(j.effective_mass)} ${unit[0]}`, `${fmt(j.k)} ${unit[1]}`, `${fmt(j.c)} ${unit[2]}`],
      { joint: j.id });
    if (j.id === picked) tr.classList.add('picked');
    return tr;
  }));
}

/// The cells of one modal target's row (a simulate answer's modal_tuning.targets[i]): the mode, what was
/// asked, what the linear model predicts at the step, what the Box2D run measured at the target's probe,
/// and the measured error (percent of the asked frequency; the damping ratio's difference).
export function modalTargetCells(t) {
  const pair = (p) => (p ? `${fmt(p.frequency_hz)} Hz, ζ ${fmt(p.damping_ratio)}` : '—');
  const e = t.error;
  const error = e ? `${formatPercent(e.frequency === null || e.frequency === undefined ? null : 100 * e.frequency)}, Δζ ${formatDifference(e.damping_ratio)}` : '—';
  // A target the run cannot measure says why (its probe's window shows no motion of the mode, or no probe).
  const measured = t.measured ? pair(t.measured) : t.unmeasured ? `not measured: ${t.unmeasured}` : '—';
  return [t.mode ?? '', pair(t.requested), pair(t.predicted), measured, error];
}

const MODAL_ROWS = ['asked', 'predicted (linear model)', 'measured (simulation)', 'error (f %, Δζ)'];

/// The modal tuning of a simulate answer in `table`: a column per target (narrow: one target fits the
/// sliders' column), a row per figure of modalTargetCells; `note` names each group's solved k and c.
/// Returns false (nothing shown) for an answer without modal tuning.
export function showModalTargets(table, note, modal) {
  const targets = modal?.targets ?? [];
  const cells = targets.map(modalTargetCells);
  const head = document.createElement('tr');
  head.append(document.createElement('td'));
  for (const c of cells) {
    const th = document.createElement('th');
    th.scope = 'col';
    th.dataset.target = c[0];
    th.textContent = c[0];
    head.append(th);
  }
  table.tHead.replaceChildren(head);
  table.tBodies[0].replaceChildren(...MODAL_ROWS.map((label, i) => row([label, ...cells.map((c) => c[i + 1])])));
  note.textContent = (modal?.groups ?? []).map((g) => `${g.id} (${(g.joints ?? []).join(', ')}): k ${fmt(g.stiffness)}, c ${fmt(g.damping)}`)
    .join('; ');
  return targets.length > 0;
}
