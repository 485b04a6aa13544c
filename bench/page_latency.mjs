// Page latency, as a designer feels it: in real headless Chromium against a fresh `softtune serve` (cold
// caches: every change asks a tuning never asked before), the time from a slider change to the live curve
// beside the slider redrawn (web/live_curve.js, no server) and painted, to the new numbers on the page, and
// to the first frame of the new preview on screen, p50 and p95 over N changes, on a Box2D preset (vehicle)
// and on the oscillator (a custom body). The baseline, measured in the same run against the same server:
// the bare POST /api/v1/tune round trip from Node for the same tunings.
// Aim (issues 16, 35): live curve within 16 ms of the input event, numbers within 100 ms p95 of the change,
// first preview frame within 300 ms p95, on an idle machine.
//
// Run by hand (not in ctest: it takes about a minute):
//   node bench/page_latency.mjs [--changes 30] [--bin build/softtune]
// Prints a Markdown table (docs/benchmarks.md, "Page latency").
import { spawn } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const CHANGES = Number(arg('changes', 30));
const BIN = path.resolve(arg('bin', path.join(root, 'build/softtune')));

function startServer() {
  return new Promise((resolve, reject) => {
    const child = spawn(BIN, ['serve', '--port', '0', '--web', path.join(root, 'web')], { cwd: root, stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    child.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/http:\/\/[^\s]+\//);
      if (m) resolve({ child, url: m[0] });
    });
    child.stderr.resume();
    child.on('exit', (code) => reject(new Error(`softtune serve exited with ${code}: ${out}`)));
  });
}

const quantile = (xs, q) => {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.max(0, Math.ceil(q * s.length) - 1))];
};

/// Installs the page-side clock: the time each new tune answer reaches the numbers, and each new
/// preview's first frame reaches the screen (an <img> load of a preview id not seen before).
async function instrument(page) {
  await page.evaluate(() => {
    performance.setResourceTimingBufferSize(100000);
    window.__lat = { numbers: [], frames: [], live: [] };
    const curve = document.querySelector('[data-testid="live-curve"]');
    new MutationObserver(() => window.__lat.live.push({ t: performance.now(), source: curve.dataset.source }))
      .observe(curve, { attributes: true, attributeFilter: ['data-drawn'] });
    const k = document.querySelector('[data-testid="k"]');
    new MutationObserver(() => window.__lat.numbers.push({ t: performance.now(), k: k.dataset.value })).observe(k, { attributes: true, attributeFilter: ['data-value'] });
    const img = document.querySelector('[data-testid="preview"]');
    const seen = new Set([img.src.split('/').at(-2)]);
    img.addEventListener('load', () => {
      const id = img.src.split('/').at(-2);
      if (!seen.has(id)) {
        seen.add(id);
        window.__lat.frames.push({ t: performance.now(), id });
      }
    });
  });
}

/// One slider change to `frames`; resolves with [ms to numbers, ms to the first preview frame].
async function change(page, frames) {
  const t0 = await page.evaluate((v) => {
    window.__lat.numbers.length = 0;
    window.__lat.frames.length = 0;
    window.__lat.live.length = 0;
    const el = document.getElementById('frames');
    el.value = String(v);
    const t = performance.now();
    el.dispatchEvent(new Event('input', { bubbles: true }));
    // The input event's handlers have run (the live curve drew in them): the next frame paints it.
    window.__lat.inputDone = performance.now();
    requestAnimationFrame(() => { window.__lat.painted = performance.now(); });
    el.dispatchEvent(new Event('change', { bubbles: true }));
    return t;
  }, frames);
  await page.waitForFunction(() => window.__lat.numbers.length > 0 && window.__lat.frames.length > 0, null, { timeout: 60000 });
  // Let the rest of this preview render so the next change starts from an idle server.
  await page.waitForFunction(() => document.body.dataset.pending === '0' && document.getElementById('preview-progress').hidden, null, { timeout: 60000 });
  return page.evaluate((start) => {
    // Where the time goes: the tune request's own start and end in the browser (resource timing).
    const entries = performance.getEntriesByType('resource').filter((e) => e.startTime >= start);
    const tune = entries.find((e) => e.name.endsWith('/api/v1/tune'));
    const preview = entries.find((e) => e.name.endsWith('/api/v1/preview'));
    const id = window.__lat.frames[0].id;
    const frame = entries.find((e) => e.name.includes(`/api/v1/preview/${id}/`) && e.name.endsWith('.png'));
    const at = (e, key) => (e ? e[key] - start : NaN);
    const live = window.__lat.live.find((e) => e.source === 'input');
    return [window.__lat.numbers[0].t - start, window.__lat.frames[0].t - start, at(tune, 'startTime'), at(tune, 'responseEnd'),
      at(preview, 'startTime'), at(preview, 'responseEnd'), at(frame, 'startTime'), at(frame, 'responseEnd'),
      live ? window.__lat.inputDone - start : NaN, window.__lat.painted - start];
  }, t0);
}

