// MuJoCo 3.x (npm mujoco-js, the official WebAssembly build) in the loop: the cases come from softtune's
// model (the mujoco_js_cases executable prints them: settings, `parameters`, `predicted`, `exact`, the
// request), each is built as the same MJCF kMujocoEngine loads (engines/mujoco/mujoco_engine.cpp), stepped
// with mj_step, fitted, and held to
//   parameters: measured within 1 % frequency and 0.02 damping ratio of `predicted` (unstable: blows up);
//   exact:      measured within 1 % / 0.02 of the request; a null `exact` carries engine_inexact.
// MuJoCo 3 adds integrator="implicitfast", which the cases include.
//
//   node tests/engines/mujoco/mujoco_js_conformance.mjs <path to mujoco_js_cases>
// Exit code 0 when every case holds, 1 otherwise; prints the table.
import { execFileSync } from 'node:child_process';
import loadMujoco from 'mujoco-js';

const casesBinary = process.argv[2];
if (!casesBinary) {
  console.error('usage: node mujoco_js_conformance.mjs <mujoco_js_cases>');
  process.exit(2);
}
const cases = JSON.parse(execFileSync(casesBinary, { encoding: 'utf8', maxBuffer: 1 << 26 }));
const mujoco = await loadMujoco();
mujoco.FS.mkdir('/softtune');
mujoco.FS.mount(mujoco.MEMFS, { root: '.' }, '/softtune');

const REST_LENGTH = 1.0;  // kMujocoRestLength
const X0 = 1e-3;          // as the C++ conformance test: the plank's geometry stays linear to 1e-4

function mjcf(c, p) {
  const soft = `solref="${p['solref[0]']} ${p['solref[1]']}" solimp="${p['solimp[0]']} ${p['solimp[1]']} ` +
               `${p['solimp[2]']} ${p['solimp[3]']} ${p['solimp[4]']}"`;
  const plank = c.body === 'plank';
  // rotating_plank(m): mass 2 m, offset 0.5, inertia mass offset^2 (engines/include/softtune/engines/engine_run.h)
  const mass = 2 * c.mass, offset = 0.5, inertia = mass * offset * offset;
  let s = `<mujoco model="softtune">\n  <option timestep="${c.h}" gravity="0 0 0" integrator="${c.integrator}">\n` +
          `    <flag refsafe="${c.refsafe}"/>\n  </option>\n  <worldbody>\n`;
  if (plank) s += `    <site name="w" pos="${-REST_LENGTH} ${-offset} 0"/>\n`;
  s += `    <body name="b">\n      <joint name="x" type="slide" axis="1 0 0"/>\n`;
  if (plank) {
    s += `      <joint name="y" type="slide" axis="0 1 0"/>\n      <joint name="q" type="hinge" axis="0 0 1"/>\n` +
         `      <inertial pos="0 0 0" mass="${mass}" diaginertia="${inertia} ${inertia} ${inertia}"/>\n` +
         `      <site name="a" pos="0 ${-offset} 0"/>\n`;
  } else {
    s += `      <inertial pos="0 0 0" mass="${c.mass}" diaginertia="1 1 1"/>\n`;
  }
  s += `    </body>\n  </worldbody>\n`;
  if (plank) {
    s += `  <tendon>\n    <spatial name="t">\n      <site site="w"/>\n      <site site="a"/>\n    </spatial>\n` +
         `  </tendon>\n  <equality>\n    <tendon tendon1="t" ${soft}/>\n  </equality>\n`;
  } else {
    s += `  <equality>\n    <joint joint1="x" ${soft}/>\n  </equality>\n`;
  }
  return s + '</mujoco>\n';
}

function run(c, p, steps) {
  mujoco.FS.writeFile('/softtune/case.xml', mjcf(c, p));
  const model = mujoco.MjModel.loadFromXML('/softtune/case.xml');
  const data = new mujoco.MjData(model);
  const offset = 0.5;
  const stretch = () => {
    const q = data.qpos;
    if (c.body !== 'plank') return q[0];
    const ax = q[0] + offset * Math.sin(q[2]) + REST_LENGTH, ay = q[1] - offset * Math.cos(q[2]) + offset;
    return Math.hypot(ax, ay) - REST_LENGTH;
  };
  data.qpos[0] = X0;
  const x = [stretch()];
  for (let i = 0; i < steps; ++i) {
    mujoco.mj_step(model, data);
    x.push(stretch());
  }
  data.delete();
  model.delete();
  return x;
}

// achieved_from_poles (core/discrete_analysis.cpp): s = ln(z) / h, omega = |s|, zeta = -Re(s) / |s|.
function fromPoles(re1, im1, re2, im2, h) {
  const r1 = Math.hypot(re1, im1), r2 = Math.hypot(re2, im2);
  if (!(r1 > 0) || !(r2 > 0)) return null;
  let sr, si;
  if (im1 !== 0) {
    sr = Math.log(r1) / h;
    si = Math.atan2(Math.abs(im1), re1) / h;
  } else if (re1 > 0 && re2 > 0) {
    const s1 = Math.log(re1) / h, s2 = Math.log(re2) / h;
    if (!(s1 * s2 > 0)) return null;
    const omega = Math.sqrt(s1 * s2);
    return { frequency_hz: omega / (2 * Math.PI), damping_ratio: -(s1 + s2) / (2 * omega) };
  } else {
    sr = Math.log(Math.sqrt(r1 * r2)) / h;
    si = Math.PI / h;
  }
  const omega = Math.hypot(sr, si);
  return { frequency_hz: omega / (2 * Math.PI), damping_ratio: sr === 0 ? 0 : -sr / omega };
}

