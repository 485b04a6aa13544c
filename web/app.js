// softtune's designer page: the form is the state (mirrored in the URL, one history entry per gesture, so
// the browser's back and forward undo and redo), every change asks the API again (debounced; only the
// newest answer is shown), and each panel says so plainly when this server lacks its route. A preset is
// tuned by the server (`tuning` of simulate and preview), so its preview and its simulation follow the
// controls. Hooks for tests and tools: data-testid on values, plots and the preview image, and
// body[data-pending] = requests in flight or scheduled.
import { Comparison } from './ab.js';
import { buildBodies } from './bodies.js';
import { drawConstraint, showMassTerms } from './constraint_view.js';
import { ApiError, Latest, callJson, hasRoute, loadRoutes, oscillationWords } from './api.js';
import { Debounced, GESTURE_WAIT_MS, InputGenerations, waitFor } from './input_flow.js';
import { askedResponse, drawLive, feel, feelWords, liveCurve } from './live_curve.js';
import { clearPending, holdSummary, markPending, showOffBy } from './summary_bar.js';
import { presetWords } from './preset_words.js';
import { download, exportName, stateFromDocument } from './exchange.js';
import { designerMessage, inputProblems } from './input_check.js';
import { responseSeries } from './oscillator.js';
import { drawLanes, oscillatorLanes } from './oscillator_lanes.js';
import { chartOf, drawError, drawResponse, drawSimulation, drawWorkPrecision, showUnavailable } from './plots.js';
import { dragToSeek, placeCursor } from './time_cursor.js';
import { fetchPresetScene, fillJointPicker, fillPresetList, isBox2dScene } from './presets.js';
import { PreviewPlayer } from './preview.js';
import { showEngines, watchEngineValues } from './engine_table.js';
import { chainField, showChain } from './chain.js';
import { chosenVerdict, copyText, fmt, showModalSummary, showNumbers, showStability, showSummary } from './results.js';
import { probeUnit, showJoints, showModalTargets, showProbes, tunedJoints } from './simulate_panel.js';
import { identifyOverlay, installIdentify, showIdentified } from './identify.js';
import { modesOfAnswer, showModes, solvedAnswer } from './modes.js';
import { installTyped } from './typed.js';
import { installSceneEngines, showSceneEngineValues, withSceneEngine } from './scene_engine.js';
import {
  fromQuery, presetRequest, previewRequest, readForm, stateFromScene, toQuery, tuneRequest, tuningFields,
  writeForm,
} from './state.js';

const form = document.getElementById('controls');
const results = document.getElementById('results');
const status = document.getElementById('status');
const $ = (id) => document.getElementById(id);
const player = new PreviewPlayer($('preview-panel'));
const comparison = new Comparison(document.querySelector('main'), $('preview'), $('preview-a'));
let lastSeries = null;  // the response series of the answer shown, for pinning it as A
const typedPanel = installTyped($('typed-panel'), (scene) => callJson('POST', 'api/v1/simulate', { scene }));
let lanes = [];         // a preset's 1-D oscillators, drawn beside its preview at the same scene time
const previewTime = () => Number($('preview').dataset.frame ?? 0) * (Number($('preview').dataset.frameSeconds) || 0);
// The one time cursor: the preview's frame; every plot shows it and a drag on a plot moves it.
const TIMED_PLOTS = ['plot-response', 'plot-error', 'plot-simulation'];
function placeCursors() {
  for (const id of TIMED_PLOTS) placeCursor($(id), chartOf($(id)), previewTime());
}
for (const id of TIMED_PLOTS) dragToSeek($(id), chartOf, (t) => player.seek(t));
new MutationObserver(() => {
  drawAtSlider();
  placeCursors();
  if (lanes.length === 0) return;
  drawLanes($('lanes'), lanes, previewTime());
}).observe($('preview'), { attributes: true, attributeFilter: ['data-frame'] });

// ---- the response at the slider (web/live_curve.js) -------------------------------------------------

// The curve shown beside the sliders: computed from the controls on every input event ('input'), then
// the tune answer's own replay ('answer'); the dot sits at the preview's time.
let live = { curve: null, source: '', fps: 60, ask: '' };
let liveDraws = 0;

