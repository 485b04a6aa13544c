// web/engines.js: each engine's snippet, in that engine's own syntax, from fixed tune answers (the shape of
// POST /api/v1/tune's engines.<name>: settings, parameters, predicted, exact, exact_predicted, warnings);
// every number is the answer's own at full precision, a null is a comment saying why, and the verdict of a
// prediction against the request ("blows up", "cannot").
// Run: node --test tests/web/engines.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  comparedTo, decimal, engineKeys, engineSnippet, engineWarnings, formatDifference, legacyFields, legacySnippet, notesFor, shortName, verdict,
} from '../../web/engines.js';

const requested = { frequency_hz: 5, damping_ratio: 0.5 };
const ok = (f, z) => ({ frequency_hz: f, damping_ratio: z, spectral_radius: 0.77, stable: true });

/// A tune answer holding one engine's report.
function answer(key, report, extra = {}) {
  return { h: 1 / 60, requested, engines: { [key]: { model: `${key} sources`, warnings: [], ...report } }, ...extra };
}

function snippet(key, report, which = 'exact') {
  const tune = answer(key, report);
  const text = engineSnippet(key, tune.engines[key], tune, which);
  assert.doesNotMatch(text, /NaN|undefined|Infinity/, text);
  return text;
}

test('Box2D 2.4 (C++): b2DistanceJointDef fields and the step, exact or plain, as float literals', () => {
  const report = {
    settings: { joint: 'distance', velocityIterations: 8 },
    parameters: { 'b2DistanceJointDef::damping': 62.83185307179586, 'b2DistanceJointDef::stiffness': 1973.9208802178716 },
    predicted: ok(4.323931655019076, 0.6476777626573689),
    exact: { 'b2DistanceJointDef::damping': 40.3112637233068, 'b2DistanceJointDef::stiffness': 2535.5851003457656 },
    exact_predicted: ok(5.000000000000001, 0.5000000000000002),
  };
  assert.equal(snippet('box2d_v2_4', report, 'exact'), [
    '// Box2D 2.4 (C++), exact values: predicted 5 Hz, damping ratio 0.5',
    'b2DistanceJointDef jd;',
    'jd.stiffness = 2535.5851003457656f;  // N/m',
    'jd.damping = 40.3112637233068f;  // N s/m',
    'world.Step(0.016666666666666666f, 8, 3);  // timeStep, velocityIterations, positionIterations',
  ].join('\n'));
  const plain = snippet('box2d_v2_4', report, 'plain');
  assert.match(plain, /^\/\/ Box2D 2\.4 \(C\+\+\), plain values: predicted 4\.32393 Hz, damping ratio 0\.647678$/m);
  assert.ok(plain.includes('jd.stiffness = 1973.9208802178716f;'), plain);
  // The wheel joint carries the same spring fields in its own def.
  const wheel = snippet('box2d_v2_4', { ...report, settings: { joint: 'wheel', velocityIterations: 3 } });
  assert.match(wheel, /^b2WheelJointDef jd;$/m);
  assert.match(wheel, /world\.Step\(0\.016666666666666666f, 3, 3\);/);
});