async function bareTune(base, request) {
  const t0 = performance.now();
  const r = await fetch(`${base}api/v1/tune`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(request) });
  await r.json();
  return performance.now() - t0;
}

const { child, url: base } = await startServer();
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', args: process.getuid?.() === 0 ? ['--no-sandbox'] : [] });
const rows = [];
try {
  // The vehicle's heave goes up to 100 frames (0.6 Hz): softer, the chassis would rest on the road, and the
  // page says the request is softer than the scene's travel allows instead of previewing (docs/scenes.md).
  const scenes = [['vehicle (Box2D preset)', '?preset=vehicle', 11.353175820803868, 100], ['oscillator (custom body, 1 kg)', '', 1, 120]];
  for (const [label, query, mass, most] of scenes) {
    const page = await browser.newPage({ viewport: { width: 1440, height: 900 } });
    await page.goto(base + query);
    await page.waitForFunction(() => document.body.dataset.pending === '0' && document.querySelector('[data-testid="k"]').textContent !== ''
      && document.querySelector('[data-testid="preview"]').naturalWidth > 0, null, { timeout: 60000 });
    await instrument(page);
    const numbers = [], frames = [], bare = [], sends = [], answers = [], posts = [], posted = [], pngs = [], pnged = [], lives = [], paints = [];
    // Frames 5..most in a scrambled order: each change a tuning this server has not seen (cold caches).
    const start = Number(await page.locator('#frames').inputValue());
    const mode = await page.locator('input[name="mode"]:checked').getAttribute('value');  // the vehicle's own: exact
    const values = Array.from({ length: CHANGES + 1 }, (_, i) => 5 + ((i * 37) % (most - 4))).filter((v) => v !== start).slice(0, CHANGES);
    for (const v of values) {
      const [n, f, sent, answered, post, postEnd, png, pngEnd, live, painted] = await change(page, v);
      lives.push(live);
      paints.push(painted);
      numbers.push(n);
      frames.push(f);
      sends.push(sent);
      answers.push(answered);
      posts.push(post);
      posted.push(postEnd);
      pngs.push(png);
      pnged.push(pngEnd);
      // The same tuning's bare round trip, on a mass the page never sent (so the response cache is cold).
      bare.push(await bareTune(base, { fps: 60, substeps: 1, response_frames: v, basis_fps: 60, oscillation: 'some', mode, effective_mass: mass * 1.001 }));
    }
    rows.push({ label, numbers, frames, bare, sends, answers, posts, posted, pngs, pnged, lives, paints });
    await page.close();
  }
} finally {
  await browser.close();
  child.kill('SIGTERM');
}

const ms = (x) => `${x.toFixed(0)} ms`;
console.log(`Page latency, ${CHANGES} changes each, cold server caches (${new Date().toISOString()})\n`);
const ms1 = (x) => `${x.toFixed(1)} ms`;
console.log('| scene | bare POST /api/v1/tune p50 / p95 | change -> live curve drawn p50 / p95 | -> live curve painted p50 / p95 | change -> numbers p50 / p95 | change -> first preview frame p50 / p95 | numbers / bare (p50) |');
console.log('| --- | --- | --- | --- | --- | --- | --- |');
for (const r of rows) {
  // A change whose live curve did not draw from the controls counts as never (Infinity), so it shows.
  const lives = r.lives.map((x) => (Number.isFinite(x) ? x : Infinity));
  console.log(`| ${r.label} | ${ms(quantile(r.bare, 0.5))} / ${ms(quantile(r.bare, 0.95))} | ${ms1(quantile(lives, 0.5))} / ${ms1(quantile(lives, 0.95))} | ` +
    `${ms1(quantile(r.paints, 0.5))} / ${ms1(quantile(r.paints, 0.95))} | ${ms(quantile(r.numbers, 0.5))} / ${ms(quantile(r.numbers, 0.95))} | ` +
    `${ms(quantile(r.frames, 0.5))} / ${ms(quantile(r.frames, 0.95))} | ${(quantile(r.numbers, 0.5) / quantile(r.bare, 0.5)).toFixed(1)}x |`);
}
console.log('\n| scene | change -> tune request sent p50 | change -> tune answer in p50 | change -> numbers p50 |');
console.log('| --- | --- | --- | --- |');
for (const r of rows) {
  console.log(`| ${r.label} | ${ms(quantile(r.sends, 0.5))} | ${ms(quantile(r.answers, 0.5))} | ${ms(quantile(r.numbers, 0.5))} |`);
}
console.log('\n| scene | preview POST sent p50 | its answer in p50 | frame 0 asked p50 | frame 0 in p50 | frame 0 on screen p50 |');
console.log('| --- | --- | --- | --- | --- | --- |');
for (const r of rows) {
  const q = (xs) => ms(quantile(xs.filter((x) => Number.isFinite(x)), 0.5));
  console.log(`| ${r.label} | ${q(r.posts)} | ${q(r.posted)} | ${q(r.pngs)} | ${q(r.pnged)} | ${q(r.frames)} |`);
}