/// The curve of the controls as they are now, before any answer (kept as it was when a field is refused,
/// and when the controls still ask what the curve shows: the answer's own replay then stays).
function liveFromControls() {
  const ask = askedResponse(readForm(form), words);
  if (!ask) {
    $('live-curve').dataset.source = 'refused';
    return;
  }
  const key = JSON.stringify(ask);
  if (key === live.ask) return;
  live = { curve: liveCurve(ask), source: 'input', fps: ask.fps, ask: key };
  drawAtSlider();
}

function drawAtSlider() {
  const canvas = $('live-curve');
  if (!live.curve) return;
  drawLive(canvas, live.curve, { ghost: comparison.pinned?.series ?? null, cursorS: previewTime() });
  canvas.dataset.source = live.source;
  canvas.dataset.drawn = String(++liveDraws);  // for tests and the latency bench: a redraw happened
  $('live-words').textContent = feelWords(feel(live.curve, live.fps));
}

buildBodies($('bodies'), $('body-template'));

/// The defaults are the values written in index.html; the URL carries only what differs from them, or,
/// with a preset, from that preset's own step and tuning (so `?preset=stiff` is the stiff preset as it is).
const DEFAULTS = readForm(form);
let urlDefaults = DEFAULTS;

const channels = { tune: new Latest(), simulate: new Latest(), accuracy: new Latest(), preview: new Latest(), modes: new Latest() };
let words = {};          // oscillation word -> damping ratio, from the server's OpenAPI document
let presetScene = null;  // the scene document of the picked preset, once loaded
let presetJoints = null; // a Box2D preset's tuned joints (their masses come from its bodies), once simulated
let pending = 0;

function busy(delta) {
  pending += delta;
  document.body.dataset.pending = String(pending);
  status.textContent = pending > 0 ? 'Updating…' : status.dataset.error ?? 'Up to date';
}

function setError(text) {
  if (text) status.dataset.error = text;
  else delete status.dataset.error;
  busy(0);
}

/// A debounced call whose waiting counts as pending work, so body[data-pending] = 0 means truly idle:
/// nothing scheduled and nothing in flight.
const trackedWait = (fn) => new Debounced(fn, { onArm: () => busy(+1), onRelease: () => busy(-1) });

async function tracked(promise) {
  busy(+1);
  try {
    return await promise;
  } finally {
    busy(-1);
  }
}

// ---- controls -------------------------------------------------------------------------------------

const box2dPreset = (state) => Boolean(state.preset) && state.preset !== 'oscillator';

function syncControls() {
  const state = readForm(form);
  const constraint = state.body === 'constraint';
  // A Box2D preset's numbers describe one of its joints, whose bodies give the mass: the body controls
  // apply only to a custom body (or a preset without tuned joints, or the 1-D oscillator preset).
  const jointMass = box2dPreset(state) && presetJoints?.length > 0;
  $('joint-group').hidden = !box2dPreset(state);
  $('body-group').hidden = jointMass || state.preset === 'oscillator';
  $('mass-group').hidden = jointMass || constraint;
  $('constraint-group').hidden = jointMass || !constraint;
  for (const p of ['a', 'b']) {
    const fs = form.querySelector(`[data-body="${p}"]`);
    const isStatic = state[`${p}_static`] === '1';
    fs.classList.toggle('is-static', isStatic);
    for (const el of fs.querySelectorAll('input[type="number"]')) el.disabled = isStatic;
  }
  $('frames-out').textContent = state.frames;
  $('zeta-out').textContent = Number(state.zeta).toFixed(2);
  const f = Number(state.basis) / Number(state.frames);
  $('frames-hz').textContent = state.basis !== '' && Number.isFinite(f) ? `= ${fmt(f)} Hz (${state.frames} frames at ${state.basis} fps)` : '';
  liveFromControls();  // the response at the slider follows every event, before any answer
}

// One history entry per gesture: the first input after a committed change opens an entry, later inputs
// of the same drag or typing replace it, and the change event closes it. Only accepted input gets here
// (onInput), so no entry holds a half-typed number; `settling` replaces the current entry (what the page
// fills in itself once a preset's scene is known belongs to the pick that caused it).
let entryOpen = false;
function updateUrl(commit, settling = false) {
  const query = toQuery(readForm(form), urlDefaults);
  const url = query ? `?${query}` : location.pathname;
  if (`${location.pathname}${location.search}` !== (query ? `${location.pathname}?${query}` : location.pathname)) {
    if (entryOpen || settling) history.replaceState(null, '', url);
    else history.pushState(null, '', url);
  }
  if (!settling) entryOpen = !commit;
}