test('a solved scene joint: its own def from its values, its note, and each prediction against what the answer names', () => {
  // The shape of a simulate answer's joints[].answer.engines for a wheel joint a modal tuning solved
  // (server/codec/joint_answer_codec.cpp): Box2D 2.4 the run's k, c measured on the mode, Jolt a per-joint model.
  const tune = {
    h: 1 / 60, requested: { frequency_hz: 3, damping_ratio: 0.5, mode: 'chassis heave' },
    engines: {
      box2d_v2_4: {
        settings: { joint: 'wheel', velocityIterations: 8 }, basis: 'scene_run', note: 'the values the scene ran in Box2D 2.4, measured on chassis heave',
        parameters: { 'b2WheelJointDef::stiffness': 24842.07, 'b2WheelJointDef::damping': 914.753 },
        exact: { 'b2WheelJointDef::stiffness': 24842.07, 'b2WheelJointDef::damping': 914.753 },
        predicted: ok(3.003, 0.499), exact_predicted: ok(3.003, 0.499), warnings: [],
      },
      jolt: { basis: 'per_joint_model', compared_to: { frequency_hz: 7.44, damping_ratio: 0.86 }, predicted: ok(7.44, 0.86) },
    },
  };
  const text = engineSnippet('box2d_v2_4', tune.engines.box2d_v2_4, tune, 'exact');
  assert.equal(text, [
    '// Box2D 2.4 (C++), exact values: predicted 3.003 Hz, damping ratio 0.499',
    '// the values the scene ran in Box2D 2.4, measured on chassis heave',
    'b2WheelJointDef jd;',
    'jd.stiffness = 24842.07f;  // N/m',
    'jd.damping = 914.753f;  // N s/m',
    'world.Step(0.016666666666666666f, 8, 3);  // timeStep, velocityIterations, positionIterations',
  ].join('\n'));
  // A scene's weld joint: the answer names its def in its settings and values.
  const weld = { settings: { joint: 'weld' }, parameters: { 'b2WeldJointDef::stiffness': 12.5, 'b2WeldJointDef::damping': 0.25 }, predicted: ok(2, 0.3) };
  assert.match(engineSnippet('box2d_v2_4', weld, { h: 1 / 60, requested }, 'plain'), /^b2WeldJointDef jd;$/m);
  // The per-joint model is held against Box2D 2.4's joint alone, not against the mode.
  assert.equal(comparedTo(tune.engines.jolt, tune), tune.engines.jolt.compared_to);
  assert.equal(verdict(tune.engines.jolt.predicted, comparedTo(tune.engines.jolt, tune)).frequencyError, 0);
  assert.equal(comparedTo(tune.engines.box2d_v2_4, tune), tune.requested);
});

test('Box2D v3 (C): b2DefaultDistanceJointDef, enableSpring, hertz, dampingRatio and b2World_Step with subStepCount', () => {
  const text = snippet('box2d_v3', {
    settings: { subStepCount: 4, enableWarmStarting: true },
    parameters: { 'b2DistanceJointDef::dampingRatio': 0.5, 'b2DistanceJointDef::enableSpring': 'true', 'b2DistanceJointDef::hertz': 5 },
    predicted: ok(5.4, 0.71),
    exact: { 'b2DistanceJointDef::dampingRatio': 0.31, 'b2DistanceJointDef::enableSpring': 'true', 'b2DistanceJointDef::hertz': 4.62 },
    exact_predicted: ok(5, 0.5),
  });
  assert.equal(text, [
    '// Box2D v3 (C), exact values: predicted 5 Hz, damping ratio 0.5',
    'b2DistanceJointDef def = b2DefaultDistanceJointDef();',
    'def.enableSpring = true;',
    'def.hertz = 4.62f;  // Hz',
    'def.dampingRatio = 0.31f;',
    'b2JointId jointId = b2CreateDistanceJoint(worldId, &def);',
    'b2World_EnableWarmStarting(worldId, true);',
    'b2World_Step(worldId, 0.016666666666666666f, 4);  // timeStep, subStepCount',
  ].join('\n'));
  // A whole number still reads as a float literal.
  assert.match(snippet('box2d_v3', { settings: { subStepCount: 4 }, parameters: { 'b2DistanceJointDef::hertz': 5 }, predicted: ok(5, 0) }, 'plain'),
    /^def\.hertz = 5\.0f;  \/\/ Hz$/m);
});

