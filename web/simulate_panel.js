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