// Accepted input, by generation (web/input_flow.js): an answer is shown only if no input came after the
// request it answers, so a late answer never clears a refusal or overwrites newer numbers.
const generations = new InputGenerations();
let acceptedState = '';  // the form as last accepted: an event that changes nothing sends nothing

function onInput(event) {
  const t = event.target;
  if (!t.name) return;
  if (t.name === 'osc' && t.value in words) $('zeta').value = String(words[t.value]);
  if (t.name === 'zeta') for (const r of form.querySelectorAll('input[name="osc"]')) r.checked = false;
  if (t.name === 'target' && t.type === 'radio') $('target').value = t.value;  // the hidden field the URL keeps
  if (t.name === 'preset') {
    if (event.type !== 'change') return;
    loadPreset(t.value, true);
    return;
  }
  syncControls();
  if (inputProblems(form).length > 0) {
    // Refused: nothing is sent, nothing scheduled or in flight may show, and the address keeps the last
    // settled state (no history entry for a half-typed number).
    refuse();
    return;
  }
  const state = readForm(form);
  const text = JSON.stringify(state);
  const changed = text !== acceptedState || generations.refused;
  updateUrl(event.type === 'change');
  if (!changed) return;  // a slider's change event after its input events: asked already
  acceptedState = text;
  generations.accept();
  const ms = waitFor(event);
  scheduleTune(ms);
  if (box2dPreset(state)) schedulePreview(ms + PREVIEW_AFTER_TUNE_MS);
}

/// Input the page refuses: every wait and every request in flight is dropped, and the fields say why.
function refuse() {
  generations.refuse();
  for (const wait of [tuneWait, slowWait, previewWait]) wait.cancel();
  for (const channel of Object.values(channels)) channel.cancel();
  lastPreview = '';
  refuseInput();
}

// ---- errors next to their fields ------------------------------------------------------------------

function clearErrors() {
  for (const out of form.querySelectorAll('.error')) out.textContent = '';
  for (const f of form.querySelectorAll('.invalid')) f.classList.remove('invalid');
  for (const el of form.querySelectorAll('[aria-invalid]')) el.removeAttribute('aria-invalid');
}

/// The field group whose data-field is the longest prefix of the problem's dotted path (a preset's
/// `tuning.fps` is the page's fps).
function fieldGroup(path) {
  const p = path.replace(/^tuning\./, '');
  let best = null;
  for (const g of form.querySelectorAll('[data-field]')) {
    const f = g.dataset.field;
    const matches = p === f || p.startsWith(`${f}.`) || p.startsWith(`${f}[`);
    if (matches && !g.closest('[hidden]') && (!best || f.length > best.dataset.field.length)) best = g;
  }
  return best;
}

function markInvalid(group, message) {
  group.querySelector('.error').textContent = message;
  group.classList.add('invalid');
  for (const el of group.querySelectorAll('input, select')) el.setAttribute('aria-invalid', 'true');
}