test('Jolt (C++): SpringSettings with its mode, PhysicsSettings and PhysicsSystem::Update', () => {
  const text = snippet('jolt', {
    settings: { collisionSteps: 1, linearDamping: 0.05, numPositionSteps: 2, numVelocitySteps: 10, springMode: 'FrequencyAndDamping' },
    parameters: { 'SpringSettings::mDamping': 0.5, 'SpringSettings::mFrequency': 5, 'SpringSettings::mMode': 'FrequencyAndDamping' },
    predicted: ok(4.9, 0.52),
    exact: { 'SpringSettings::mDamping': 0.47, 'SpringSettings::mFrequency': 5.1, 'SpringSettings::mMode': 'FrequencyAndDamping' },
    exact_predicted: ok(5, 0.5),
  });
  for (const line of [
    'JPH::SpringSettings spring;', 'spring.mMode = JPH::ESpringMode::FrequencyAndDamping;', 'spring.mFrequency = 5.1f;  // Hz',
    'spring.mDamping = 0.47f;', 'constraintSettings.mLimitsSpringSettings = spring;  // JPH::DistanceConstraintSettings',
    'physicsSettings.mNumVelocitySteps = 10;', 'physicsSettings.mNumPositionSteps = 2;', 'physicsSystem.SetPhysicsSettings(physicsSettings);',
    'bodySettings.mLinearDamping = 0.05f;  // JPH::BodyCreationSettings',
    'physicsSystem.Update(0.016666666666666666f, 1, &tempAllocator, &jobSystem);',
  ]) assert.ok(text.split('\n').includes(line), `${line}\n---\n${text}`);
  const stiff = snippet('jolt', {
    settings: {}, parameters: { 'SpringSettings::mDamping': 62.8, 'SpringSettings::mMode': 'StiffnessAndDamping', 'SpringSettings::mStiffness': 1973.9 },
    predicted: ok(5, 0.5),
  }, 'plain');
  assert.match(stiff, /^spring\.mStiffness = 1973\.9f;$/m);
  assert.doesNotMatch(stiff, /mFrequency/);
});

