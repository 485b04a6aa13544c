// A recorded trajectory dropped on the tuning panel (issue 19, docs/identify.md): the CSV (a header row,
// time in seconds first, then one column per probe) goes to POST /api/v1/identify with the tuning on the
// page; the recording and its fit are overlaid on the response plot (normalised like it: x0 = 1 about the
// fitted equilibrium), and a row in the engine table says what the engine did and what to type instead.
// The pure parts (query, overlay, row text) are exported for tests/web/identify.test.mjs.
import { ApiError } from './api.js';

const MAX_CSV_BYTES = 1 << 20;  // the service's body limit (server/http/limits.h kMaxBodyBytes)

let shown = null;  // { answer, engine, file } of the last recording identified
// The rounds of one request in one engine, oldest first: what was typed for each recording and what it
// measured. A recording dropped after the first is taken as made with the last answer's `next` typed, and
// goes with the earlier rounds as `previous` (docs/identify.md), so the correction iterates.
let rounds = { key: '', list: [], next: null };
const MAX_PREVIOUS = 4;  // kIdentifyMaxPrevious (core/include/softtune/identify.h)
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

/// The JSON body of a recording that continues `list` (earlier rounds, oldest first): `typed` is what the
/// user typed for it (the last answer's `next`), the newest rounds go as `previous`.
export function roundBody(csv, request, engine, list, typed) {
  const body = { csv, request };
  if (engine) body.engine = engine;
  if (typed) body.typed = { frequency_hz: typed.frequency_hz, damping_ratio: typed.damping_ratio };
  if (list.length) body.previous = list.slice(-MAX_PREVIOUS).map((r) => ({ typed: r.typed, measured: r.measured }));
  return body;
}

/// The round an answer adds: what was typed and what the recording measured (null when it measured no
/// frequency to iterate on).
export function roundOf(answer) {
  const typed = answer?.correction?.typed;
  if (!typed || typeof answer.frequency_hz !== 'number' || typeof answer.damping_ratio !== 'number') return null;
  return { typed: { frequency_hz: typed.frequency_hz, damping_ratio: typed.damping_ratio },
    measured: { frequency_hz: answer.frequency_hz, damping_ratio: Math.max(0, answer.damping_ratio) } };
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
  // No name: the engine of a recording is not tuning state (a link cannot carry the recording either).
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
  // After a black-box correction: type `next` into the engine, record again, drop the new recording.
  const again = document.createElement('small');
  again.className = 'note';
  again.dataset.testid = 'identify-again';
  again.textContent = 'Type the values under "instead" into the engine, record again and drop the new recording: it is sent with the earlier ones, so the correction iterates.';
  again.hidden = true;
  const restart = document.createElement('button');
  restart.type = 'button';
  restart.textContent = 'Start the rounds over';
  restart.hidden = true;
  restart.addEventListener('click', () => {
    rounds = { key: '', list: [], next: null };
    again.hidden = restart.hidden = true;
  });
  label.append(select);
  box.append(label, input, note, again, restart, error);
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

  let sent = 0;  // recordings sent: only the newest one's answer is shown and counted as a round
  async function send(file) {
    const mine = ++sent;
    error.textContent = '';
    if (file.size > MAX_CSV_BYTES) {
      error.textContent = `${file.name} is larger than the 1 MiB the service accepts`;
      return;
    }
    const tuned = request();
    const key = JSON.stringify([tuned, select.value]);
    if (key !== rounds.key) rounds = { key, list: [], next: null };  // another request or engine: round 1
    const csv = await file.text();
    let r;
    try {
      r = rounds.list.length === 0
        ? await fetch(`api/v1/identify?${identifyQuery(tuned, select.value)}`, { method: 'POST', headers: { 'Content-Type': 'text/csv' }, body: csv })
        : await fetch('api/v1/identify', { method: 'POST', headers: { 'Content-Type': 'application/json' },
          body: JSON.stringify(roundBody(csv, tuned, select.value, rounds.list, rounds.next)) });
    } catch (e) {
      error.textContent = new ApiError(0, { detail: `Cannot reach the softtune server (${e.message})` }).message;
      return;
    }
    const doc = await r.json().catch(() => null);
    if (mine !== sent) return;  // a newer recording was dropped meanwhile: this answer is of an older round
    if (!r.ok) {
      error.textContent = doc ? `${doc.field ? `${doc.field}: ` : ''}${doc.detail ?? doc.title}` : `identify failed (${r.status})`;
      return;
    }
    shown = { answer: doc, engine: select.value, file: file.name };
    window.softtune = { ...(window.softtune ?? {}), identify: doc };
    const round = roundOf(doc);
    if (round) rounds.list.push(round);
    rounds.next = doc.correction?.next ?? null;
    note.textContent = `${file.name} (round ${rounds.list.length || 1}): ${identifiedRow(doc, select.value).did}`;
    again.hidden = !(rounds.next && !doc.exact && doc.correction?.verdict !== 'met');
    restart.hidden = rounds.list.length < 2;
    // The round's marker last: whoever waits for it finds the answer's whole state in place.
    note.dataset.round = String(rounds.list.length);
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