function groupLabel(group) {
  const label = group.querySelector('label, .label');
  return label ? label.textContent.replace(/\s*\(.*$/s, '').replace(/:.*$/s, '').trim() : '';
}

/// Shows an API problem at its field, in designer words; returns the sentence for the status line.
function showProblem(error) {
  const field = error.field ?? '';
  const group = field ? fieldGroup(field) : null;
  const message = designerMessage(error.message, group ? groupLabel(group) : '');
  if (group) markInvalid(group, message);
  else $('form-error').textContent = message;
  return message;
}

/// The page's own check: empty or non-numeric fields are shown at the field and nothing is sent.
function refuseInput() {
  const problems = inputProblems(form);
  if (problems.length === 0) return false;
  clearErrors();
  for (const { el, message } of problems) {
    const group = el.closest('.field');
    const out = group.querySelector('.error');
    out.textContent = out.textContent ? `${out.textContent} ${message}` : message;
    group.classList.add('invalid');
    el.setAttribute('aria-invalid', 'true');
  }
  results.classList.add('stale');
  const more = problems.length > 1 ? ` (and ${problems.length - 1} more)` : '';
  setError(`Not updated: ${problems[0].message}${more}`);
  return true;
}

// ---- tune -----------------------------------------------------------------------------------------

// Short waits: a drag sends few requests (a newer one aborts the older), yet the numbers follow at once.
const tuneWait = trackedWait(() => runTune());
const scheduleTune = (ms = GESTURE_WAIT_MS) => tuneWait.call(ms);
let tuneShown = 0;  // answers shown so far: a newer one drops the older one's plots

async function runTune() {
  if (refuseInput()) return;
  const generation = generations.current;
  let state = readForm(form);
  acceptedState = JSON.stringify(state);
  if (box2dPreset(state) && presetJoints === null) {
    // The joints' effective masses come from the preset's bodies: the first simulation reports them.
    await runSimulate(state, null);
    if (!generations.belongs(generation)) return;
    state = readForm(form);
  }
  const joint = presetJoints?.find((j) => j.id === state.joint);
  const request = tuneRequest(state, box2dPreset(state) && joint ? joint.model_mass : undefined);
  if (box2dPreset(state) && joint?.engine_settings) request.engine_settings = joint.engine_settings;  // its own def
  const chain = chainField($('chain-mass-ratio')?.value);  // no name: not part of the URL state
  $('chain-error').textContent = chain instanceof Error ? chain.message : '';
  if (chain && !(chain instanceof Error)) request.chain = chain;
  results.classList.add('stale');
  let tune;
  try {
    tune = await tracked(channels.tune.run((signal) => callJson('POST', 'api/v1/tune', request, signal)));
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    if (!generations.belongs(generation)) return;
    clearErrors();
    const message = showProblem(e);
    setError(e.status === 0 ? e.message : `Not updated: ${message}`);
    return;
  }
  if (tune === Latest.stale || !generations.belongs(generation)) return;
  clearErrors();
  setError('');
  // The slider follows the word the server mapped (when the page could not read the mapping itself).
  if (state.osc && typeof tune.requested?.damping_ratio === 'number') {
    $('zeta').value = String(tune.requested.damping_ratio);
    $('zeta-out').textContent = tune.requested.damping_ratio.toFixed(2);
  }
  // A modally tuned preset's joint shows its solved answer (the last simulation's), never the per-spring tune.
  // Merged, not replaced: the identify answer (identify.js) lives here too, and this tune (the redraw its
  // round asks for) must not wipe it while a reader of the round's marker is about to read it.
  const solved = solvedFor(state);
  window.softtune = { ...window.softtune, request, tune: solved ?? tune };
  results.classList.remove('stale');
  // A preset tuned by its modes shows its scene's solve in the bar: until that answer, the last one stays,
  // marked pending (the tune answer describes one spring on its own mass).
  const modal = modalTuned(state);
  const held = modal ? holdSummary($('summary')) : null;
  showSummary($('summary'), tune, joint ? `joint ${joint.id}` : '');
  if (modal) markPending($('summary'), held);
  else {
    clearPending($('summary'));
    showOffBy($('summary'), tune.requested, tune.achieved);
  }
  showNumbers(results, solved ?? tune);
  comparison.showNumbers();
  // The preview is what a designer watches: it starts now, before the plots are built. The oscillator's needs
  // this answer (its mass and duration); a Box2D preset's started with the change (schedulePreview) unless
  // the preset was just opened, and the same request is not sent twice.
  runPreview(state, tune);
  // Let the numbers paint before the tables and plots are built (a frame, then the rest).
  const seq = ++tuneShown;
  await tracked(new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0))));
  if (seq !== tuneShown) return;
  // One panel per task: between them the preview's answers and frames get the main thread (built at once,
  // they held the first preview frame back by 150-250 ms in headless Chromium on two cores).
  const steps = [
    () => {
      $('mass-terms').hidden = !showMassTerms($('mass-terms-table').querySelector('tbody'), tune, state.ctype === 'angular');
      if (!$('mass-terms').hidden) drawConstraint($('constraint-drawing'), state);
      showStability(results, tune, Number(state.fps), Number(state.substeps));
    },
    () => showEngines(results, solvedFor(state) ?? tune),
    () => {
      showChain(document, tune);
      showIdentified(results);
    },
    () => {
      const series = responseSeries(tune);
      lastSeries = series;
      const chosen = series.methods[chosenMethod(tune)];
      if (chosen) {
        live = { curve: { t: series.t, x: chosen }, source: 'answer', fps: Number(state.fps), ask: JSON.stringify(askedResponse(state, words)) };
        drawAtSlider();
      }
      drawResponse($('plot-response'), series, chosenMethod(tune), comparison.pinned?.series, identifyOverlay());
      $('response-note').textContent = sameCurve(series.methods.soft, series.methods.implicit_euler)
        ? 'The soft constraint and implicit Euler draw one curve: they are the same integrator (Catto, GDC 2011).' : '';
    },
    () => {
      drawError($('plot-error'), lastSeries);
      placeCursors();
    },
  ];
  for (const [i, step] of steps.entries()) {
    if (i > 0) await tracked(new Promise((r) => setTimeout(r, 0)));
    if (seq !== tuneShown) return;
    step();
  }
  scheduleSlow(state, request, tune);
}

