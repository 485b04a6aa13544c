// The three charts, drawn with uPlot (loaded as the global `uPlot` from web/vendor/, copied there from
// the npm package by the build): response against the exact motion, error over time, work-precision.
import { METHODS, METHOD_LABELS } from './oscillator.js';

export const COLORS = {
  exact: '#111111',
  explicit_euler: '#d1242f',
  semi_implicit_euler: '#bf8700',
  implicit_euler: '#8250df',
  soft: '#1f6feb',
  soft_exact: '#1a7f37',
};

const charts = new Map();

function width(el) {
  return Math.max(260, Math.floor(el.clientWidth || el.parentElement.clientWidth || 600));
}

function height(el) {
  return el.clientWidth < 500 ? 200 : 260;
}

/// Replaces the chart in `el` (series sets change with the data, so a chart is rebuilt, not patched).
function draw(el, opts, data) {
  charts.get(el)?.destroy();
  el.replaceChildren();
  el.classList.remove('unavailable');
  // A drag on a chart moves the page's time cursor (time_cursor.js), so it does not zoom.
  const chart = new uPlot({ width: width(el), height: height(el), cursor: { drag: { x: false, y: false } }, ...opts }, data, el);
  charts.set(el, chart);
  el.dataset.points = String(data[0].length);
  tableBehind(el, opts.series.map((s) => s.label), data);
}

/// The chart drawn in `el` now (undefined before the first answer), for the time cursor.
export function chartOf(el) {
  return charts.get(el);
}

/// Rows a plot's data table shows at most (every n-th sample beyond that).
export const TABLE_ROWS = 200;

/// The plot's numbers as a table (accessibility: what the chart shows, for a screen reader or a copy),
/// behind a "Data table" disclosure after the chart; built when opened, so redraws stay cheap.
function tableBehind(el, labels, data) {
  let details = el.parentElement.querySelector(`details[data-for="${el.id}"]`);
  if (!details) {
    details = document.createElement('details');
    details.dataset.for = el.id;
    details.className = 'data-table';
    details.addEventListener('toggle', () => fillTable(details));
    el.after(details);
  }
  details.hidden = false;
  details.plot = { labels, data };
  fillTable(details);
}

function fillTable(details) {
  const summary = document.createElement('summary');
  summary.textContent = 'Data table';
  if (!details.open || !details.plot) {
    details.replaceChildren(summary);
    return;
  }
  const { labels, data } = details.plot;
  const n = data[0].length;
  const step = Math.max(1, Math.ceil(n / TABLE_ROWS));
  const table = document.createElement('table');
  const head = table.createTHead().insertRow();
  for (const label of labels) {
    const th = document.createElement('th');
    th.scope = 'col';
    th.textContent = label;
    head.append(th);
  }
  const body = table.createTBody();
  for (let i = 0; i < n; i += step) {
    const tr = body.insertRow();
    data.forEach((column, j) => {
      const cell = document.createElement(j === 0 ? 'th' : 'td');
      if (j === 0) cell.scope = 'row';
      const v = column[i];
      cell.textContent = v === null || v === undefined ? '' : Number(v.toPrecision(6)).toString();
      tr.append(cell);
    });
  }
  const note = document.createElement('p');
  note.className = 'note';
  note.textContent = step > 1 ? `Every ${step}th of ${n} points.` : `${n} points.`;
  const wrap = document.createElement('div');
  wrap.className = 'scroll';
  wrap.append(table);
  details.replaceChildren(summary, note, wrap);
}

export function showUnavailable(el, text) {
  charts.get(el)?.destroy();
  charts.delete(el);
  const details = el.parentElement?.querySelector(`details[data-for="${el.id}"]`);
  if (details) details.hidden = true;
  el.classList.add('unavailable');
  el.textContent = text;
  el.dataset.points = '0';
}

// Charts follow their column's width (the page reflows between one and two columns).
const resize = new ResizeObserver((entries) => {
  for (const entry of entries) {
    const chart = charts.get(entry.target);
    if (chart && Math.abs(chart.width - width(entry.target)) > 4) {
      chart.setSize({ width: width(entry.target), height: height(entry.target) });
    }
  }
});

