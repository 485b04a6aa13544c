// The designer page end to end in real headless Chromium against a real `softtune serve`: the numbers
// shown equal the API's, moving the frames slider and the oscillation choice updates numbers, plots and
// preview, the engine table shows each engine's prediction and copies its code, a shared URL restores the
// tuning, an API error shows next to its field, no console errors, and
// screenshots at 1280x800 and on a narrow window.
//
// Run (ctest does this as web.e2e): SOFTTUNE_BIN=build/softtune SOFTTUNE_WEB=web \
//   SOFTTUNE_SCREENSHOT_DIR=build node --test tests/web/page.e2e.mjs
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const softtune = path.resolve(process.env.SOFTTUNE_BIN ?? path.join(root, 'build/softtune'));
const webDir = path.resolve(process.env.SOFTTUNE_WEB ?? path.join(root, 'web'));
const shotDir = path.resolve(process.env.SOFTTUNE_SCREENSHOT_DIR ?? path.join(root, 'build'));
const chromiumPath = process.env.CHROMIUM ?? '/usr/bin/chromium';

let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch {
  throw new Error('playwright-core is not installed: run scripts/setup.sh (npm ci) first');
}
assert.ok(existsSync(path.join(webDir, 'vendor/uPlot.iife.min.js')),
  'web/vendor/uPlot.iife.min.js is missing: run scripts/setup.sh and build (the build copies it from node_modules)');

let server, base, browser;
const consoleErrors = [];

function startServer() {
  return new Promise((resolve, reject) => {
    // From the source root, so the server finds presets/ by its default (or $SOFTTUNE_PRESETS) too.
    const child = spawn(softtune, ['serve', '--port', '0', '--web', webDir], { cwd: root, stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    const timer = setTimeout(() => reject(new Error(`softtune serve printed no URL: ${out}`)), 10000);
    child.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/http:\/\/[^\s]+\//);
      if (m) {
        clearTimeout(timer);
        resolve({ child, url: m[0] });
      }
    });
    child.stderr.resume();  // the request log
    child.on('exit', (code) => reject(new Error(`softtune serve exited with ${code}: ${out}`)));
  });
}

async function waitHealthy(url) {
  for (let i = 0; i < 100; ++i) {
    try {
      const r = await fetch(`${url}api/v1/health`);
      if (r.ok && (await r.json()).status === 'ok') return;
    } catch { /* not listening yet */ }
    await new Promise((r) => setTimeout(r, 100));
  }
  throw new Error('/api/v1/health never answered ok');
}

const killServer = () => { if (server && server.exitCode === null) server.kill('SIGKILL'); };
process.on('exit', killServer);

before(async () => {
  const started = await startServer();
  server = started.child;
  base = started.url;
  await waitHealthy(base);
  const args = process.getuid?.() === 0 ? ['--no-sandbox'] : [];
  browser = await chromium.launch({ executablePath: chromiumPath, args });
});

after(async () => {
  await browser?.close();
  if (server && server.exitCode === null) {
    server.kill('SIGTERM');
    await new Promise((r) => { const t = setTimeout(() => { killServer(); r(); }, 3000); server.on('exit', () => { clearTimeout(t); r(); }); });
  }
});

async function api(method, route, body) {
  const r = await fetch(base + route, { method, headers: body ? { 'Content-Type': 'application/json' } : {},
    body: body ? JSON.stringify(body) : undefined });
  return { status: r.status, doc: await r.json().catch(() => null) };
}

async function routes() {
  const { doc } = await api('GET', 'api/v1/openapi.json');
  return new Set(Object.entries(doc.paths).flatMap(([p, ops]) => Object.keys(ops).map((m) => `${m.toUpperCase()} ${p}`)));
}

async function openPage(url, viewport = { width: 1280, height: 800 }) {
  const page = await browser.newPage({ viewport, permissions: ['clipboard-read', 'clipboard-write'] });
  page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(`${m.text()} @ ${m.location().url}`); });
  page.on('pageerror', (e) => consoleErrors.push(String(e)));
  await page.goto(url);
  await settled(page);
  return page;
}

/// Waits until the page has nothing scheduled or in flight (the debounce counts) and shows numbers.
async function settled(page) {
  await page.waitForFunction(() => document.body.dataset.pending === '0' &&
    document.querySelector('[data-testid="k"]').textContent !== '' &&
    !document.getElementById('results').classList.contains('stale'), null, { timeout: 30000 });
}

