// The engine a scene runs in (docs/page.md, "Scene engine"): a select listing the scene engines this server
// has (GET /api/v1/scene-engines, Box2D 2.4 first and the default), whose value goes as `engine` with every
// scene request (simulate, modes, preview), so the numbers, the modes and the frames come from that engine's
// run. Its name is `engine`, so the URL keeps the pick like every other control.
import { callJson, hasRoute } from './api.js';
import { copyText } from './results.js';

export const DEFAULT_SCENE_ENGINE = 'box2d_v2_4';

/// `request` with the picked engine (state.engine) as its `engine`; unchanged when none is picked (a server
/// without the route, or before the list loads: the server's default runs).
export function withSceneEngine(request, state) {
  const engine = state?.engine;
  return engine ? { ...request, engine } : request;
}

/// The option label of one engine of the index: its name and the version it runs.
export function sceneEngineLabel(engine) {
  return engine.version ? `${engine.name} (${engine.version})` : engine.name;
}

/// Fills `select` from the server's engine index and keeps a pending pick (a link's engine=...); hides the
/// field (`group`) when the server has no such route. Returns the engines listed.
export async function installSceneEngines(select, group, fetchJson = callJson) {
  if (!hasRoute('GET', '/api/v1/scene-engines')) {
    if (group) group.hidden = true;
    return [];
  }
  const index = await fetchJson('GET', 'api/v1/scene-engines');
  const engines = index?.engines ?? [];
  const wanted = select.dataset.pending || select.value || DEFAULT_SCENE_ENGINE;
  select.replaceChildren(...engines.map((e) => {
    const option = document.createElement('option');
    option.value = e.name;
    option.textContent = sceneEngineLabel(e);
    return option;
  }));
  select.value = engines.some((e) => e.name === wanted) ? wanted : (engines.find((e) => e.default)?.name ?? DEFAULT_SCENE_ENGINE);
  delete select.dataset.pending;
  if (group) group.hidden = engines.length === 0;
  return engines;
}

/// What to type for the joint `jointId` (or the first joint with a spring) in the engine that ran a simulate
/// answer: {engine, joint, values} from the joint's `parameters`, or null when no joint has one.
export function sceneJointValues(doc, jointId) {
  const joints = (doc?.joints ?? []).filter((j) => j.parameters?.values);
  const j = joints.find((x) => x.id === jointId) ?? joints[0];
  return j ? { engine: j.parameters.engine, joint: j.id, values: j.parameters.values } : null;
}

/// The text Copy puts on the clipboard: the values under the engine's own field names, one per line.
export function sceneValuesText(v) {
  return Object.entries(v.values).map(([name, value]) => `${name} = ${value}`).join('\n');
}

/// Shows, under the engine picker, the picked joint's values in the engine that ran, with a Copy button
/// that copies exactly them; empty when the answer has none.
export function showSceneEngineValues(container, doc, jointId) {
  if (!container) return;
  const v = sceneJointValues(doc, jointId);
  if (!v) {
    container.replaceChildren();
    return;
  }
  const caption = document.createElement('small');
  caption.className = 'note';
  caption.textContent = `What to type in ${v.engine} for ${v.joint}:`;
  const pre = document.createElement('pre');
  pre.dataset.testid = 'engine-values';
  pre.textContent = sceneValuesText(v);
  const button = document.createElement('button');
  button.type = 'button';
  button.textContent = 'Copy';
  button.setAttribute('aria-label', `Copy the ${v.engine} values of ${v.joint}`);
  button.addEventListener('click', async () => {
    button.textContent = (await copyText(pre.textContent)) ? 'Copied' : 'Copy failed';
    setTimeout(() => { button.textContent = 'Copy'; }, 1500);
  });
  container.replaceChildren(caption, pre, button);
}
