// The "For your engine" table: per engine what to type, what that engine's own step then does against the
// request (or that it blows up, or cannot), the exact values, and its code with a copy button. The rows
// follow whatever engines the answer carries; one with a model (engines.<name>.parameters) shows its
// report, one without shows its older fields. web/engines.js builds every text; this file only draws.
import {
  ENGINE_LABELS, comparedTo, engineKeys, engineSnippet, engineWarnings, formatDifference, isModelled, legacyFields, notesFor,
  shortName, verdict,
} from './engines.js';
import { copyText, fmt, formatPercent } from './results.js';

let shown = null;  // the answer the table draws, so the exact / plain choice redraws the code alone

function el(tag, props = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'dataset') Object.assign(node.dataset, v);
    else if (k === 'className' || k === 'textContent' || k === 'title' || k === 'scope' || k === 'colSpan' || k === 'type') node[k] = v;
    else node.setAttribute(k, v);
  }
  node.append(...children.filter((c) => c !== null && c !== undefined && c !== ''));
  return node;
}

/// A number to read: six digits, the full value in the title and in data-value for tests and tools.
function number(value, testid) {
  return el('span', {
    className: 'num', textContent: fmt(value), title: value === null || value === undefined ? 'not defined' : String(value),
    dataset: { value: typeof value === 'number' ? String(value) : '', ...(testid ? { testid } : {}) },
  });
}

function valueList(values) {
  const entries = Object.entries(values ?? {});
  if (!entries.length) return el('span', { className: 'muted', textContent: 'nothing to type' });
  return el('ul', { className: 'values' }, ...entries.map(([name, v]) => el('li', {},
    el('code', { title: name, textContent: shortName(name) }), ' = ',
    typeof v === 'string' || typeof v === 'boolean' ? el('code', { textContent: String(v) }) : number(v))));
}

function errorClass(p, small, big) {
  if (p === null) return '';
  return Math.abs(p) < small ? 'err-small' : Math.abs(p) > big ? 'err-big' : '';
}

/// What a set of values does in the engine, against the request: frequency with its error in percent,
/// damping ratio with its error as a difference; or a "blows up" / "cannot" badge and why.
function prediction(e, which, prefix) {
  const v = verdict(which === 'exact' ? e.exact_predicted : e.predicted, comparedTo(e, shown));
  const box = el('div', { className: `prediction state-${v.state}` });
  if (v.state === 'blows_up' || v.state === 'cannot') {
    box.append(el('strong', { className: 'badge', textContent: v.state === 'blows_up' ? 'blows up' : 'cannot', dataset: { testid: `${prefix}-state` } }),
      el('span', { className: 'muted', textContent: v.state === 'blows_up' ? ` spectral radius ${fmt(v.predicted.spectral_radius)} per step` : ' no spring with these values' }));
    for (const m of notesFor(e, which)) box.append(el('p', { className: 'note', textContent: m }));
    return box;
  }
  if (v.state === 'none') return el('span', { className: 'muted', textContent: 'no prediction' });
  const df = v.dampingError;
  box.append(
    el('div', {}, number(v.predicted.frequency_hz, `${prefix}-frequency`), ' Hz ',
      el('span', { className: errorClass(v.frequencyError, 2, 10), textContent: formatPercent(v.frequencyError) })),
    el('div', {}, 'ζ ', number(v.predicted.damping_ratio, `${prefix}-damping`), ' ',
      el('span', { className: errorClass(df === null ? null : 100 * df, 1, 5), textContent: formatDifference(df) })));
  return box;
}

function exactCell(e) {
  if (!e.exact) {
    return el('div', { className: 'prediction state-cannot' },
      el('strong', { className: 'badge', textContent: 'cannot', dataset: { testid: 'exact-state' } }),
      el('span', { className: 'muted', textContent: ' no values meet the request' }),
      ...notesFor(e, 'exact').map((m) => el('p', { className: 'note', textContent: m })));
  }
  return el('div', {}, valueList(e.exact), prediction(e, 'exact', 'exact'));
}