const SHOWN = { 'effective-mass': 'effective_mass', k: 'k', c: 'c', gamma: 'gamma', beta: 'beta', erp: 'erp', cfm: 'cfm' };

/// Every shown value equals the API's answer for `request`: the full-precision value exactly, the text to
/// its six significant digits.
async function expectNumbers(page, request) {
  const { status, doc } = await api('POST', 'api/v1/tune', request);
  assert.equal(status, 200);
  const expected = { ...Object.fromEntries(Object.entries(SHOWN).map(([id, key]) => [id, doc[key]])),
    'achieved-frequency': doc.achieved.frequency_hz, 'achieved-damping': doc.achieved.damping_ratio };
  for (const [id, want] of Object.entries(expected)) {
    const el = page.getByTestId(id);
    const value = await el.getAttribute('data-value');
    const text = await el.textContent();
    if (want === null) {
      assert.equal(value, '', `${id} should be undefined`);
      continue;
    }
    assert.equal(Number(value), want, `${id}: page ${value}, API ${want}`);
    assert.ok(Math.abs(Number(text) - want) <= 5e-6 * Math.abs(want), `${id} text "${text}" against ${want}`);
  }
  return doc;
}

const canvas = (page, id) => page.getByTestId(id).locator('canvas').evaluate((c) => c.toDataURL());