function methodSeries(names, extra = {}) {
  return names.map((m) => ({ label: METHOD_LABELS[m], stroke: COLORS[m], width: 1.5, ...extra }));
}

const fmtAxis = (digits) => (u, vals) => vals.map((v) => (v === null ? '' : Number(v.toPrecision(digits)).toString()));
const logAxis = (u, vals) => vals.map((v) => (v === null ? '' : v.toExponential(0).replace('e+', 'e')));

/// Response plot: time (s) against x for the exact motion (on its fine grid) and each method (at its steps).
/// `chosen` (the mode's soft method) is drawn thick, the others thin, so the one the designer gets stands
/// out; `pinned` (A of an A/B comparison: {t, x}) is A's chosen method, drawn grey and dashed; `overlay`
/// adds curves [{label, stroke, points: [[t, x]], dash?, markers?}] (a recording, web/identify.js).
export function drawResponse(el, series, chosen, pinned, overlay = []) {
  resize.observe(el);
  const names = METHODS.filter((m) => series.methods[m]);
  const zip = (t, x) => t.map((ti, i) => [ti, x[i]]);
  const curves = [zip(series.smooth.t, series.smooth.x), ...names.map((m) => zip(series.t, series.methods[m]))];
  if (pinned) curves.push(zip(pinned.t, pinned.x));
  const end = series.t[series.t.length - 1];  // an overlay is cut to the plot's own time span
  curves.push(...overlay.map((c) => c.points.filter(([t]) => t <= end)));
  draw(el, {
    scales: {
      x: { time: false },
      // Past the stability limit a method's growth would flatten the others: show at most +-3 (x0 = 1).
      y: { range: (u, lo, hi) => [Math.max(Math.min(lo, -1.05), -3), Math.min(Math.max(hi, 1.05), 3)] },
    },
    axes: [{ label: 'time (s)', values: fmtAxis(3) }, { label: 'x (x0 = 1)', values: fmtAxis(3) }],
    series: [{ label: 't (s)' },
      { label: 'exact', stroke: COLORS.exact, width: 2.5, dash: [6, 4], spanGaps: true, points: { show: false } },
      // Markers at each step while they are few enough to tell apart: they show where the method samples.
      ...names.map((m) => ({ label: m === chosen ? `${METHOD_LABELS[m]} (chosen)` : METHOD_LABELS[m], stroke: COLORS[m],
        width: m === chosen ? 3.5 : 1.2, spanGaps: true, points: { show: series.t.length <= 200 && m === chosen } })),
      ...(pinned ? [{ label: `A: ${pinned.label}`, stroke: '#8c959f', width: 2.5, dash: [3, 3], spanGaps: true, points: { show: false } }] : []),
      ...overlay.map((c) => ({ label: c.label, stroke: c.stroke, width: 1.5, dash: c.dash, spanGaps: true,
        points: { show: Boolean(c.markers) && c.points.length <= 200 } }))],
  }, aligned(curves));
}

/// Error plot: time (s) against |x_method - x_exact|, log scale.
export function drawError(el, series) {
  resize.observe(el);
  const names = METHODS.filter((m) => series.error[m]);
  draw(el, {
    scales: { x: { time: false }, y: { distr: 3 } },
    axes: [{ label: 'time (s)', values: fmtAxis(3) }, { label: '|x - exact|', values: logAxis, size: 60 }],
    series: [{ label: 't (s)' }, ...methodSeries(names)],
  }, [series.t, ...names.map((m) => series.error[m])]);
}

