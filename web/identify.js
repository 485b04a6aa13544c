// A recorded trajectory dropped on the tuning panel (issue 19, docs/identify.md): the CSV (a header row,
// time in seconds first, then one column per probe) goes to POST /api/v1/identify with the tuning on the
// page; the recording and its fit are overlaid on the response plot (normalised like it: x0 = 1 about the
// fitted equilibrium), and a row in the engine table says what the engine did and what to type instead.
// The pure parts (query, overlay, row text) are exported for tests/web/identify.test.mjs.
import { ApiError } from './api.js';

const MAX_CSV_BYTES = 1 << 20;  // the service's body limit (server/http/limits.h kMaxBodyBytes)

let shown = null;  // { answer, engine, file } of the last recording identified
let fillEngines = () => {};  // refreshes the engine choice from the latest tune answer

/// The query of a text/csv identify request: the tune request's scalar fields, and the engine.
export function identifyQuery(request, engine) {
  const q = new URLSearchParams();
  for (const [k, v] of Object.entries(request ?? {})) {
    if (typeof v === 'number' || typeof v === 'string') q.set(k, String(v));
  }
  if (engine) q.set('engine', engine);
  return q;
}

/// The first probe's recording and fit as curves [[t, x]], normalised like the response plot: time from
/// the first sample, x = (x - x_e) / (x[0] - x_e). Empty when the answer has no equilibrium to scale by.
export function overlayCurves(answer) {
  const plot = answer?.plot;
  const name = plot && Object.keys(plot.recorded ?? {})[0];
  const xe = name !== undefined ? answer.equilibrium?.[name] : null;
  const rec = name !== undefined ? plot.recorded[name] : null;
  if (!rec?.length || typeof xe !== 'number' || !(Math.abs(rec[0] - xe) > 0)) return [];
  const t0 = plot.time_s[0], scale = rec[0] - xe;
  const curve = (t, x) => t.map((ti, i) => [ti - t0, x[i] === null ? null : (x[i] - xe) / scale]);
  const out = [{ label: `recorded (${name})`, stroke: '#e16f24', points: curve(plot.time_s, rec), markers: true }];
  const fit = plot.fitted?.[name];
  if (fit?.length) out.push({ label: 'identified fit', stroke: '#6e7781', points: curve(plot.fit_time_s, fit), dash: [3, 3] });
  return out;
}

const num = (v, digits = 4) => (typeof v === 'number' ? Number(v.toPrecision(digits)).toString() : '-');
const pct = (v) => (typeof v === 'number' ? `${v >= 0 ? '+' : ''}${(100 * v).toFixed(1)} %` : '-');

// Where the correction's rounds stand, when it is more than "record again" (docs/identify.md, the verdicts).
const stance = (verdict) => (verdict && verdict !== 'converging' ? `: ${verdict.replace('_', ' ')}` : '');

/// The engine-table row's texts: what the recording did, against the request, and what to type instead.
export function identifiedRow(answer, engine) {
  const verdicts = (answer.verdicts ?? []).map((v) => v.code);
  const did = `${num(answer.frequency_hz)} Hz, zeta ${num(answer.damping_ratio, 3)}` +
    (answer.error ? ` (${pct(answer.error.frequency)}, zeta ${answer.error.damping_ratio >= 0 ? '+' : ''}${num(answer.error.damping_ratio, 2)})` : '');
  const next = answer.correction?.next;
  const engineFields = answer.exact ?? answer.correction?.parameters ?? null;
  const instead = engineFields
    ? Object.entries(engineFields).filter(([, v]) => typeof v === 'number').map(([k, v]) => `${k} = ${num(v, 6)}`)
    : next ? [`frequency ${num(next.frequency_hz)} Hz, damping ratio ${num(next.damping_ratio, 3)}`, `k = ${num(next.k, 6)}, c = ${num(next.c, 6)}`] : [];
  return {
    engine: engine || 'recording',
    did,
    quality: verdicts.length ? verdicts.join(', ') : 'ok',
    instead,
    method: answer.exact ? "the engine model's exact" : next ? `${answer.correction.method} correction${stance(answer.correction.verdict)}` : 'no request to correct towards',
  };
}