const chosenMethod = (tune) => (tune.mode === 'exact' ? 'soft_exact' : 'soft');

/// Whether the preset's scene is tuned by a mode (its simulation solves the joints' k and c for it).
function modalTuned(state) {
  if (!box2dPreset(state) || !presetScene) return false;
  const asked = presetRequest(state, presetScene);
  return Boolean((asked.scene ?? presetScene).modal_tuning);
}

function describeTuning(state) {
  const feel = state.osc ? `${state.osc} oscillation` : `damping ratio ${state.zeta}`;
  return `${state.preset || 'custom'}, ${state.frames} frames, ${feel}, ${state.mode}`;
}

// The jump to the engine table scrolls there without a fragment: no history entry, no popstate.
$('live').querySelector('.jump').addEventListener('click', (e) => {
  e.preventDefault();
  $('engines-h').scrollIntoView({ block: 'start' });
});

$('ab-side').addEventListener('change', (e) => {
  document.querySelector('main').dataset.abLayout = e.target.checked ? 'side' : 'ghost';
});

$('pin').addEventListener('click', () => {
  const tune = window.softtune?.tune;
  if (comparison.pinned || !tune) comparison.unpin();
  else comparison.pin(tune, lastSeries, chosenMethod(tune), { frames: player.frames, dt: player.frameSeconds }, describeTuning(readForm(form)));
  $('pin').textContent = comparison.pinned ? 'Unpin A' : 'Pin as A';
  $('pin').setAttribute('aria-pressed', comparison.pinned ? 'true' : 'false');
  scheduleTune();
});

function sameCurve(a, b) {
  return a && b && a.every((x, i) => (x === null ? b[i] === null : Math.abs(x - b[i]) <= 1e-9));
}

// ---- the slower panels: simulate, accuracy, preview ------------------------------------------------

// The simulation and the accuracy run wait for a drag to settle. The preview does not: the render pool
// takes the newest preview first (render/src/frame_pipeline.cpp), so a drag's stale previews render behind
// the one the designer waits for, and stay cached for undo.
const slowWait = trackedWait((state, request, tune) => {
  runSimulate(state, tune);
  runAccuracy(request);
});
const scheduleSlow = (state, request, tune) => slowWait.call(100, state, request, tune);
// A Box2D preset's preview needs no tune answer (the server tunes the scene): it starts with the change,
// a little after the tune request, whose answer it would otherwise slow down (its scene's run and modal
// solve take the server's cores for 50 ms: at 30 ms the numbers' p95 went from 95 to 224 ms).
const PREVIEW_AFTER_TUNE_MS = 30;
const previewWait = trackedWait(() => {
  const state = readForm(form);
  if (box2dPreset(state) && inputProblems(form).length === 0) runPreview(state, null);
});
const schedulePreview = (ms) => previewWait.call(ms);

function unavailable(what) {
  return `${what} is not available on this server.`;
}

/// What to simulate: the picked preset tuned by the page (server/app/scene_tuning.h), with the mode the
/// `target` control picks as the target of its tuned joints (state.js presetRequest), or a 1-D oscillator
/// with the effective mass the tune answer computed (from the mass or the 2-D constraint).
function simulateRequest(state, tune) {
  if (state.preset) return presetRequest(state, presetScene);
  const f = tune.requested?.frequency_hz ?? 0;
  return {
    name: 'custom',
    world: { fps: Number(state.fps), substeps: Number(state.substeps), duration_s: f > 0 ? Math.min(60, Math.max(1, 5 / f)) : 2 },
    oscillators: [{ id: 'body', method: state.mode === 'exact' ? 'soft_exact' : 'soft', effective_mass: tune.effective_mass,
      initial_displacement: 1, ...tuningFields(state) }],
    probes: [{ id: 'body', kind: 'oscillator', oscillator: 'body' }],
  };
}