/// Work-precision chart from POST /api/v1/accuracy rows: CPU seconds per simulated second against max
/// error, log-log, one line per method through its step sizes; runs that blew up are left out.
export function drawWorkPrecision(el, rows) {
  resize.observe(el);
  const byMethod = new Map();
  for (const r of rows) {
    if (r.blew_up || !(r.cpu_seconds_per_sim_second > 0) || !(r.max_error > 0)) continue;
    if (!byMethod.has(r.method)) byMethod.set(r.method, []);
    byMethod.get(r.method).push(r);
  }
  if (byMethod.size === 0) {
    showUnavailable(el, 'Every configuration the accuracy run tried blew up or took no measurable time.');
    return;
  }
  // The five integrators in their usual order, then whatever else the run measured (an engine's row).
  const rank = (m) => (METHODS.includes(m) ? METHODS.indexOf(m) : METHODS.length);
  const names = [...byMethod.keys()].sort((a, b) => rank(a) - rank(b));
  const [xs, ...ys] = aligned(names.map((m) => byMethod.get(m).map((r) => [r.cpu_seconds_per_sim_second, r.max_error])));
  draw(el, {
    scales: { x: { time: false, distr: 3 }, y: { distr: 3 } },
    axes: [{ label: 'CPU s per simulated s', values: logAxis }, { label: 'max error', values: logAxis, size: 60 }],
    series: [{ label: 'CPU s' }, ...names.map((m) => ({
      label: METHOD_LABELS[m] ?? m.replaceAll('_', ' '), stroke: COLORS[m] ?? '#555', width: 1.5, spanGaps: true,
      points: { show: true, size: 7, fill: COLORS[m] ?? '#555' },
    }))],
  }, [xs, ...ys]);
}

/// uPlot's aligned data from curves sampled at different x: one shared, sorted x (every x of every curve)
/// and each curve's y at its own x, null elsewhere (the series join across the gaps with spanGaps).
export function aligned(curves) {
  const xs = [...new Set(curves.flatMap((c) => c.map(([x]) => x)))].sort((a, b) => a - b);
  const column = new Map(xs.map((x, i) => [x, i]));
  return [xs, ...curves.map((c) => {
    const y = new Array(xs.length).fill(null);
    for (const [x, v] of c) y[column.get(x)] = v;
    return y;
  })];
}

const PROBE_COLORS = ['#1f6feb', '#d1242f', '#1a7f37', '#bf8700', '#8250df', '#0a7ea4', '#cf222e', '#57606a'];

/// The simulation's probes over time (POST /api/v1/simulate `probes[].series`), one line per probe, on one
/// axis per unit: metres on the left, radians on the right (probeUnit, web/simulate_panel.js).
export function drawSimulation(el, probes, unitOf) {
  resize.observe(el);
  const withSeries = probes.filter((p) => Array.isArray(p.series?.time) && p.series.time.length > 1);
  if (withSeries.length === 0) {
    showUnavailable(el, 'This simulation returned no probe series to draw.');
    return;
  }
  const curves = withSeries.map((p) => p.series.time.map((t, i) => [t, p.series.value[i]]).filter(([t]) => t !== null));
  const units = [...new Set(withSeries.map((p) => unitOf(p.kind)))];
  const axes = [{ label: 'time (s)', values: fmtAxis(3) }, ...units.map((u, i) => ({
    scale: u, label: u === 'rad' ? 'angle (rad)' : 'length (m)', values: fmtAxis(3), size: 60, side: i === 0 ? 3 : 1,
    grid: { show: i === 0 },
  }))];
  // A probe that blew up would flatten the others: each unit's axis spans the probes that did not
  // (with a margin), and the blow-up leaves the plot at its edge.
  const span = (u) => {
    const values = withSeries.filter((p) => !p.diverged && unitOf(p.kind) === u).flatMap((p) => p.series.value)
      .filter((v) => typeof v === 'number' && Number.isFinite(v));
    if (values.length === 0) return {};
    const lo = Math.min(...values), hi = Math.max(...values), pad = 0.15 * (hi - lo || Math.abs(hi) || 1);
    return { range: [lo - pad, hi + pad] };
  };
  draw(el, {
    scales: { x: { time: false }, ...Object.fromEntries(units.map((u) => [u, span(u)])) },
    axes,
    series: [{ label: 't (s)' }, ...withSeries.map((p, i) => ({
      label: `${p.id} (${unitOf(p.kind)})`, scale: unitOf(p.kind), stroke: PROBE_COLORS[i % PROBE_COLORS.length], width: 1.5,
      spanGaps: true,
    }))],
  }, aligned(curves));
  el.dataset.units = units.join(' ');
}
