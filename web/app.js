// softtune's designer page: the form is the state (mirrored in the URL), every change asks the API
// again (debounced; only the newest answer is shown), and each panel says so plainly when this server
// lacks its route. Hooks for tests and tools: data-testid on values, plots and the preview image, and
// body[data-pending] = requests in flight or scheduled.
import { buildBodies } from './bodies.js';
import { ApiError, Latest, callJson, debounce, hasRoute, loadRoutes } from './api.js';
import { responseSeries } from './oscillator.js';
import { drawError, drawResponse, drawSimulation, drawWorkPrecision, showUnavailable } from './plots.js';
import { PreviewPlayer } from './preview.js';
import { showEngines, watchEngineValues } from './engine_table.js';
import { copyText, fmt, formatPercent, showNumbers, showStability } from './results.js';
import { modalScene, showModes } from './modes.js';
import {
  OSCILLATION_ZETA, fromQuery, readForm, stateFromScene, toQuery, tuneRequest, tunedScene, tuningFields,
  writeForm,
} from './state.js';

const form = document.getElementById('controls');
const results = document.getElementById('results');
const status = document.getElementById('status');
const $ = (id) => document.getElementById(id);
const player = new PreviewPlayer($('preview-panel'));

buildBodies($('bodies'), $('body-template'));

/// The defaults are the values written in index.html; the URL carries only what differs from them.
const DEFAULTS = readForm(form);
const PREVIEW_FRAMES = 60;
const PREVIEW_SIZE = '480x270';

const channels = { tune: new Latest(), simulate: new Latest(), accuracy: new Latest(), preview: new Latest() };
let presetScene = null;  // the scene JSON of the picked preset, once loaded
let pickedMode = null;   // {body, mode} the sliders tune (modes.js), or null: each spring on its own mass
let pending = 0;

function busy(delta) {
  pending += delta;
  document.body.dataset.pending = String(pending);
  status.textContent = pending > 0 ? 'Updating…' : status.dataset.error ?? 'Up to date';
}

/// debounce() whose waiting counts as pending work, so body[data-pending] = 0 means truly idle: nothing
/// scheduled and nothing in flight.
function trackedDebounce(fn, ms) {
  let armed = false;
  const run = debounce((...args) => {
    armed = false;
    fn(...args);  // starts its requests (tracked) before the wait is released below
    busy(-1);
  }, ms);
  return (...args) => {
    if (!armed) busy(+1);
    armed = true;
    run(...args);
  };
}

async function tracked(promise) {
  busy(+1);
  try {
    return await promise;
  } finally {
    busy(-1);
  }
}

// ---- controls -------------------------------------------------------------------------------------

function syncControls() {
  const state = readForm(form);
  const constraint = state.body === 'constraint';
  $('mass-group').hidden = constraint;
  $('constraint-group').hidden = !constraint;
  for (const p of ['a', 'b']) {
    const fs = form.querySelector(`[data-body="${p}"]`);
    const isStatic = state[`${p}_static`] === '1';
    fs.classList.toggle('is-static', isStatic);
    for (const el of fs.querySelectorAll('input[type="number"]')) el.disabled = isStatic;
  }
  $('frames-out').textContent = state.frames;
  $('zeta-out').textContent = Number(state.zeta).toFixed(2);
  const f = Number(state.basis) / Number(state.frames);
  $('frames-hz').textContent = Number.isFinite(f) ? `= ${fmt(f)} Hz (${state.frames} frames at ${state.basis} fps)` : '';
}

function updateUrl() {
  const query = toQuery(readForm(form), DEFAULTS);
  history.replaceState(null, '', query ? `?${query}` : location.pathname);
}

function onInput(event) {
  const t = event.target;
  if (t.name === 'osc') $('zeta').value = String(OSCILLATION_ZETA[t.value]);
  if (t.name === 'zeta') for (const r of form.querySelectorAll('input[name="osc"]')) r.checked = false;
  if (t.name === 'preset') {
    if (event.type !== 'change') return;
    loadPreset(t.value, true);
  }
  syncControls();
  updateUrl();
  scheduleTune();
}

// ---- errors next to their fields ------------------------------------------------------------------