/// The joint table and picker from a simulate answer of a Box2D preset.
function showPresetJoints(state, doc) {
  const joints = tunedJoints(doc);
  const first = presetJoints === null;
  presetJoints = joints;
  const select = $('joint');
  const picked = fillJointPicker(select, joints, select.dataset.pending || state.joint);
  delete select.dataset.pending;
  showJoints($('joints').querySelector('tbody'), joints, picked);
  $('joints').closest('.scroll').hidden = joints.length === 0;
  select.disabled = joints.length === 0;
  const joint = joints.find((j) => j.id === picked);
  const mass = `${fmt(joint?.model_mass)} ${joint?.angular ? 'kg m²' : 'kg'} of effective mass from its bodies`;
  const mode = doc.modal_tuning?.targets?.[0]?.mode;
  $('joint-note').textContent = joints.length === 0
    ? 'This scene has no designer-tuned joint: the tuning changes only its step (fps, substeps); the numbers tune the body below.'
    : mode
      ? `The sliders tune the ${mode}: softtune solves the joints' k and c so that this mode has the asked frequency and damping (the table below lists them). The numbers describe ${picked} alone, on its own ${mass}.`
      : `The numbers describe ${picked}: ${mass}. Every joint listed takes this tuning.`;
  if (first) {
    // The first joint is the preset's default: a link names a joint only when it picks another.
    urlDefaults = { ...urlDefaults, joint: joints[0]?.id ?? '' };
    syncControls();
    if (picked !== state.joint) updateUrl(true, true);
  }
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
    if (box2dPreset(state)) presetJoints = [];
    return;
  }
  const generation = generations.current;
  try {
    const doc = await tracked(channels.simulate.run((signal) => callJson('POST', 'api/v1/simulate', withSceneEngine(simulateRequest(state, tune), state), signal)));
    if (doc === Latest.stale || !generations.belongs(generation)) return;
    if (box2dPreset(state)) showPresetJoints(state, doc);
    showSceneEngineValues($('engine-values'), doc, state.joint);
    typedPanel.show(box2dPreset(state) ? presetScene : null, doc);
    const modal = showModalTargets($('modal-targets'), $('modal-note'), doc.modal_tuning);
    $('modal-group').hidden = !modal;
    $('joints-caption').textContent = modal ? "The scene's tuned joints: k and c solved for the mode"
      : "The scene's tuned joints: each takes this tuning on the effective mass its bodies give it";
    lastSolved = modal && box2dPreset(state) ? { preset: state.preset, doc } : null;
    if (modal) {
      showModalSummary($('summary'), doc.modal_tuning, chosenVerdict(tune));
      const t = doc.modal_tuning.targets?.[0];
      clearPending($('summary'));
      showOffBy($('summary'), t?.requested, t?.measured);
      showSolvedJoint(solvedFor(readForm(form)));
    }
    refreshModes(state, doc);
    lanes = box2dPreset(state) ? oscillatorLanes(doc.probes) : [];
    $('lanes-figure').hidden = lanes.length === 0;
    note.textContent = doc.stages ? `Stages run: ${doc.stages.join(', ')}` : '';
    figure.hidden = false;
    drawSimulation($('plot-simulation'), doc.probes ?? [], probeUnit);
    placeCursors();
    showProbes(body, doc.probes ?? []);
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    if (!generations.belongs(generation)) return;
    clearPending($('summary'));
    if (box2dPreset(state) && presetJoints === null) presetJoints = [];
    $('modal-group').hidden = true;
    body.replaceChildren();
    table.hidden = e.unavailable;
    note.textContent = e.unavailable ? unavailable('Simulation') : `Simulation refused: ${designerMessage(e.message, e.field)}`;
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
    const generation = generations.current;
    const doc = await tracked(channels.accuracy.run((signal) => callJson('POST', 'api/v1/accuracy', request, signal)));
    if (doc === Latest.stale || !generations.belongs(generation)) return;
    drawWorkPrecision(el, doc.rows ?? []);
    note.textContent = `Recommendation: ${describe(doc.recommendation)}`;
  } catch (e) {
    if (!(e instanceof ApiError)) throw e;
    showUnavailable(el, e.unavailable ? unavailable('The work-precision chart (POST /api/v1/accuracy)')
      : `Accuracy run refused: ${designerMessage(e.message, e.field)}`);
    note.textContent = '';
  }
}