test('the page shows the API numbers, follows the controls, restores a shared URL and reports errors by field', async () => {
  const served = await routes();
  const page = await openPage(base);

  // Default state: 12 frames, some oscillation, 1 kg, 60 fps, standard.
  const defaults = { fps: 60, substeps: 1, response_frames: 12, basis_fps: 60, mode: 'standard', oscillation: 'some', effective_mass: 1 };
  let tune = await expectNumbers(page, defaults);
  assert.equal(await page.getByTestId('requested-frequency').getAttribute('data-value'), String(tune.requested.frequency_hz));
  assert.equal(await page.locator('#stability tbody tr').count(), 5, 'a verdict per integrator');
  assert.ok(await page.locator('#engines tr.engine').count() >= 7, 'the engine export table');
  for (const id of ['plot-response', 'plot-error']) {
    assert.ok(Number(await page.getByTestId(id).getAttribute('data-points')) > 10, `${id} has data`);
  }
  // Every control has a label (or an aria-label) a screen reader and a click can use.
  const unlabelled = await page.locator('input, select, button').evaluateAll((els) =>
    els.filter((e) => !(e.labels?.length || e.getAttribute('aria-label') || (e.tagName === 'BUTTON' && e.textContent.trim())))
      .map((e) => e.name || e.id || e.outerHTML));
  assert.deepEqual(unlabelled, []);
  // The response plot: the exact motion and the five methods.
  assert.equal(await page.getByTestId('plot-response').locator('.u-legend .u-series').count(), 7);

  // The engine table: a row per engine the answer carries; Box2D 2.4's row shows what its model predicts.
  for (const key of Object.keys(tune.engines).filter((k) => tune.engines[k].parameters && k !== 'ode_bullet')) {
    assert.equal(await page.locator(`#engines tr.engine[data-engine="${key}"]`).count(), 1, `a row for ${key}`);
  }
  const box2d = page.locator('#engines tr.engine[data-engine="box2d_v2_4"]');
  const b2 = tune.engines.box2d_v2_4;
  assert.equal(Number(await box2d.getByTestId('predicted-frequency').getAttribute('data-value')), b2.predicted.frequency_hz);
  assert.equal(Number(await box2d.getByTestId('exact-frequency').getAttribute('data-value')), b2.exact_predicted.frequency_hz);
  // Its copy button puts Box2D code with the answer's values, at full precision, on the clipboard: the exact
  // values first, softtune's plain stiffness and damping on the toggle; the code shown is the code copied.
  const copy = async () => {
    await box2d.locator('button').click();
    return page.evaluate(() => navigator.clipboard.readText());
  };
  let copied = await copy();
  assert.ok(copied.includes(`jd.stiffness = ${b2.exact['b2DistanceJointDef::stiffness']}f;`), copied);
  await page.getByLabel(/plain values/).check();
  copied = await copy();
  assert.ok(copied.includes('b2DistanceJointDef jd;'), copied);
  assert.ok(copied.includes(`jd.stiffness = ${b2.stiffness}f;`), copied);
  assert.ok(copied.includes(`jd.damping = ${b2.damping}f;`), copied);
  assert.equal(await page.locator('#engines tr.snippet[data-engine="box2d_v2_4"] pre').textContent(), copied);
  for (const text of await page.locator('#engines pre').allTextContents()) assert.doesNotMatch(text, /NaN|undefined/, text);
  await page.getByLabel(/exact values/).check();

  const responseBefore = await canvas(page, 'plot-response');
  const errorBefore = await canvas(page, 'plot-error');
  const previewBefore = await page.getByTestId('preview').getAttribute('src');

  // Move the frames slider with the keyboard (12 -> 24 frames).
  await page.locator('#frames').focus();
  for (let i = 0; i < 12; ++i) await page.keyboard.press('ArrowRight');
  await settled(page);
  tune = await expectNumbers(page, { ...defaults, response_frames: 24 });
  assert.equal(tune.frequency_hz, 2.5);
  assert.match(page.url(), /frames=24/);

  // The oscillation choice: none (critical damping) moves the fine slider to 1.
  await page.getByLabel('none', { exact: true }).check();
  await settled(page);
  tune = await expectNumbers(page, { ...defaults, response_frames: 24, oscillation: 'none' });
  assert.equal(await page.locator('#zeta').inputValue(), '1');
  assert.match(page.url(), /osc=none/);
  assert.notEqual(await canvas(page, 'plot-response'), responseBefore, 'the response plot redrew');
  assert.notEqual(await canvas(page, 'plot-error'), errorBefore, 'the error plot redrew');

  if (served.has('POST /api/v1/preview')) {
    await page.waitForFunction(() => document.querySelector('[data-testid="preview"]').naturalWidth > 0, null, { timeout: 30000 });
    assert.notEqual(await page.getByTestId('preview').getAttribute('src'), previewBefore, 'the preview re-rendered');
  } else {
    assert.match(await page.locator('#preview-note').textContent(), /not available on this server/);
  }
  if (served.has('POST /api/v1/accuracy')) {
    assert.ok(Number(await page.getByTestId('plot-work-precision').getAttribute('data-points')) > 0);
  } else {
    assert.match(await page.getByTestId('plot-work-precision').textContent(), /not available on this server/);
  }
  if (!served.has('POST /api/v1/simulate')) {
    assert.match(await page.locator('#simulate-note').textContent(), /not available on this server/);
  }

  // Fine damping ratio and exact mode, then share the link.
  await page.locator('#zeta').fill('0.25');
  await page.getByLabel('exact', { exact: true }).check();
  await page.locator('#fps').fill('30');
  await settled(page);
  const shared = { ...defaults, response_frames: 24, damping_ratio: 0.25, mode: 'exact', fps: 30 };
  delete shared.oscillation;
  await expectNumbers(page, shared);
  await page.screenshot({ path: path.join(shotDir, 'web-screenshot.png') });
  // From the top, so the sticky controls sit where a reader first sees them.
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: path.join(shotDir, 'web-screenshot-full.png'), fullPage: true });
  const link = page.url();
  await page.close();

  const reloaded = await openPage(link);
  assert.equal(await reloaded.locator('#frames').inputValue(), '24');
  assert.equal(await reloaded.locator('#zeta').inputValue(), '0.25');
  assert.equal(await reloaded.getByLabel('exact', { exact: true }).isChecked(), true);
  assert.equal(await reloaded.getByLabel('none', { exact: true }).isChecked(), false);
  await expectNumbers(reloaded, shared);

  // The suggested fix works: explicit Euler is unstable at 30 fps (h > 2 zeta / omega); taking the
  // substeps it names makes it stable.
  const explicit = reloaded.locator('#stability tr[data-method="explicit_euler"]');
  assert.equal(await explicit.locator('td').nth(0).textContent(), 'unstable');
  const fix = await explicit.getByTestId('fix').textContent();
  const needed = Number(fix.match(/needs (\d+) substeps/)?.[1]);
  assert.ok(needed > 1, `fix "${fix}" names a substep count`);
  await reloaded.locator('#substeps').fill(String(needed));
  await settled(reloaded);
  await expectNumbers(reloaded, { ...shared, substeps: needed });
  assert.equal(await explicit.locator('td').nth(0).textContent(), 'stable');

  // An API error appears next to the field it names. Chromium logs the refused request itself (a 422 of
  // api/v1/tune); that one is expected, every other console error fails the test.
  const errorsBefore = consoleErrors.length;
  await reloaded.locator('#mass').fill('-2');
  await reloaded.waitForFunction(() => document.querySelector('[data-field="effective_mass"] .error').textContent !== '', null, { timeout: 10000 });
  const message = await reloaded.locator('[data-field="effective_mass"] .error').textContent();
  const { status, doc } = await api('POST', 'api/v1/tune', { ...shared, effective_mass: -2 });
  assert.equal(status, 422);
  assert.equal(doc.field, 'effective_mass');
  assert.equal(message, doc.detail);
  // The long status message must not squeeze the results column (1280 - 360 px of controls - margins).
  const resultsWidth = await reloaded.evaluate(() => document.getElementById('results').getBoundingClientRect().width);
  assert.ok(resultsWidth > 800, `results column ${resultsWidth} px wide`);
  const logged = consoleErrors.splice(errorsBefore);
  assert.ok(logged.every((m) => /status of 422 .*api\/v1\/tune$/.test(m)), logged.join('\n'));
  await reloaded.close();

  // A 2-D constraint and a narrow window.
  const narrow = await openPage(`${base}?body=constraint`, { width: 420, height: 900 });
  const constraintTune = await expectNumbers(narrow, {
    fps: 60, substeps: 1, response_frames: 12, basis_fps: 60, mode: 'standard', oscillation: 'some',
    constraint: { dimension: 2, type: 'linear', body_a: 'static', body_b: { mass: 2, inertia: 0.5, position: [1, 0], angle: 0 },
      anchor_a: [0, 0], anchor_b: [1, 0.5], axis: [1, 0] },
  });
  // Anchor B sits 0.5 m off body B's centre across the axis: rotation lowers the effective mass below 2 kg.
  assert.ok(constraintTune.effective_mass < 2 && constraintTune.effective_mass > 0);
  await narrow.screenshot({ path: path.join(shotDir, 'web-screenshot-narrow.png'), fullPage: true });
  const overflow = await narrow.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflow <= 0, `the narrow page scrolls sideways by ${overflow} px`);
  await narrow.close();

  assert.deepEqual(consoleErrors, [], 'no console errors');
});

