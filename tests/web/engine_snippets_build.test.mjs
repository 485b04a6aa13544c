// web/engines.js's snippets in the engines' own toolchains: Chipmunk's C compiled against Debian's
// libchipmunk-dev headers (cc -fsyntax-only), Godot's GDScript parsed by Godot 3.2.3 itself
// (godot3-server --check-only), 2-D and 3-D. Each from a fixed answer with every field and setting the model
// reports.
// Run: node --test tests/web/engine_snippets_build.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { engineSnippet } from '../../web/engines.js';

const requested = { frequency_hz: 5, damping_ratio: 0.5 };
const predicted = { frequency_hz: 5, damping_ratio: 0.5, spectral_radius: 0.77, stable: true };
const work = mkdtempSync(join(tmpdir(), 'softtune-snippets-'));

function snippet(key, report, which) {
  const tune = { h: 1 / 180, requested, engines: { [key]: { warnings: [], predicted, exact_predicted: predicted, ...report } } };
  const text = engineSnippet(key, tune.engines[key], tune, which);
  assert.doesNotMatch(text, /NaN|undefined|Infinity/, text);
  return text;
}

const hasChipmunk = existsSync('/usr/include/chipmunk/chipmunk.h');
test('Chipmunk (C): the snippet compiles against chipmunk.h, plain and exact', { skip: !hasChipmunk && 'libchipmunk-dev not installed' }, () => {
  const report = {
    settings: { cpSpaceSetIterations: 10, cpSpaceSetDamping: 0.9 },
    parameters: { cpDampedSpringSetStiffness: 986.96, cpDampedSpringSetDamping: 31.4159 },
    exact: { cpDampedSpringSetStiffness: 1017.3, cpDampedSpringSetDamping: 31.31 },
  };
  for (const which of ['plain', 'exact']) {
    const text = snippet('chipmunk', report, which);
    assert.match(text, which === 'exact' ? /cpDampedSpringSetStiffness\(spring, 1017\.3\);/ : /cpDampedSpringSetDamping\(spring, 31\.4159\);/);
    assert.match(text, /^cpSpaceStep\(space, 0\.005555555555555556\);$/m);
    const file = join(work, `chipmunk_${which}.c`);
    writeFileSync(file, ['#include <chipmunk/chipmunk.h>', 'void tune(cpSpace *space, cpBody *staticBody, cpBody *body) {',
      text, '}', ''].join('\n'));
    execFileSync('cc', ['-fsyntax-only', '-Wall', '-Werror', '-Wno-unused-variable', file], { stdio: 'pipe' });
  }
});

const godot = ['/usr/bin/godot3-server'].find(existsSync);
test('Godot 3.2 2-D (GDScript): the snippet parses in Godot, with the .tscn lines as comments', { skip: !godot && 'godot3-server not installed' }, () => {
  const report = {
    settings: { linear_damp: 0 },
    parameters: { 'DampedSpringJoint2D.stiffness': 986.96, 'DampedSpringJoint2D.damping': 31.4159 },
    exact: { 'DampedSpringJoint2D.stiffness': 1017.3, 'DampedSpringJoint2D.damping': 7.85 },
  };
  const text = snippet('godot_2d', report, 'exact');
  for (const line of ['$DampedSpringJoint2D.stiffness = 1017.3  # N/m', '$DampedSpringJoint2D.damping = 7.85  # N s/m',
    '$RigidBody2D.linear_damp = 0.0', '# stiffness = 1017.3', '# damping = 7.85']) {
    assert.ok(text.split('\n').includes(line), `${line}\n---\n${text}`);
  }
  assert.match(text, /^Engine\.iterations_per_second = 180 /m);
  const file = join(work, 'godot_2d.gd');
  writeFileSync(file, ['extends Node', '', 'func _ready():', ...text.split('\n').map((l) => `\t${l}`), ''].join('\n'));
  const home = join(work, 'home');
  execFileSync('mkdir', ['-p', home]);
  const out = execFileSync(godot, ['--check-only', '-s', file], { cwd: work, env: { ...process.env, HOME: home }, encoding: 'utf8', stdio: 'pipe' });
  assert.doesNotMatch(out, /SCRIPT ERROR|Parse Error/, out);
});

test('Godot 3.2 2-D PinJoint2D (GDScript): softness and bias parse in Godot', { skip: !godot && 'godot3-server not installed' }, () => {
  const report = {
    settings: { linear_damp: 0.1, joint: 'PinJoint2D' },
    parameters: { 'PinJoint2D.softness': 0.0254, 'PinJoint2D.bias': 0.3 },
    exact: { 'PinJoint2D.softness': 0.0261, 'PinJoint2D.bias': 0.29 },
  };
  const text = snippet('godot_2d', report, 'plain');
  for (const line of ['$PinJoint2D.softness = 0.0254  # 1/kg', '$PinJoint2D.bias = 0.3', '# softness = 0.0254']) {
    assert.ok(text.split('\n').includes(line), `${line}\n---\n${text}`);
  }
  assert.doesNotMatch(text, /DampedSpringJoint2D\./);
  const file = join(work, 'godot_pin.gd');
  writeFileSync(file, ['extends Node', '', 'func _ready():', ...text.split('\n').map((l) => `\t${l}`), ''].join('\n'));
  const home = join(work, 'home');
  execFileSync('mkdir', ['-p', home]);
  execFileSync(godot, ['--check-only', '-s', file], { cwd: work, env: { ...process.env, HOME: home }, encoding: 'utf8', stdio: 'pipe' });
});

test('Godot 3.2 3-D (GDScript): Generic6DOFJoint\'s X spring parses in Godot, with the .tscn lines as comments', { skip: !godot && 'godot3-server not installed' }, () => {
  const report = {
    settings: { 'physics/3d/physics_engine': 'Bullet', 'physics/3d/default_linear_damp': 0.1, linear_damp: -1 },
    parameters: { 'Generic6DOFJoint.linear_spring_x/stiffness': 986.96, 'Generic6DOFJoint.linear_spring_x/damping': 31.4159 },
    exact: { 'Generic6DOFJoint.linear_spring_x/stiffness': 960.5, 'Generic6DOFJoint.linear_spring_x/damping': 27.25 },
  };
  const text = snippet('godot_3d', report, 'exact');
  for (const line of ['$Generic6DOFJoint.set_param_x(Generic6DOFJoint.PARAM_LINEAR_SPRING_STIFFNESS, 960.5)  # N/m',
    '$Generic6DOFJoint.set_param_x(Generic6DOFJoint.PARAM_LINEAR_SPRING_DAMPING, 27.25)  # N s/m',
    '# linear_spring_x/stiffness = 960.5', '# linear_limit_x/enabled = false']) {
    assert.ok(text.split('\n').includes(line), `${line}\n---\n${text}`);
  }
  const file = join(work, 'godot_3d.gd');
  writeFileSync(file, ['extends Node', '', 'func _ready():', ...text.split('\n').map((l) => `\t${l}`), ''].join('\n'));
  const home = join(work, 'home');
  execFileSync('mkdir', ['-p', home]);
  const out = execFileSync(godot, ['--check-only', '-s', file], { cwd: work, env: { ...process.env, HOME: home }, encoding: 'utf8', stdio: 'pipe' });
  assert.doesNotMatch(out, /SCRIPT ERROR|Parse Error/, out);
});