function clearErrors() {
  for (const out of form.querySelectorAll('.error')) out.textContent = '';
  for (const f of form.querySelectorAll('.invalid')) f.classList.remove('invalid');
}

/// The field group whose data-field is the longest prefix of the problem's dotted path.
function fieldGroup(path) {
  let best = null;
  for (const g of form.querySelectorAll('[data-field]')) {
    const f = g.dataset.field;
    const matches = path === f || path.startsWith(`${f}.`) || path.startsWith(`${f}[`);
    if (matches && !g.closest('[hidden]') && (!best || f.length > best.dataset.field.length)) best = g;
  }
  return best;
}

function showProblem(error) {
  const field = error.field ?? '';
  const group = field ? fieldGroup(field) : null;
  const message = group ? error.message : `${field ? `${field}: ` : ''}${error.message}`;
  const out = group ? group.querySelector('.error') : $('form-error');
  out.textContent = message;
  group?.classList.add('invalid');
}

// ---- tune -----------------------------------------------------------------------------------------

const scheduleTune = trackedDebounce(runTune, 120);

async function runTune() {
  const state = readForm(form);
  const request = tuneRequest(state);
  results.classList.add('stale');
  let tune;
  try {
    tune = await tracked(channels.tune.run((signal) => callJson('POST', 'api/v1/tune', request, signal)));
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    clearErrors();
    showProblem(e);
    status.dataset.error = e.status === 0 ? e.message : `The API refused this tuning: ${e.message}`;
    busy(0);
    return;
  }
  if (tune === Latest.stale) return;
  clearErrors();
  delete status.dataset.error;
  busy(0);
  window.softtune = { request, tune };
  results.classList.remove('stale');
  showNumbers(results, tune);
  showStability(results, tune, Number(state.fps), Number(state.substeps));
  showEngines(results, tune);
  const series = responseSeries(tune);
  drawResponse($('plot-response'), series);
  $('response-note').textContent = sameCurve(series.methods.soft, series.methods.implicit_euler)
    ? 'The soft constraint and implicit Euler draw one curve: they are the same integrator (Catto, GDC 2011).' : '';
  drawError($('plot-error'), series);
  scheduleSlow(state, request, tune);
}

function sameCurve(a, b) {
  return a && b && a.every((x, i) => (x === null ? b[i] === null : Math.abs(x - b[i]) <= 1e-9));
}

// ---- the slower panels: simulate, accuracy, preview ------------------------------------------------

const scheduleSlow = trackedDebounce((state, request, tune) => {
  runSimulate(state, tune);
  runAccuracy(request);
  runPreview(state, tune);
}, 350);

function unavailable(what) {
  return `${what} is not available on this server.`;
}

/// The scene to simulate: the picked preset with the page's step and tuning, or a 1-D
/// oscillator with the effective mass the tune answer computed (from the mass or the 2-D constraint).
function sceneFor(state, tune) {
  if (state.preset) return presetScene ? modalScene(tunedScene(presetScene, state), tuningFields(state), pickedMode) : { preset: state.preset };
  const f = tune.requested?.frequency_hz ?? 0;
  return {
    name: 'custom',
    world: { fps: Number(state.fps), substeps: Number(state.substeps), duration_s: f > 0 ? Math.min(60, Math.max(1, 5 / f)) : 2 },
    oscillators: [{ id: 'body', method: state.mode === 'exact' ? 'soft_exact' : 'soft', effective_mass: tune.effective_mass,
      initial_displacement: 1, ...tuningFields(state) }],
    probes: [{ id: 'body', kind: 'oscillator', oscillator: 'body' }],
  };
}