/// Curves to overlay on the response plot (none before a recording is dropped).
export function identifyOverlay() {
  return shown ? overlayCurves(shown.answer) : [];
}

/// Adds the identified row to the engine table (#engines), which each tune answer redraws, and offers that
/// answer's engines for the next recording.
export function showIdentified(root) {
  fillEngines();
  const body = root.querySelector('#engines tbody');
  if (!body || !shown) return;
  body.querySelector('[data-testid="identify-row"]')?.remove();
  const row = identifiedRow(shown.answer, shown.engine);
  const tr = document.createElement('tr');
  tr.dataset.testid = 'identify-row';
  const cell = (...lines) => {
    const td = document.createElement('td');
    lines.forEach((l, i) => { if (i) td.append(document.createElement('br')); td.append(l); });
    return td;
  };
  const cols = root.querySelectorAll('#engines thead th').length || 4;
  const tds = [cell(`${row.engine}: recorded`, `(${shown.file})`), cell(...row.instead, row.method), cell(row.did, `quality: ${row.quality}`)];
  while (tds.length < cols) tds.push(cell(''));
  tr.append(...tds.slice(0, cols));
  body.prepend(tr);
}

/// Makes `panel` (the tuning form) accept a dropped CSV; `request()` is the tune request on the page,
/// `engines()` the engine names to offer, `redraw()` redraws the plot and the table.
export function installIdentify(panel, { request, engines, redraw }) {
  const box = document.createElement('div');
  box.className = 'field identify-drop';
  box.dataset.testid = 'identify-drop';
  const label = document.createElement('label');
  label.textContent = 'Recorded in ';
  const select = document.createElement('select');
  select.name = 'identify-engine';
  select.setAttribute('aria-label', 'Engine the recording comes from');
  const input = document.createElement('input');
  input.type = 'file';
  input.accept = '.csv,text/csv';
  input.setAttribute('aria-label', 'Recorded trajectory (CSV)');
  const note = document.createElement('small');
  note.className = 'note';
  note.textContent = 'Drop a recorded trajectory (CSV: time, then a position or angle) on this panel.';
  const error = document.createElement('output');
  error.className = 'error';
  label.append(select);
  box.append(label, input, note, error);
  panel.append(box);

  fillEngines = () => {
    const keep = select.value;
    const names = engines();
    if (names.join() === [...select.options].slice(1).map((o) => o.value).join()) return;
    select.replaceChildren(new Option('another engine', ''), ...names.map((e) => new Option(e, e)));
    select.value = names.includes(keep) ? keep : '';
  };
  select.addEventListener('focus', fillEngines);
  fillEngines();

  async function send(file) {
    error.textContent = '';
    if (file.size > MAX_CSV_BYTES) {
      error.textContent = `${file.name} is larger than the 1 MiB the service accepts`;
      return;
    }
    const query = identifyQuery(request(), select.value);
    let r;
    try {
      r = await fetch(`api/v1/identify?${query}`, { method: 'POST', headers: { 'Content-Type': 'text/csv' }, body: await file.text() });
    } catch (e) {
      error.textContent = new ApiError(0, { detail: `Cannot reach the softtune server (${e.message})` }).message;
      return;
    }
    const doc = await r.json().catch(() => null);
    if (!r.ok) {
      error.textContent = doc ? `${doc.field ? `${doc.field}: ` : ''}${doc.detail ?? doc.title}` : `identify failed (${r.status})`;
      return;
    }
    shown = { answer: doc, engine: select.value, file: file.name };
    window.softtune = { ...(window.softtune ?? {}), identify: doc };
    note.textContent = `${file.name}: ${identifiedRow(doc, select.value).did}`;
    redraw();
  }
  input.addEventListener('change', () => input.files[0] && send(input.files[0]));
  panel.addEventListener('dragover', (e) => {
    if ([...(e.dataTransfer?.types ?? [])].includes('Files')) {
      e.preventDefault();
      panel.classList.add('dropping');
    }
  });
  panel.addEventListener('dragleave', () => panel.classList.remove('dropping'));
  panel.addEventListener('drop', (e) => {
    const file = e.dataTransfer?.files?.[0];
    panel.classList.remove('dropping');
    if (!file) return;
    e.preventDefault();
    send(file);
  });
}