// Order-2 linear prediction x[n] = a1 x[n-1] + a2 x[n-2] (the motion decays to 0: no constant term), each
// equation scaled by 1 / max(|x[n-1]|, |x[n-2]|), over the rows above 1e-5 x0 (below it the plank's
// second-order geometry shows).
function fit(x, h) {
  let s00 = 0, s01 = 0, s11 = 0, r0 = 0, r1 = 0, rows = 0;
  for (let n = 2; n < x.length; ++n) {
    const w = Math.max(Math.abs(x[n - 1]), Math.abs(x[n - 2]));
    if (!(w > 1e-5 * Math.abs(x[0]))) continue;
    const p = x[n - 1] / w, q = x[n - 2] / w, y = x[n] / w;
    s00 += p * p; s01 += p * q; s11 += q * q; r0 += p * y; r1 += q * y; ++rows;
  }
  const det = s00 * s11 - s01 * s01;
  if (rows < 2 || !(Math.abs(det) > 0)) return null;
  const a1 = (r0 * s11 - r1 * s01) / det, a2 = (s00 * r1 - s01 * r0) / det;
  const disc = a1 * a1 + 4 * a2;
  if (disc >= 0) {
    const root = Math.sqrt(disc);
    const z1 = 0.5 * (a1 + root), z2 = 0.5 * (a1 - root);
    return fromPoles(Math.abs(z1) >= Math.abs(z2) ? z1 : z2, 0, Math.abs(z1) >= Math.abs(z2) ? z2 : z1, 0, h);
  }
  const im = 0.5 * Math.sqrt(-disc);
  return fromPoles(0.5 * a1, im, 0.5 * a1, -im, h);
}

function blewUp(x) {
  for (let i = 1; i < x.length; ++i) {
    if (!Number.isFinite(x[i]) || Math.abs(x[i]) > 10 * Math.abs(X0)) return true;
    if (x[i] === 0 && x[x.length - 1] === 0) return true;  // mj_checkAcc reset to qpos0
  }
  return false;
}

const worst = { predicted: { cases: 0, f: 0, z: 0 }, exact: { cases: 0, f: 0, z: 0 } };
let failures = 0, unstable = 0, inexact = 0;
const fail = (label, what) => { ++failures; console.log(`FAIL ${label}: ${what}`); };
for (const c of cases) {
  const label = `h ${c.h.toPrecision(4)} ${c.integrator} ${c.mode} ${c.body} mass ${c.mass} asked ` +
                `${c.asked.frequency_hz.toPrecision(4)} Hz zeta ${c.asked.damping_ratio}`;
  const steps = Math.min(6000, Math.max(300, Math.floor(4 / (Math.max(1e-9, c.asked.frequency_hz) * c.h))));
  const plain = run(c, c.parameters, steps);
  if (!c.predicted.stable) {
    ++unstable;
    if (!blewUp(plain)) fail(label, 'predicted unstable, the engine did not blow up');
  } else if (c.predicted.frequency_hz > 0) {
    const m = fit(plain, c.h);
    if (!m) {
      fail(label, 'no fit of the plain export');
    } else {
      const ef = m.frequency_hz / c.predicted.frequency_hz - 1, ez = m.damping_ratio - c.predicted.damping_ratio;
      worst.predicted.cases++;
      worst.predicted.f = Math.max(worst.predicted.f, Math.abs(ef));
      worst.predicted.z = Math.max(worst.predicted.z, Math.abs(ez));
      if (Math.abs(ef) >= 0.01 || Math.abs(ez) >= 0.02) {
        fail(label, `plain measured ${m.frequency_hz} Hz ${m.damping_ratio}, predicted ` +
                    `${c.predicted.frequency_hz} Hz ${c.predicted.damping_ratio}`);
      }
    }
  }
  if (!c.exact) {
    ++inexact;
    if (!c.inexact_warned) fail(label, 'exact null without engine_inexact');
    continue;
  }
  const m = fit(run(c, c.exact, steps), c.h);
  if (!m) {
    fail(label, 'no fit of exact');
    continue;
  }
  const ef = m.frequency_hz / c.asked.frequency_hz - 1, ez = m.damping_ratio - c.asked.damping_ratio;
  worst.exact.cases++;
  worst.exact.f = Math.max(worst.exact.f, Math.abs(ef));
  worst.exact.z = Math.max(worst.exact.z, Math.abs(ez));
  if (Math.abs(ef) >= 0.01 || Math.abs(ez) >= 0.02) {
    fail(label, `exact measured ${m.frequency_hz} Hz ${m.damping_ratio}, asked ${c.asked.frequency_hz} Hz`);
  }
}
mujoco.FS.unmount('/softtune');
const row = (name, w) => `  ${name.padEnd(26)} ${String(w.cases).padStart(6)} ${(100 * w.f).toFixed(4).padStart(12)}% ` +
                         `${w.z.toFixed(4).padStart(12)}`;
console.log(`\nMuJoCo ${mujoco.mj_versionString()} (mujoco-js) conformance, ${cases.length} cases`);
console.log(`  ${''.padEnd(26)} ${'cases'.padStart(6)} ${'worst freq'.padStart(13)} ${'worst zeta'.padStart(12)}`);
console.log(row('parameters vs predicted', worst.predicted));
console.log(row('exact vs request', worst.exact));
console.log(`  predicted unstable (and blew up): ${unstable}, exact null (engine_inexact): ${inexact}, failures: ${failures}`);
process.exit(failures === 0 ? 0 : 1);