async function runSimulate(state, tune) {
  const note = $('simulate-note');
  const body = $('probes').querySelector('tbody');
  const table = $('probes').closest('.scroll');
  const figure = $('simulation-figure');
  table.hidden = false;
  figure.hidden = true;
  if (!hasRoute('POST', '/api/v1/simulate')) {
    note.textContent = unavailable('Simulation');
    body.replaceChildren();
    table.hidden = true;
    return;
  }
  try {
    const doc = await tracked(channels.simulate.run((signal) => callJson('POST', 'api/v1/simulate', sceneFor(state, tune), signal)));
    if (doc === Latest.stale) return;
    note.textContent = doc.stages ? `Stages run: ${doc.stages.join(', ')}` : '';
    figure.hidden = false;
    drawSimulation($('plot-simulation'), doc.probes ?? []);
    body.replaceChildren(...(doc.probes ?? []).map((p) => {
      const tr = document.createElement('tr');
      const pct = (e) => formatPercent(e === null || e === undefined ? null : 100 * e);
      const cells = [p.id ?? '', fmt(p.requested?.frequency_hz), fmt(p.measured?.frequency_hz), pct(p.error?.frequency),
        fmt(p.requested?.damping_ratio), fmt(p.measured?.damping_ratio), pct(p.error?.damping_ratio),
        fmt(p.measured?.overshoot), fmt(p.measured?.settle_frames)];
      for (const [i, v] of cells.entries()) {
        const td = document.createElement(i === 0 ? 'th' : 'td');
        if (i === 0) td.scope = 'row';
        td.textContent = v;
        tr.append(td);
      }
      return tr;
    }));
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    body.replaceChildren();
    table.hidden = e.unavailable;
    note.textContent = e.unavailable ? unavailable('Simulation') : `Simulation refused: ${e.field ? `${e.field}: ` : ''}${e.message}`;
  }
}

/// The accuracy run's recommendation in words: its own `reason` sentence when it gives one.
function describe(recommendation) {
  if (recommendation === null || recommendation === undefined) return 'No configuration meets the error budget.';
  if (typeof recommendation !== 'object') return String(recommendation);
  if (recommendation.reason) return recommendation.reason;
  return Object.entries(recommendation).map(([k, v]) => `${k.replaceAll('_', ' ')}: ${typeof v === 'number' ? fmt(v) : v}`).join(', ');
}

async function runAccuracy(request) {
  const el = $('plot-work-precision');
  const note = $('accuracy-note');
  if (!hasRoute('POST', '/api/v1/accuracy')) {
    showUnavailable(el, unavailable('The work-precision chart (POST /api/v1/accuracy)'));
    note.textContent = '';
    return;
  }
  try {
    const doc = await tracked(channels.accuracy.run((signal) => callJson('POST', 'api/v1/accuracy', request, signal)));
    if (doc === Latest.stale) return;
    drawWorkPrecision(el, doc.rows ?? []);
    note.textContent = `Recommendation: ${describe(doc.recommendation)}`;
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    showUnavailable(el, e.unavailable ? unavailable('The work-precision chart (POST /api/v1/accuracy)')
      : `Accuracy run refused: ${e.field ? `${e.field}: ` : ''}${e.message}`);
    note.textContent = '';
  }
}

/// The preview contract (docs/preview.md): a Box2D preset by name, or the 1-D oscillator with the
/// tuning fields of `softtune tune` (a custom body, or the oscillator preset) and the effective mass the
/// tune answer computed (from the mass or the 2-D constraint). `wait: false` answers at once, so the
/// progress bar can follow the render.
function previewRequest(state, tune) {
  const settings = { frames: PREVIEW_FRAMES, size: PREVIEW_SIZE, wait: false };
  if (state.preset && state.preset !== 'oscillator') return { preset: state.preset, ...settings };
  const { constraint, ...fields } = tuneRequest(state);
  return { ...fields, effective_mass: tune.effective_mass, ...settings };
}

async function runPreview(state, tune) {
  const note = $('preview-note');
  const panel = $('preview-panel');
  panel.hidden = false;
  if (!hasRoute('POST', '/api/v1/preview')) {
    player.clear();
    panel.hidden = true;
    note.textContent = unavailable('The rendered preview');
    return;
  }
  try {
    const doc = await tracked(channels.preview.run(async (signal) => {
      player.rendering(null);
      let answer = await callJson('POST', 'api/v1/preview', previewRequest(state, tune), signal);
      // A preview still rendering answers with its id and progress: ask again until the frames are listed.
      while (!Array.isArray(answer.frames) && answer.id) {
        player.rendering(answer.progress ?? answer);
        await new Promise((r) => setTimeout(r, 250));
        if (signal.aborted) throw new DOMException('aborted', 'AbortError');
        answer = await callJson('GET', `api/v1/preview/${encodeURIComponent(answer.id)}`, undefined, signal);
      }
      return answer;
    }));
    if (doc === Latest.stale) return;
    player.load(doc.frames ?? [], doc.filmstrip);
    const ms = doc.timings?.wall_ms;
    note.textContent = `${doc.frames?.length ?? 0} frames${ms !== undefined && ms !== null ? `, rendered in ${fmt(ms)} ms` : ''}${doc.cached ? ' (from the cache)' : ''}`;
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    player.clear();
    panel.hidden = e.unavailable;
    note.textContent = e.unavailable ? unavailable('The rendered preview') : `Preview refused: ${e.field ? `${e.field}: ` : ''}${e.message}`;
  }
}