test('picking a preset fills the controls from its scene and simulates it', async (t) => {
  const served = await routes();
  if (!served.has('GET /api/v1/presets') || !served.has('GET /api/v1/presets/{name}')) {
    t.skip('this server has no presets routes');
    return;
  }
  const { doc: index } = await api('GET', 'api/v1/presets');
  if (!index.presets.some((p) => p.name === 'oscillator')) {
    t.skip('no oscillator preset in this server\'s presets folder');
    return;
  }
  const { doc: scene } = await api('GET', 'api/v1/presets/oscillator');
  const page = await openPage(base);
  assert.equal(await page.locator('#preset option').count(), index.presets.length + 1);
  await page.locator('#preset').selectOption('oscillator');
  await page.waitForFunction(() => new URLSearchParams(location.search).get('preset') === 'oscillator');
  await settled(page);
  const first = scene.oscillators[0];
  assert.equal(await page.locator('#frames').inputValue(), String(first.response_frames));
  await expectNumbers(page, { fps: scene.world.fps, substeps: scene.world.substeps ?? 1, response_frames: first.response_frames,
    basis_fps: first.basis_fps ?? 60, mode: first.mode ?? 'standard', oscillation: first.oscillation, effective_mass: first.effective_mass });
  if (served.has('POST /api/v1/simulate')) {
    assert.equal(await page.locator('#probes tbody tr').count(), scene.probes.length);
    assert.ok(Number(await page.getByTestId('plot-simulation').getAttribute('data-points')) > 10);
  }
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: path.join(shotDir, 'web-screenshot-preset.png'), fullPage: true });
  await page.close();
  assert.deepEqual(consoleErrors, [], 'no console errors');
});
