// A custom 2-D constraint explained: its effective mass term by term, as the tune answer's
// `effective_mass_check.terms` gives them (each body's 1/m and (r x n)^2 / I, from core's
// inverse_effective_mass_terms), beside a small drawing of the two bodies, their anchors, the levers r
// from each centre to its anchor, and the axis n.
import { fmt } from './results.js';

const SVG = 'http://www.w3.org/2000/svg';

function svg(tag, attrs, text) {
  const node = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, String(v));
  if (text) node.textContent = text;
  return node;
}

const point = (state, x, y) => [Number(state[x]), Number(state[y])];

/// The drawing: y up, fitted to the bodies and anchors with a margin.
export function drawConstraint(el, state) {
  const bodies = ['a', 'b'].map((p) => ({
    p, centre: point(state, `${p}_x`, `${p}_y`), isStatic: state[`${p}_static`] === '1',
    anchor: point(state, `anchor_${p}_x`, `anchor_${p}_y`),
  }));
  const axis = point(state, 'axis_x', 'axis_y');
  const norm = Math.hypot(...axis) || 1;
  const n = [axis[0] / norm, axis[1] / norm];
  const all = bodies.flatMap((b) => [b.centre, b.anchor]).filter(([x, y]) => Number.isFinite(x) && Number.isFinite(y));
  if (all.length < 4) {
    el.replaceChildren();
    return;
  }
  const xs = all.map(([x]) => x), ys = all.map(([, y]) => y);
  const span = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys), 0.5);
  const pad = 0.35 * span;
  const [x0, y0] = [Math.min(...xs) - pad, Math.min(...ys) - pad];
  const w = Math.max(...xs) - Math.min(...xs) + 2 * pad, h = Math.max(...ys) - Math.min(...ys) + 2 * pad;
  const s = (x, y) => [x - x0, y0 + h - y];  // world (y up) to SVG (y down)
  const r = 0.06 * span;
  el.setAttribute('viewBox', `0 0 ${w} ${h}`);
  el.replaceChildren();
  for (const b of bodies) {
    const [cx, cy] = s(...b.centre);
    const [ax, ay] = s(...b.anchor);
    if (b.isStatic) el.append(svg('rect', { x: cx - r, y: cy - r, width: 2 * r, height: 2 * r, class: 'static' }));
    else el.append(svg('circle', { cx, cy, r: 1.6 * r, class: `body body-${b.p}` }));
    el.append(svg('line', { x1: cx, y1: cy, x2: ax, y2: ay, class: 'lever' }));
    el.append(svg('circle', { cx: ax, cy: ay, r: 0.45 * r, class: 'anchor' }));
    el.append(svg('text', { x: cx + 1.9 * r, y: cy - 1.2 * r, 'font-size': 2.2 * r }, b.p.toUpperCase()));
  }
  // The axis through anchor B, as an arrow of a third of the picture.
  const [bx, by] = bodies[1].anchor;
  const len = 0.3 * span;
  const [tx, ty] = s(bx + n[0] * len, by + n[1] * len);
  const [fx, fy] = s(bx - n[0] * len * 0.3, by - n[1] * len * 0.3);
  el.append(svg('line', { x1: fx, y1: fy, x2: tx, y2: ty, class: 'axis', 'marker-end': 'url(#axis-head)' }));
  el.append(svg('text', { x: tx + 0.5 * r, y: ty, 'font-size': 2.2 * r }, 'n'));
  const defs = svg('defs', {});
  const marker = svg('marker', { id: 'axis-head', viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 6, markerHeight: 6, orient: 'auto-start-reverse' });
  marker.append(svg('path', { d: 'M 0 0 L 10 5 L 0 10 z', class: 'axis-head' }));
  defs.append(marker);
  el.prepend(defs);
}

/// The table of the terms of 1 / m_eff; `angular` says the units (1/(kg m^2)).
export function showMassTerms(tbody, tune, angular) {
  const terms = tune.effective_mass_check?.terms;
  if (!terms) {
    tbody.replaceChildren();
    return false;
  }
  const unit = angular ? '1/(kg m²)' : '1/kg';
  const rows = [
    ['body A, translational: 1 / m_A', terms.body_a.translational],
    [angular ? 'body A, rotational: 1 / I_A' : 'body A, rotational: (r_A × n)² / I_A', terms.body_a.rotational],
    ['body B, translational: 1 / m_B', terms.body_b.translational],
    [angular ? 'body B, rotational: 1 / I_B' : 'body B, rotational: (r_B × n)² / I_B', terms.body_b.rotational],
    ['K = J M⁻¹ Jᵀ, the sum', tune.effective_mass_check.jacobian],
  ];
  tbody.replaceChildren(...rows.map(([what, v]) => {
    const tr = document.createElement('tr');
    const th = document.createElement('th');
    th.scope = 'row';
    th.textContent = what;
    const td = document.createElement('td');
    td.textContent = `${fmt(v)} ${unit}`;
    td.dataset.value = String(v);
    tr.append(th, td);
    return tr;
  }));
  const tr = document.createElement('tr');
  tr.innerHTML = '<th scope="row">effective mass 1 / K</th><td></td>';
  tr.lastChild.textContent = `${fmt(tune.effective_mass)} ${angular ? 'kg m²' : 'kg'}`;
  tbody.append(tr);
  return true;
}