let lastPreview = '';  // the request of the preview shown or on its way

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
  const request = withSceneEngine(previewRequest(state, tune, presetScene), state);
  const text = JSON.stringify(request);
  // Asked already for this input (a preset's preview starts with the change, then the tune answer asks).
  const generation = generations.current;
  if (`${generation} ${text}` === lastPreview) return;
  lastPreview = `${generation} ${text}`;
  player.supersede();  // the frames of the preview this one replaces stop loading
  $('preview').dataset.request = text;  // what this preview shows, for tests and tools
  try {
    const doc = await tracked(channels.preview.run(async (signal) => {
      player.rendering(null);
      const first = await callJson('POST', 'api/v1/preview', request, signal);
      // "From the cache" only when the first answer already had every frame from it.
      const fromCache = first.cached === true && Array.isArray(first.frames);
      let answer = first;
      let shownFirst = false;
      // A preview still rendering answers with its id and progress: ask again until the frames are listed,
      // showing frame 0 as soon as it is encoded (frames stream).
      while (!Array.isArray(answer.frames) && answer.id) {
        if (answer.status === 'failed') throw new ApiError(500, { detail: 'the preview failed to render' });
        player.rendering(answer.progress ?? answer);
        if (!shownFirst && answer.progress?.ready >= 1 && answer.progress_url && generations.belongs(generation)) {
          player.first(`${answer.progress_url}/0.png`);
          shownFirst = true;
        }
        await new Promise((r) => setTimeout(r, 20));  // a progress poll is a small answer from memory
        if (signal.aborted) throw new DOMException('aborted', 'AbortError');
        answer = await callJson('GET', `api/v1/preview/${encodeURIComponent(answer.id)}`, undefined, signal);
      }
      return { ...answer, fromCache, frameSeconds: first.frame_dt_s, warnings: first.warnings ?? [] };
    }));
    if (doc === Latest.stale || !generations.belongs(generation)) return;
    player.load(doc.frames ?? [], doc.filmstrip, doc.frameSeconds);
    const n = doc.frames?.length ?? 0;
    const seconds = doc.frameSeconds > 0 ? `, ${fmt(Math.round((n - 1) * doc.frameSeconds * 100) / 100)} s of ${state.preset || 'oscillator'} played in real time` : '';
    const ms = doc.timings?.wall_ms;
    const rendered = doc.fromCache ? ' (from the cache)' : ms !== undefined && ms !== null ? `, rendered in ${fmt(Math.round(ms))} ms` : '';
    note.textContent = `${n} frames${seconds}${rendered}`;
  } catch (e) {
    lastPreview = '';
    if (!(e instanceof ApiError)) throw e;
    player.clear();
    panel.hidden = e.unavailable;
    note.textContent = e.unavailable ? unavailable('The rendered preview') : `Preview refused: ${designerMessage(e.message, e.field)}`;
  }
}

// ---- presets --------------------------------------------------------------------------------------

/// Loads a preset's scene; `adopt` copies its step and tuning into the controls (a user's pick), while a
/// link or a history step keeps the controls it holds. Either way the numbers, simulation and preview
/// then run on that preset.
async function loadPreset(name, adopt) {
  generations.accept();
  presetScene = null;
  presetJoints = null;
  urlDefaults = DEFAULTS;
  $('preset-note').textContent = '';
  $('preset-details').hidden = true;
  // The last preset's joints are not this one's: a pick of this preset never carries one of them.
  if (adopt) $('joint').replaceChildren(new Option('', ''));
  $('joints').querySelector('tbody').replaceChildren();
  $('modes-panel')?.replaceChildren();
  if (name) {
    const { scene, note } = await tracked(fetchPresetScene(name));
    if ($('preset').value !== name) return;
    presetScene = scene;
    if (scene) loadModes(name);
    $('preset-note').textContent = scene ? presetWords(name, scene.description ?? '') : note;
    $('preset-tech').textContent = scene?.description ?? '';
    $('preset-details').hidden = !scene?.description;
    if (scene) urlDefaults = { ...DEFAULTS, ...stateFromScene(scene, words) };
    writeForm(form, adopt ? { ...urlDefaults, preset: name } : fromQuery(location.search, urlDefaults, words));
    if (scene && !isBox2dScene(scene)) presetJoints = [];
  } else if (!adopt) {
    writeForm(form, fromQuery(location.search, DEFAULTS, words));
  }
  syncControls();
  if (adopt) updateUrl(true);
  scheduleTune();
}

