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
  const chart = new uPlot({ width: width(el), height: height(el), ...opts }, data, el);
  charts.set(el, chart);
  el.dataset.points = String(data[0].length);
}

export function showUnavailable(el, text) {
  charts.get(el)?.destroy();
  charts.delete(el);
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

/// Response plot: time (s) against x for the exact motion (on its fine grid) and each method (at its steps);
/// `overlay` adds curves [{label, stroke, points: [[t, x]], dash?, markers?}] (a recording, web/identify.js).
export function drawResponse(el, series, overlay = []) {
  resize.observe(el);
  const names = METHODS.filter((m) => series.methods[m]);
  const zip = (t, x) => t.map((ti, i) => [ti, x[i]]);
  const end = series.t[series.t.length - 1];  // an overlay is cut to the plot's own time span
  const data = aligned([zip(series.smooth.t, series.smooth.x), ...names.map((m) => zip(series.t, series.methods[m])),
    ...overlay.map((c) => c.points.filter(([t]) => t <= end))]);
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
      ...methodSeries(names, { spanGaps: true, points: { show: series.t.length <= 200 } }),
      ...overlay.map((c) => ({ label: c.label, stroke: c.stroke, width: 1.5, dash: c.dash, spanGaps: true,
        points: { show: Boolean(c.markers) && c.points.length <= 200 } }))],
  }, data);
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

/// The simulation's probes over time (POST /api/v1/simulate `probes[].series`), one line per probe.
export function drawSimulation(el, probes) {
  resize.observe(el);
  const withSeries = probes.filter((p) => Array.isArray(p.series?.time) && p.series.time.length > 1);
  if (withSeries.length === 0) {
    showUnavailable(el, 'This simulation returned no probe series to draw.');
    return;
  }
  const curves = withSeries.map((p) => p.series.time.map((t, i) => [t, p.series.value[i]]).filter(([t]) => t !== null));
  draw(el, {
    scales: { x: { time: false } },
    axes: [{ label: 'time (s)', values: fmtAxis(3) }, { label: 'probe value', values: fmtAxis(3), size: 60 }],
    series: [{ label: 't (s)' }, ...withSeries.map((p, i) => ({
      label: p.id, stroke: PROBE_COLORS[i % PROBE_COLORS.length], width: 1.5, spanGaps: true,
    }))],
  }, aligned(curves));
}