// ---- presets --------------------------------------------------------------------------------------

async function loadPresetList() {
  const select = $('preset');
  const note = $('preset-note');
  if (!hasRoute('GET', '/api/v1/presets')) {
    note.textContent = 'Presets are not available on this server: tune a custom body.';
    select.disabled = true;
    return;
  }
  try {
    const doc = await tracked(callJson('GET', 'api/v1/presets'));
    const list = Array.isArray(doc) ? doc : doc.presets ?? [];
    for (const item of list) {
      const name = typeof item === 'string' ? item : item.name;
      const option = new Option(typeof item === 'string' ? item : item.title ?? item.name, name);
      if (item.description) option.title = item.description;
      select.append(option);
    }
    if (select.dataset.pending) {
      select.value = select.dataset.pending;
      delete select.dataset.pending;
      if (select.value) await loadPreset(select.value, false);
    }
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    note.textContent = e.unavailable ? 'Presets are not available on this server: tune a custom body.' : e.message;
    select.disabled = e.unavailable;
  }
}

/// Loads a preset's scene; `adopt` copies its step and tuning into the controls (a user's pick), while a
/// reload keeps the controls the link holds.
async function loadPreset(name, adopt) {
  presetScene = null;
  const note = $('preset-note');
  note.textContent = '';
  if (!name) return;
  if (!hasRoute('GET', '/api/v1/presets/{name}')) {
    note.textContent = 'This server cannot send preset scenes; the preset is simulated by name.';
    return;
  }
  try {
    const doc = await tracked(callJson('GET', `api/v1/presets/${encodeURIComponent(name)}`));
    if ($('preset').value !== name) return;
    presetScene = doc.scene ?? doc;
    loadModes(name);
    // The numbers above tune the body in the controls; the simulation and preview run the preset's own bodies.
    note.textContent = presetScene.description ?? '';
    if (adopt) {
      writeForm(form, stateFromScene(presetScene));
      syncControls();
      updateUrl();
      scheduleTune();
    }
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    note.textContent = e.message;
  }
}

/// The preset's modes (modes.js); picking one makes the sliders tune it.
async function loadModes(name) {
  const panel = $('modes-panel');
  pickedMode = null;
  if (!panel) return;
  panel.replaceChildren();
  if (!presetScene?.bodies?.length || !hasRoute('POST', '/api/v1/modes')) return;
  try {
    const answer = await tracked(callJson('POST', 'api/v1/modes', { preset: name }));
    if ($('preset').value !== name) return;
    showModes(panel, answer, pickedMode, (target) => { pickedMode = target; scheduleTune(); });
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    panel.textContent = e.message;
  }
}

// ---- start ----------------------------------------------------------------------------------------

watchEngineValues(results);
form.addEventListener('input', onInput);
form.addEventListener('change', onInput);
form.addEventListener('submit', (e) => e.preventDefault());
$('copy-link').addEventListener('click', async (e) => {
  e.target.textContent = (await copyText(location.href)) ? 'Link copied' : 'Copy failed';
  setTimeout(() => { e.target.textContent = 'Copy link'; }, 1500);
});
window.addEventListener('popstate', () => {
  writeForm(form, fromQuery(location.search, DEFAULTS));
  syncControls();
  scheduleTune();
});

writeForm(form, fromQuery(location.search, DEFAULTS));
syncControls();
busy(0);
await loadRoutes();
runTune();
loadPresetList();