let lastSolved = null;  // {preset, doc}: the last simulation of a modally tuned preset

/// The picked joint's solved answer from the last simulation of this preset, or null (not modally tuned).
function solvedFor(state) {
  return box2dPreset(state) && lastSolved?.preset === state.preset ? solvedAnswer(lastSolved.doc, state.joint) : null;
}

/// A modally tuned preset: the picked joint's solved answer (server: joint_answer_codec.h) is what the Numbers,
/// the engine table, the Copy snippet and a pinned A show, so they say the k, c the preview ran.
function showSolvedJoint(answer) {
  if (!answer) return;
  window.softtune = { ...window.softtune, tune: answer };
  showNumbers(results, answer);
  comparison.showNumbers();
  showEngines(results, answer);
}

/// The modes list follows every answer: a modal tuning's solved modes, else the modes of the scene as tuned now.
function refreshModes(state, doc) {
  const listing = modesOfAnswer(doc);
  if (listing) showModes($('modes-panel'), listing, $('target').value);
  else if (box2dPreset(state)) loadModes(state.preset, withSceneEngine(simulateRequest(state, null), state));
}

/// The preset's modes (modes.js): radios of the `target` control; picking one makes the sliders tune it.
async function loadModes(name, request = { preset: name }) {
  const panel = $('modes-panel');
  if (!panel) return;
  if (!presetScene?.bodies?.length || !hasRoute('POST', '/api/v1/modes')) return panel.replaceChildren();
  try {
    const answer = await tracked(channels.modes.run((signal) => callJson('POST', 'api/v1/modes', request, signal)));
    if (answer === Latest.stale) return;
    if ($('preset').value !== name) return;
    showModes(panel, answer, $('target').value);
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
$('export').addEventListener('click', () => {
  const state = readForm(form);
  download(simulateRequest(state, window.softtune?.tune ?? {}), exportName(state));
});
$('import').addEventListener('change', async (e) => {
  const file = e.target.files?.[0];
  e.stopPropagation();
  if (!file) return;
  try {
    const next = stateFromDocument(JSON.parse(await file.text()), words);
    // The URL holds what differs from the preset's own tuning, so that scene is read first.
    let defaults = DEFAULTS;
    if (next.preset) {
      const { scene } = await fetchPresetScene(next.preset);
      if (scene) defaults = { ...DEFAULTS, ...stateFromScene(scene, words) };
    }
    const query = toQuery({ ...defaults, ...next }, defaults);
    history.pushState(null, '', query ? `?${query}` : location.pathname);
    $('form-error').textContent = '';
    await restoreFromUrl();
  } catch (err) {
    $('form-error').textContent = `Import refused: ${err.message}`;
  }
  e.target.value = '';
});

/// The controls of the address bar's query (a history step, an import).
async function restoreFromUrl() {
  generations.accept();
  const before = $('preset').value;
  const named = fromQuery(location.search, DEFAULTS, words).preset;
  entryOpen = false;
  if (named !== before) {
    $('preset').value = named;
    await loadPreset(named, false);
  } else {
    writeForm(form, fromQuery(location.search, urlDefaults, words));
    syncControls();
    scheduleTune();
  }
}
window.addEventListener('popstate', restoreFromUrl);

busy(0);
await loadRoutes();
words = oscillationWords();
writeForm(form, fromQuery(location.search, DEFAULTS, words));
try {
  await installSceneEngines($('engine'), $('engine-group'));  // keeps a link's engine (writeForm left it pending)
} catch {
  $('engine-group').hidden = true;  // no list: the server's default engine runs every scene
}
syncControls();
installIdentify(form, { request: () => tuneRequest(readForm(form)), engines: () => Object.keys(window.softtune?.tune?.engines ?? {}),
  redraw: () => scheduleTune() });
const listNote = await tracked(fillPresetList($('preset')));
if (listNote) {
  $('preset-note').textContent = listNote;
  $('preset').disabled = true;
}
const select = $('preset');
if (select.dataset.pending) {
  select.value = select.dataset.pending;
  delete select.dataset.pending;
}
// A link that names a preset previews and simulates that preset with the link's tuning, from the start.
if (select.value) await loadPreset(select.value, false);
else runTune();