test('MuJoCo (MJCF XML): option with timestep, integrator and refsafe; solref and solimp on the constraint', () => {
  const text = snippet('mujoco', {
    settings: { integrator: 'implicitfast', refsafe: 'enable', 'solimp[0]': 0.9, 'solimp[1]': 0.95, 'solimp[2]': 0.001, 'solimp[3]': 0.5, 'solimp[4]': 2 },
    parameters: { 'solimp[0]': 0.9, 'solimp[1]': 0.9, 'solimp[2]': 0.001, 'solimp[3]': 0.5, 'solimp[4]': 2, 'solref[0]': 0.0636, 'solref[1]': 0.5 },
    predicted: ok(4.1, 0.6),
    exact: { 'solimp[0]': 0.9, 'solimp[1]': 0.9, 'solimp[2]': 0.001, 'solimp[3]': 0.5, 'solimp[4]': 2, 'solref[0]': -1234.5, 'solref[1]': -56.75 },
    exact_predicted: ok(5, 0.5),
  });
  assert.equal(text, [
    '<!-- MuJoCo (MJCF XML), exact values: predicted 5 Hz, damping ratio 0.5 -->',
    '<option timestep="0.016666666666666666" integrator="implicitfast">',
    '  <flag refsafe="enable"/>',
    '</option>',
    '<!-- on the soft constraint: an equality here (a joint limit takes solreflimit and solimplimit) -->',
    '<equality>',
    '  <connect body1="A" body2="B" anchor="0 0 0" solref="-1234.5 -56.75" solimp="0.9 0.9 0.001 0.5 2"/>',
    '</equality>',
  ].join('\n'));
  // A null solref is left out, with an XML comment (no "--" inside it) saying why.
  const missing = snippet('mujoco', { settings: {}, parameters: { 'solref[0]': null, 'solref[1]': 0.5 }, predicted: ok(5, 0.5) }, 'plain');
  assert.match(missing, /<!-- solref\[0\]: no value \(null in the answer: the engine cannot represent it\) -->/);
  assert.doesNotMatch(missing, /solref="/);
  for (const comment of missing.match(/<!--(.*?)-->/g)) assert.doesNotMatch(comment.slice(4, -3), /--/);
});

test('Rapier (Rust): set_motor_model and set_motor_position on the joint axis, IntegrationParameters and the body', () => {
  const text = snippet('rapier', {
    settings: { additionalSolverIterations: 0, linearDamping: 0, motorModel: 'AccelerationBased', numInternalPgsIterations: 1, numSolverIterations: 4 },
    parameters: { 'JointMotor::damping': 5, 'JointMotor::model': 'AccelerationBased', 'JointMotor::stiffness': 986.96 },
    predicted: ok(5, 0.5),
  }, 'plain');
  assert.equal(text, [
    '// Rapier (Rust), plain values: predicted 5 Hz, damping ratio 0.5',
    'joint.set_motor_model(JointAxis::LinX, MotorModel::AccelerationBased);',
    'joint.set_motor_position(JointAxis::LinX, 0.0, 986.96, 5.0);  // target, stiffness, damping',
    'integration_parameters.dt = 0.016666666666666666;',
    'integration_parameters.num_solver_iterations = NonZeroUsize::new(4).unwrap();',
    'integration_parameters.num_internal_pgs_iterations = 1;',
    'let body = RigidBodyBuilder::dynamic().additional_solver_iterations(0).linear_damping(0.0);',
  ].join('\n'));
});

test('ODE (C): the joint\'s own dJointSet*Param per field and the stepper the settings name', () => {
  const text = snippet('ode', {
    settings: { dWorldSetQuickStepNumIterations: 20, dWorldSetQuickStepW: 1.3, joint: 'slider', stepper: 'dWorldQuickStep' },
    parameters: { dParamHiStop: 0, dParamLoStop: 0, dParamStopCFM: 0.0104, dParamStopERP: 0.3436 },
    predicted: ok(5, 0.5),
  }, 'plain');
  for (const line of [
    'dJointSetSliderParam(joint, dParamHiStop, 0);  // m', 'dJointSetSliderParam(joint, dParamLoStop, 0);  // m',
    'dJointSetSliderParam(joint, dParamStopCFM, 0.0104);  // m/(N s)', 'dJointSetSliderParam(joint, dParamStopERP, 0.3436);',
    'dWorldSetQuickStepNumIterations(world, 20);', 'dWorldSetQuickStepW(world, 1.3);', 'dWorldQuickStep(world, 0.016666666666666666);',
  ]) assert.ok(text.split('\n').includes(line), `${line}\n---\n${text}`);
  const dball = snippet('ode', { settings: { joint: 'dball', stepper: 'dWorldStep' }, parameters: { dParamCFM: 0.01, dParamERP: 0.34 }, predicted: ok(5, 0.5) }, 'plain');
  assert.match(dball, /^dJointSetDBallParam\(joint, dParamERP, 0\.34\);$/m);
  assert.match(dball, /^dWorldStep\(world, 0\.016666666666666666\);$/m);
  assert.doesNotMatch(dball, /QuickStep/);
});

test('Bullet (C++): btGeneric6DofSpring2Constraint springs with limitIfNeeded, or the locked axis\' STOP_ERP / STOP_CFM', () => {
  const spring = snippet('bullet', {
    settings: { m_numIterations: 10, route: 'spring2' },
    parameters: {
      'btGeneric6DofSpring2Constraint::setDamping': 62.83, 'btGeneric6DofSpring2Constraint::setStiffness': 1973.92,
      'setDamping(limitIfNeeded)': 'false', 'setStiffness(limitIfNeeded)': 'true',
    },
    predicted: ok(5, 0.5),
  }, 'plain');
  for (const line of [
    'spring->enableSpring(0, true);  // axis 0: linear x', 'spring->setStiffness(0, 1973.92f, true);  // N/m',
    'spring->setDamping(0, 62.83f, false);  // N s/m', 'dynamicsWorld->getSolverInfo().m_numIterations = 10;',
    'dynamicsWorld->stepSimulation(0.016666666666666666f, 1, 0.016666666666666666f);  // timeStep, maxSubSteps, fixedTimeStep',
  ]) assert.ok(spring.split('\n').includes(line), `${line}\n---\n${spring}`);
  const stop = snippet('bullet', {
    settings: { m_numIterations: 10, route: 'erp_cfm' },
    parameters: { 'btGeneric6DofSpring2Constraint::setParam(BT_CONSTRAINT_STOP_CFM)': 0.01, 'btGeneric6DofSpring2Constraint::setParam(BT_CONSTRAINT_STOP_ERP)': 0.34 },
    predicted: ok(5, 0.5),
  }, 'plain');
  assert.match(stop, /^spring->setParam\(BT_CONSTRAINT_STOP_ERP, 0\.34f, 0\);$/m);
  assert.match(stop, /^spring->setParam\(BT_CONSTRAINT_STOP_CFM, 0\.01f, 0\);$/m);
  assert.doesNotMatch(stop, /setStiffness/);
});

test('PhysX (C++): a D6 drive on the axis', () => {
  const text = snippet('physx', {
    settings: {}, parameters: { 'PxD6JointDrive::damping': 31.4, 'PxD6JointDrive::isAcceleration': 'true', 'PxD6JointDrive::stiffness': 986.9 },
    predicted: ok(5, 0.5),
  }, 'plain');
  assert.match(text, /^joint->setDrive\(physx::PxD6Drive::eX, physx::PxD6JointDrive\(986\.9f, 31\.4f, PX_MAX_F32, true\)\);$/m);
  assert.match(text, /^scene->simulate\(0\.016666666666666666f\);$/m);
});

test('no exact values: the snippet is comments only, with the engine\'s reason', () => {
  const report = {
    settings: { joint: 'distance', velocityIterations: 8 },
    parameters: { 'b2DistanceJointDef::damping': -32.15, 'b2DistanceJointDef::stiffness': 1929.2 },
    predicted: { frequency_hz: null, damping_ratio: null, spectral_radius: 1, stable: true },
    exact: null, exact_predicted: null,
    warnings: [
      { code: 'engine_refuses', engine: 'box2d_v2_4', message: 'damping + h stiffness > 0, else the joint is rigid' },
      { code: 'engine_inexact', engine: 'box2d_v2_4', message: 'box2d_v2_4 cannot meet the request exactly' },
    ],
  };
  const text = snippet('box2d_v2_4', report, 'exact');
  assert.ok(text.split('\n').every((l) => l.startsWith('// ')), text);
  assert.match(text, /cannot meet the request exactly/);
  assert.doesNotMatch(text, /rigid/);
  // The plain values still say what to type, headed by why the engine shows no spring.
  const plain = snippet('box2d_v2_4', report, 'plain');
  assert.match(plain, /^\/\/ Box2D 2\.4 \(C\+\+\), plain values: CANNOT/);
  assert.match(plain, /^\/\/ damping \+ h stiffness > 0, else the joint is rigid$/m);
  assert.match(plain, /^jd\.damping = -32\.15f;/m);
});

test('a null value or a field with no API line becomes a comment', () => {
  const text = snippet('box2d_v3', {
    settings: { subStepCount: 4 },
    parameters: { 'b2DistanceJointDef::hertz': null, 'b2DistanceJointDef::dampingRatio': 0, 'b2DistanceJointDef::maxHertz': 15 },
    predicted: ok(null, null),
  }, 'plain');
  assert.match(text, /^\/\/ b2DistanceJointDef::hertz: no value \(null in the answer: the engine cannot represent it\)$/m);
  assert.match(text, /^def\.dampingRatio = 0\.0f;$/m);
  assert.match(text, /^\/\/ b2DistanceJointDef::maxHertz = 15 \(no API line for this field in web\/engines\.js\)$/m);
});

test('verdicts: blows up when unstable, cannot when asked to oscillate and no frequency, else the errors', () => {
  const blows = verdict({ frequency_hz: 9, damping_ratio: -0.1, spectral_radius: 1.04, stable: false }, requested);
  assert.equal(blows.state, 'blows_up');
  assert.equal(verdict({ frequency_hz: null, damping_ratio: null, spectral_radius: 1, stable: true }, requested).state, 'cannot');
  assert.equal(verdict({ frequency_hz: null, damping_ratio: null, spectral_radius: 1, stable: true }, { frequency_hz: 0, damping_ratio: 0 }).state, 'ok');
  assert.equal(verdict(null, requested).state, 'none');
  const off = verdict(ok(4.5, 0.55), requested);
  assert.equal(off.state, 'ok');
  assert.ok(Math.abs(off.frequencyError - -10) < 1e-12);
  assert.ok(Math.abs(off.dampingError - 0.05) < 1e-12);
  assert.equal(verdict(ok(1, 0), { frequency_hz: 0, damping_ratio: 0 }).frequencyError, null);
  const text = snippet('jolt', { settings: {}, parameters: { 'SpringSettings::mDamping': 0, 'SpringSettings::mFrequency': 40 },
    predicted: { frequency_hz: 9, damping_ratio: -0.1, spectral_radius: 1.04, stable: false },
    warnings: [{ code: 'engine_unstable', engine: 'jolt', message: 'jolt blows up above 30 Hz at this step' }] }, 'plain');
  assert.match(text, /^\/\/ Jolt \(C\+\+\), plain values: BLOWS UP \(spectral radius 1\.04 per step\)$/m);
  assert.match(text, /^\/\/ jolt blows up above 30 Hz at this step$/m);
});

test('notes: exactness warnings explain the exact values, the others the plain ones', () => {
  const e = { warnings: [{ code: 'engine_refuses', message: 'a' }, { code: 'engine_inexact', message: 'b' }] };
  assert.deepEqual(notesFor(e, 'exact'), ['b']);
  assert.deepEqual(notesFor(e, 'plain'), ['a']);
  assert.deepEqual(notesFor({ warnings: [{ code: 'engine_refuses', message: 'a' }] }, 'exact'), ['a']);
  // An engine's warnings: its report's and the answer's top-level ones naming it, each once.
  const tune = { engines: { jolt: e }, warnings: [{ code: 'engine_note', engine: 'jolt', message: 'c' }, { code: 'x', engine: 'jolt', message: 'a' },
    { code: 'frequency_error', message: 'd' }, { code: 'engine_note', engine: 'mujoco', message: 'e' }] };
  assert.deepEqual(engineWarnings(tune, 'jolt').map((w) => w.message), ['a', 'b', 'c']);
  assert.deepEqual(engineWarnings(tune, 'mujoco').map((w) => w.message), ['e']);
});

test('engines without a model show their older fields; a null one is a comment; ODE / Bullet goes once both are modelled', () => {
  const legacy = { hertz: null, damping_ratio: 0.5, max_hertz: 15, headroom: 3 };
  const text = legacySnippet('box2d_v3', legacy);
  assert.match(text, /^\/\/ no value \(null in the answer: not representable\): def\.hertz = null;$/m);
  assert.match(text, /^def\.dampingRatio = 0\.5f;$/m);
  assert.doesNotMatch(text, /NaN|undefined/);
  const tune = { h: 1 / 60, requested, engines: { box2d_v3: legacy } };
  assert.equal(engineSnippet('box2d_v3', legacy, tune, 'exact'), text);
  assert.deepEqual(legacyFields({ solref: [0.06, 0.5], form: 'standard', jolt: { a: { b: 1 } } }),
    [['solref[0]', 0.06], ['solref[1]', 0.5], ['form', 'standard'], ['jolt.a.b', 1]]);
  const modelled = { parameters: {}, predicted: ok(5, 0.5) };
  assert.deepEqual(engineKeys({ engines: { box2d_v2_4: modelled, ode_bullet: {}, ode: modelled } }), ['box2d_v2_4', 'ode_bullet', 'ode']);
  assert.deepEqual(engineKeys({ engines: { ode_bullet: {}, ode: modelled, bullet: modelled } }), ['ode', 'bullet']);
  // An engine the page has no syntax for shows its JSON.
  assert.equal(engineSnippet('havok', { x: 1 }, tune, 'exact'), JSON.stringify({ x: 1 }, null, 1));
});

test('literals and short names', () => {
  assert.equal(decimal(5), '5.0');
  assert.equal(decimal(-0.25), '-0.25');
  assert.equal(decimal(1e21), '1e+21');
  assert.equal(decimal(1e-7), '1e-7');
  assert.equal(shortName('btGeneric6DofSpring2Constraint::setParam(BT_CONSTRAINT_STOP_ERP)'), 'setParam(BT_CONSTRAINT_STOP_ERP)');
  assert.equal(shortName('solref[0]'), 'solref[0]');
  assert.equal(formatDifference(2.220446049250313e-16), '+0.000');
  assert.equal(formatDifference(-0.0004), '+0.000');
  assert.equal(formatDifference(-0.1476), '−0.148');
  assert.equal(formatDifference(null), '—');
});

test('matter.js (JavaScript): the snippet runs under node in the real matter-js with the answer\'s numbers', async () => {
  const { default: Matter } = await import('matter-js');
  const report = {
    settings: { anchorLeverage: 0, constraintIterations: 4, frictionAir: 0 },
    parameters: { 'Constraint.damping': 0.05235987755982988, 'Constraint.stiffness': 0.02741556778080377 },
    predicted: ok(7.1, 0.41),
    exact: { 'Constraint.damping': 0.011437212003245196, 'Constraint.stiffness': 0.005925818553396128 },
    exact_predicted: ok(5.000000000000002, 0.4999999999999998),
  };
  const text = snippet('matter_js', report, 'exact');
  assert.equal(text, [
    '// matter.js (JavaScript), exact values: predicted 5 Hz, damping ratio 0.5',
    'const engine = Matter.Engine.create({ constraintIterations: 4 });',
    'body.frictionAir = 0;  // Body.frictionAir of the constrained body',
    'const spring = Matter.Constraint.create({ pointA, bodyB: body, pointB, length, stiffness: 0.005925818553396128, damping: 0.011437212003245196 });',
    'Matter.Composite.add(engine.world, [body, spring]);',
    'Matter.Engine.update(engine, 16.666666666666668);  // delta in ms, every step',
  ].join('\n'));
  // Run as written, on a body 1 past a length-1 constraint: the engine holds the answer's numbers and moves.
  const body = Matter.Bodies.circle(2, 0, 0.1);
  const run = new Function('Matter', 'body', 'pointA', 'pointB', 'length', `${text}\nreturn { engine, spring };`);
  const { engine, spring } = run(Matter, body, { x: 0, y: 0 }, { x: 0, y: 0 }, 1);
  assert.equal(engine.constraintIterations, 4);
  assert.equal(body.frictionAir, 0);
  assert.equal(spring.stiffness, report.exact['Constraint.stiffness']);
  assert.equal(spring.damping, report.exact['Constraint.damping']);
  assert.ok(body.position.x < 2 && body.position.x > 1);
  // A null stiffness is a comment, and the rest still runs.
  const missing = snippet('matter_js', { ...report, exact: { 'Constraint.stiffness': null, 'Constraint.damping': 0.1 } }, 'exact');
  assert.match(missing, /^\/\/ Constraint\.stiffness: no value \(null in the answer: the engine cannot represent it\)$/m);
  assert.doesNotMatch(missing, /Constraint\.create/);
});

test('planck.js (JavaScript): the snippet runs under node in the real planck with the answer\'s numbers', async () => {
  const { default: planck } = await import('planck');
  const report = {
    settings: { joint: 'distance', rotationShare: 0, velocityIterations: 8 },
    parameters: { 'DistanceJointDef.dampingRatio': 0.1, 'DistanceJointDef.frequencyHz': 10 },
    predicted: ok(8.25, 0.484),
    exact: { 'DistanceJointDef.dampingRatio': -0.4168998473405207, 'DistanceJointDef.frequencyHz': 10.072180089047493 },
    exact_predicted: ok(10.000000000000002, 0.10000000000000003),
  };
  const text = snippet('planck_js', report, 'exact');
  assert.equal(text, [
    '// planck.js (JavaScript), exact values: predicted 10 Hz, damping ratio 0.1',
    'const joint = world.createJoint(new planck.DistanceJoint({ frequencyHz: 10.072180089047492, dampingRatio: -0.4168998473405207, length }, ground, body, anchorA, anchorB));',
    'world.step(0.016666666666666666, 8, 3);  // dt, velocityIterations, positionIterations',
  ].join('\n'));
  const world = new planck.World({ gravity: planck.Vec2(0, 0) });
  const ground = world.createBody();
  const body = world.createDynamicBody({ position: planck.Vec2(1.05, 0), fixedRotation: true });
  body.setMassData({ mass: 1, center: planck.Vec2(0, 0), I: 0 });
  const run = new Function('planck', 'world', 'ground', 'body', 'anchorA', 'anchorB', 'length', `${text}\nreturn joint;`);
  const joint = run(planck, world, ground, body, planck.Vec2(0, 0), planck.Vec2(1.05, 0), 1);
  assert.equal(joint.getFrequency(), report.exact['DistanceJointDef.frequencyHz']);
  assert.equal(joint.getDampingRatio(), report.exact['DistanceJointDef.dampingRatio']);
  assert.ok(body.getPosition().x < 1.05);
  // The mouse joint carries maxForce.
  const mouse = snippet('planck_js', { ...report, settings: { joint: 'mouse', velocityIterations: 8 },
    parameters: { 'MouseJointDef.dampingRatio': 0.1, 'MouseJointDef.frequencyHz': 10, 'MouseJointDef.maxForce': 1e15 } }, 'plain');
  assert.match(mouse, /new planck\.MouseJoint\(\{ frequencyHz: 10, dampingRatio: 0\.1, maxForce: 1000000000000000 \}, ground, body, target\)/);
});

test('cannon-es (JavaScript): the Spring and the DistanceConstraint snippets run under node in the real cannon-es', async () => {
  const CANNON = await import('cannon-es');
  const report = {
    settings: { iterations: 10, joint: 'spring', linearDamping: 0.01, spookTimeStep: 0 },
    parameters: { 'Spring.damping': 2.5132741228718345, 'Spring.stiffness': 157.91367041742973 },
    predicted: ok(2.025314432017956, 0.10129010666490974),
    exact: { 'Spring.damping': 2.4513140696813185, 'Spring.stiffness': 154.08755979183198 },
    exact_predicted: ok(2.0000000000000004, 0.10000000000000048),
  };
  const text = snippet('cannon_es', report, 'exact');
  assert.equal(text, [
    '// cannon-es (JavaScript), exact values: predicted 2 Hz, damping ratio 0.1',
    'body.linearDamping = 0.01;',
    'body.angularDamping = 0.01;',
    'world.solver.iterations = 10;',
    'const spring = new CANNON.Spring(ground, body, { restLength, localAnchorA, localAnchorB, stiffness: 154.08755979183198, damping: 2.4513140696813185 });',
    "world.addEventListener('postStep', () => spring.applyForce());  // the force for the next step",
    'world.step(0.016666666666666666);  // a fixed step of h',
  ].join('\n'));
  // Run as written on a 1 kg body 0.05 past a rest length of 1: the Spring holds the numbers and pulls it back.
  const scene = () => {
    const world = new CANNON.World({ gravity: new CANNON.Vec3(0, 0, 0) });
    const ground = new CANNON.Body({ mass: 0 });
    const body = new CANNON.Body({ mass: 1, shape: new CANNON.Sphere(0.1), position: new CANNON.Vec3(1.05, 0, 0) });
    world.addBody(ground);
    world.addBody(body);
    return { world, ground, body };
  };
  const { world, ground, body } = scene();
  const run = new Function('CANNON', 'world', 'ground', 'body', 'restLength', 'localAnchorA', 'localAnchorB',
                           `${text}\nreturn spring;`);
  const spring = run(CANNON, world, ground, body, 1, new CANNON.Vec3(), new CANNON.Vec3());
  assert.equal(spring.stiffness, report.exact['Spring.stiffness']);
  assert.equal(spring.damping, report.exact['Spring.damping']);
  assert.equal(body.linearDamping, 0.01);
  world.step(1 / 60);
  assert.ok(body.velocity.x < 0 && body.position.x < 1.05);
  // The DistanceConstraint bakes its SPOOK numbers with the report's spookTimeStep.
  const spook = { ...report, settings: { ...report.settings, joint: 'distance', spookTimeStep: 1 / 60 },
    exact: { 'setSpookParams.relaxation': 0.9545147212375769, 'setSpookParams.stiffness': 162.49218380854475 } };
  const spookText = snippet('cannon_es', spook, 'exact');
  assert.match(spookText, /^constraint\.distanceEquation\.setSpookParams\(162\.49218380854475, 0\.9545147212375769, 0\.016666666666666666\);/m);
  const s = scene();
  const build = new Function('CANNON', 'world', 'ground', 'body', 'distance', `${spookText}\nreturn constraint;`);
  const constraint = build(CANNON, s.world, s.ground, s.body, 1);
  const eq = constraint.distanceEquation, d = 0.9545147212375769, h = 1 / 60;
  assert.equal(s.world.constraints[0], constraint);
  assert.ok(Math.abs(eq.a - 4 / (h * (1 + 4 * d))) < 1e-9 && Math.abs(eq.b - 4 * d / (1 + 4 * d)) < 1e-12);
  assert.ok(s.body.position.x < 1.05);
});