function settingsLine(e) {
  const s = Object.entries(e.settings ?? {});
  return s.length ? el('small', { className: 'note settings', textContent: `assumes ${s.map(([k, v]) => `${k} ${typeof v === 'number' ? fmt(v) : v}`).join(', ')}` }) : null;
}

function chosenValues(root) {
  return root.querySelector('input[name="engine-values"]:checked')?.value ?? 'exact';
}

function copyButton(label, text) {
  const button = el('button', { type: 'button', textContent: 'Copy', 'aria-label': `Copy the ${label} code` });
  button.addEventListener('click', async () => {
    button.textContent = (await copyText(text())) ? 'Copied' : 'Copy failed';
    setTimeout(() => { button.textContent = 'Copy'; }, 1500);
  });
  return button;
}

function rows(root, key) {
  const e = shown.engines[key];
  const label = ENGINE_LABELS[key] ?? key;
  const modelled = isModelled(e);
  const code = () => engineSnippet(key, e, shown, chosenValues(root));
  const pre = el('pre', { dataset: { testid: 'snippet' } });
  pre.textContent = code();
  // A solved scene joint says where each engine's values come from: the scene's run, or a per-joint model.
  const basis = e?.note ? el('small', { className: 'note basis', textContent: e.note, dataset: { testid: 'engine-basis', basis: e.basis ?? '' } }) : null;
  const head = el('th', { scope: 'row', title: e?.model ?? '' }, el('span', { className: 'engine-name', textContent: label }),
    modelled ? settingsLine(e) : null, basis);
  const cells = modelled
    ? [valueList(e.parameters), prediction(e, 'plain', 'predicted'), exactCell(e)]
    : [valueList(Object.fromEntries(legacyFields(e))),
      el('span', { className: 'muted', textContent: 'not modelled yet: these are softtune\'s own numbers, not a prediction of this engine\'s step' })];
  const labels = ['what to type', 'predicted', 'exact values'];
  const main = el('tr', { dataset: { engine: key }, className: modelled ? 'engine' : 'engine legacy' }, head,
    ...cells.map((c, i) => el('td', { dataset: { label: labels[i] }, ...(modelled || i === 0 ? {} : { colSpan: 2 }) }, c)),
    el('td', { className: 'copy' }, copyButton(label, code)));
  // The engine's warnings that no cell above shows (those explain a "blows up" or "cannot").
  const seen = new Set([...main.querySelectorAll('.note')].map((p) => p.textContent));
  const rest = engineWarnings(shown, key).filter((w) => !seen.has(w.message));
  const snippet = el('tr', { className: 'snippet', dataset: { engine: key } },
    el('td', { colSpan: 5 },
      rest.length ? el('ul', { className: 'warnings' }, ...rest.map((w) => el('li', { textContent: w.message, dataset: { code: w.code ?? '' } }))) : null,
      el('details', {}, el('summary', { textContent: `${label} code` }),
        e?.model ? el('p', { className: 'note', textContent: `Modelled from ${e.model}.` }) : null, pre)));
  snippet.redraw = () => { pre.textContent = code(); };
  return [main, snippet];
}

export function showEngines(root, tune) {
  shown = tune;
  const req = tune.requested ?? {};
  root.querySelector('#engines-note').textContent =
    `Predicted: what each engine's own step does with the values to type, against the request (error in percent for the frequency, difference for the damping ratio ζ). Exact: the values that make the engine do what was asked.`;
  root.querySelector('#engines-asked').textContent = `asked ${req.mode ? `${req.mode} ` : ''}${fmt(req.frequency_hz)} Hz, ζ ${fmt(req.damping_ratio)}`;
  root.querySelector('#engines tbody').replaceChildren(...engineKeys(tune).flatMap((key) => rows(root, key)));
}

/// The exact / plain choice redraws each engine's code; the copy buttons read it when clicked.
export function watchEngineValues(root) {
  for (const r of root.querySelectorAll('input[name="engine-values"]')) {
    r.addEventListener('change', () => {
      for (const tr of root.querySelectorAll('#engines tr.snippet')) tr.redraw?.();
    });
  }
}
