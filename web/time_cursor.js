// The page's one time cursor on its plots: a vertical line at the preview's scene time on each chart
// (response, error, simulation), moved by the preview as it plays or steps, and a press or drag on a chart
// moves the preview to that time (paused). Charts are rebuilt with each answer, so the line is put back
// into whichever chart the element holds now.

/// Where time `t` (s) falls on `chart`'s plotting area, in CSS px from its left edge; null when outside it.
export function cursorLeft(chart, t, widthPx) {
  if (!chart || !Number.isFinite(t)) return null;
  const x = chart.valToPos(t, 'x');
  return Number.isFinite(x) && x >= 0 && x <= widthPx ? x : null;
}

/// Shows the time cursor of `el`'s chart at `t` (s); `chartOf(el)` is its uPlot instance (plots.js).
export function placeCursor(el, chart, t) {
  const over = chart?.over;
  if (!over) return;
  let line = over.querySelector('.time-cursor');
  if (!line) {
    line = document.createElement('div');
    line.className = 'time-cursor';
    line.dataset.testid = 'time-cursor';
    over.append(line);
  }
  const left = cursorLeft(chart, t, over.clientWidth);
  line.hidden = left === null;
  if (left !== null) line.style.left = `${left}px`;
  el.dataset.cursorS = String(t);
}

/// A press or drag on `el`'s chart seeks: `seek(t)` with the time under the pointer.
export function dragToSeek(el, chartOf, seek) {
  let dragging = false;
  const at = (e) => {
    const chart = chartOf(el);
    const over = chart?.over;
    if (!over) return;
    const x = e.clientX - over.getBoundingClientRect().left;
    if (x < 0 || x > over.clientWidth) return;
    const t = chart.posToVal(x, 'x');
    if (Number.isFinite(t)) seek(Math.max(0, t));
  };
  el.addEventListener('pointerdown', (e) => {
    if (!e.target.closest?.('.u-over')) return;
    dragging = true;
    el.setPointerCapture?.(e.pointerId);
    at(e);
  });
  el.addEventListener('pointermove', (e) => { if (dragging) at(e); });
  const stop = () => { dragging = false; };
  el.addEventListener('pointerup', stop);
  el.addEventListener('pointercancel', stop);
}
