// Each engine's answer as a user types it: a snippet in that engine's own syntax (C for Box2D, C++ for Jolt,
// Bullet and PhysX, MJCF XML for MuJoCo, Rust for Rapier, C for ODE and Chipmunk, GDScript and .tscn lines for
// Godot, JavaScript for matter.js and planck.js) built from the tune answer's
// engines.<name>.parameters or .exact and .settings, and the verdict of its predicted response against the
// request. Pure functions, no DOM: web/engine_table.js draws them, tests/web/engines.test.mjs checks them.
//
// Every number in a snippet is the answer's own, at full precision; the page computes none. A value the
// answer leaves null (or does not carry) becomes a comment saying why, so a snippet never holds NaN,
// undefined or a made-up number. Each engine has one field table: the answer's field name -> the slot of
// the API call it goes into, with its unit; a field the table does not know is kept as a comment.
import { fmt } from './results.js';

const isNumber = (v) => typeof v === 'number' && Number.isFinite(v);

/// A number at full precision with a decimal point or an exponent: a floating literal in C, C++ and Rust.
export function decimal(v) {
  const s = String(v);
  return /[.e]/.test(s) ? s : `${s}.0`;
}
const cFloat = (v) => `${decimal(v)}f`;
const slashes = (text) => `// ${text}`;
const hashes = (text) => `# ${text}`;
/// The same values as the scene file's property lines of the node, as GDScript comments.
const tscnLines = (type, properties) => [
  `# or in the .tscn, under [node name="${type}" type="${type}" ...]:`,
  ...properties.filter(([, v]) => v !== undefined).map(([name, v]) => `# ${name} = ${v}`),
];
const xmlComment = (text) => `<!-- ${String(text).replace(/-{2,}/g, '-')} -->`;

// ---- the engines' syntax ---------------------------------------------------------------------------
// Each entry: label, language, comment(text), literal(number), fields {answer field name: {slot, unit}},
// and code(w, settings, h): the snippet's lines, where w.slot(name) is the slot's literal (or undefined),
// w.line(slots, make) writes make(...literals) or, when a slot has no value, a comment naming it.

const BOX2D_V2_4_DEFS = { distance: 'b2DistanceJointDef', wheel: 'b2WheelJointDef', mouse: 'b2MouseJointDef', weld: 'b2WeldJointDef' };
const box2dV24Fields = Object.fromEntries(Object.values(BOX2D_V2_4_DEFS).flatMap((def) => [
  [`${def}::stiffness`, { slot: 'stiffness', unit: 'N/m' }],
  [`${def}::damping`, { slot: 'damping', unit: 'N s/m' }],
]));

const ODE_SETTERS = { dball: 'dJointSetDBallParam', ball: 'dJointSetBallParam', slider: 'dJointSetSliderParam' };
const odeFields = Object.fromEntries(['dParamERP', 'dParamCFM', 'dParamStopERP', 'dParamStopCFM', 'dParamLoStop', 'dParamHiStop']
  .map((p) => [p, { slot: p, unit: { dParamCFM: 'm/(N s)', dParamStopCFM: 'm/(N s)', dParamLoStop: 'm', dParamHiStop: 'm' }[p] }]));

export const ENGINE_SYNTAX = {
  box2d_v2_4: {
    label: 'Box2D 2.4', language: 'C++', comment: slashes, literal: cFloat, fields: box2dV24Fields,
    code(w, settings, h) {
      const def = BOX2D_V2_4_DEFS[settings.joint] ?? 'b2DistanceJointDef';
      return [
        `${def} jd;`,
        w.line(['stiffness'], (k) => `jd.stiffness = ${k};`),
        w.line(['damping'], (c) => `jd.damping = ${c};`),
        ...(isNumber(settings.velocityIterations) && isNumber(h)
          ? [`world.Step(${cFloat(h)}, ${settings.velocityIterations}, 3);  // timeStep, velocityIterations, positionIterations`]
          : []),
      ];
    },
  },
  box2d_v3: {
    label: 'Box2D v3', language: 'C', comment: slashes, literal: cFloat,
    fields: {
      'b2DistanceJointDef::enableSpring': { slot: 'enableSpring' },
      'b2DistanceJointDef::hertz': { slot: 'hertz', unit: 'Hz' },
      'b2DistanceJointDef::dampingRatio': { slot: 'dampingRatio' },
    },
    code(w, settings, h) {
      return [
        'b2DistanceJointDef def = b2DefaultDistanceJointDef();',
        `def.enableSpring = ${w.slot('enableSpring') === 'false' ? 'false' : 'true'};`,
        w.line(['hertz'], (f) => `def.hertz = ${f};`),
        w.line(['dampingRatio'], (z) => `def.dampingRatio = ${z};`),
        'b2JointId jointId = b2CreateDistanceJoint(worldId, &def);',
        ...(settings.enableWarmStarting === undefined ? []
          : [`b2World_EnableWarmStarting(worldId, ${settings.enableWarmStarting === false || settings.enableWarmStarting === 'false' ? 'false' : 'true'});`]),
        ...(isNumber(settings.subStepCount) && isNumber(h)
          ? [`b2World_Step(worldId, ${cFloat(h)}, ${settings.subStepCount});  // timeStep, subStepCount`] : []),
      ];
    },
  },
  jolt: {
    label: 'Jolt', language: 'C++', comment: slashes, literal: cFloat,
    fields: {
      'SpringSettings::mMode': { slot: 'mode' },
      'SpringSettings::mFrequency': { slot: 'frequency', unit: 'Hz' },
      'SpringSettings::mStiffness': { slot: 'stiffness' },
      'SpringSettings::mDamping': { slot: 'damping' },
    },
    code(w, settings, h) {
      const mode = w.slot('mode') ?? settings.springMode;
      const physics = [['numVelocitySteps', 'mNumVelocitySteps'], ['numPositionSteps', 'mNumPositionSteps']]
        .filter(([s]) => isNumber(settings[s])).map(([s, m]) => `physicsSettings.${m} = ${settings[s]};`);
      return [
        'JPH::SpringSettings spring;',
        ...(mode ? [`spring.mMode = JPH::ESpringMode::${mode};`] : []),
        ...(w.has('frequency') ? [w.line(['frequency'], (f) => `spring.mFrequency = ${f};`)] : []),
        ...(w.has('stiffness') ? [w.line(['stiffness'], (k) => `spring.mStiffness = ${k};`)] : []),
        w.line(['damping'], (c) => `spring.mDamping = ${c};`),
        'constraintSettings.mLimitsSpringSettings = spring;  // JPH::DistanceConstraintSettings',
        ...(physics.length ? ['JPH::PhysicsSettings physicsSettings;', ...physics, 'physicsSystem.SetPhysicsSettings(physicsSettings);'] : []),
        ...(isNumber(settings.linearDamping) ? [`bodySettings.mLinearDamping = ${cFloat(settings.linearDamping)};  // JPH::BodyCreationSettings`] : []),
        ...(isNumber(settings.collisionSteps) && isNumber(h)
          ? [`physicsSystem.Update(${cFloat(h)}, ${settings.collisionSteps}, &tempAllocator, &jobSystem);`] : []),
      ];
    },
  },
  mujoco: {
    label: 'MuJoCo', language: 'MJCF XML', comment: xmlComment, literal: String,
    fields: Object.fromEntries([
      ['solref[0]', { slot: 'solref0' }], ['solref[1]', { slot: 'solref1' }],
      ...[0, 1, 2, 3, 4].map((i) => [`solimp[${i}]`, { slot: `solimp${i}` }]),
    ]),
    code(w, settings, h) {
      const solimp = [0, 1, 2, 3, 4].map((i) => w.slot(`solimp${i}`) ?? (isNumber(settings[`solimp[${i}]`]) ? String(settings[`solimp[${i}]`]) : undefined));
      const attributes = [];
      const notes = [];
      if (w.slot('solref0') !== undefined && w.slot('solref1') !== undefined) {
        attributes.push(`solref="${w.slot('solref0')} ${w.slot('solref1')}"`);
      } else notes.push(w.missing(['solref0', 'solref1']));
      if (solimp.every((v) => v !== undefined)) attributes.push(`solimp="${solimp.join(' ')}"`);
      const option = [isNumber(h) ? `timestep="${h}"` : '', settings.integrator ? `integrator="${settings.integrator}"` : ''].filter(Boolean).join(' ');
      return [
        ...(settings.refsafe ? [`<option ${option}>`, `  <flag refsafe="${settings.refsafe}"/>`, '</option>'] : [`<option ${option}/>`]),
        xmlComment('on the soft constraint: an equality here (a joint limit takes solreflimit and solimplimit)'),
        ...notes,
        '<equality>',
        `  <connect body1="A" body2="B" anchor="0 0 0" ${attributes.join(' ')}/>`,
        '</equality>',
      ];
    },
  },
  rapier: {
    label: 'Rapier', language: 'Rust', comment: slashes, literal: decimal,
    fields: {
      'JointMotor::model': { slot: 'model' },
      'JointMotor::stiffness': { slot: 'stiffness' },
      'JointMotor::damping': { slot: 'damping' },
    },
    code(w, settings, h) {
      const model = w.slot('model') ?? settings.motorModel;
      return [
        ...(model ? [`joint.set_motor_model(JointAxis::LinX, MotorModel::${model});`] : []),
        w.line(['stiffness', 'damping'], (k, c) => `joint.set_motor_position(JointAxis::LinX, 0.0, ${k}, ${c});  // target, stiffness, damping`),
        ...(isNumber(h) ? [`integration_parameters.dt = ${decimal(h)};`] : []),
        ...(isNumber(settings.numSolverIterations)
          ? [`integration_parameters.num_solver_iterations = NonZeroUsize::new(${settings.numSolverIterations}).unwrap();`] : []),
        ...(isNumber(settings.numInternalPgsIterations)
          ? [`integration_parameters.num_internal_pgs_iterations = ${settings.numInternalPgsIterations};`] : []),
        ...(isNumber(settings.additionalSolverIterations) || isNumber(settings.linearDamping)
          ? [`let body = RigidBodyBuilder::dynamic()${isNumber(settings.additionalSolverIterations) ? `.additional_solver_iterations(${settings.additionalSolverIterations})` : ''}${isNumber(settings.linearDamping) ? `.linear_damping(${decimal(settings.linearDamping)})` : ''};`]
          : []),
      ];
    },
  },
  ode: {
    label: 'ODE', language: 'C', comment: slashes, literal: String, fields: odeFields,
    code(w, settings, h) {
      const setter = ODE_SETTERS[settings.joint] ?? 'dJointSetDBallParam';
      const quick = settings.stepper === 'dWorldQuickStep';
      return [
        ...w.known().map((slot) => w.line([slot], (v) => `${setter}(joint, ${slot}, ${v});`)),
        ...(quick && isNumber(settings.dWorldSetQuickStepNumIterations) ? [`dWorldSetQuickStepNumIterations(world, ${settings.dWorldSetQuickStepNumIterations});`] : []),
        ...(quick && isNumber(settings.dWorldSetQuickStepW) ? [`dWorldSetQuickStepW(world, ${settings.dWorldSetQuickStepW});`] : []),
        ...(isNumber(h) ? [`${quick ? 'dWorldQuickStep' : 'dWorldStep'}(world, ${h});`] : []),
      ];
    },
  },
  bullet: {
    label: 'Bullet', language: 'C++', comment: slashes, literal: cFloat,
    fields: {
      'btGeneric6DofSpring2Constraint::setStiffness': { slot: 'stiffness', unit: 'N/m' },
      'btGeneric6DofSpring2Constraint::setDamping': { slot: 'damping', unit: 'N s/m' },
      'setStiffness(limitIfNeeded)': { slot: 'limitStiffness' },
      'setDamping(limitIfNeeded)': { slot: 'limitDamping' },
      'btGeneric6DofSpring2Constraint::setParam(BT_CONSTRAINT_STOP_ERP)': { slot: 'stopErp' },
      'btGeneric6DofSpring2Constraint::setParam(BT_CONSTRAINT_STOP_CFM)': { slot: 'stopCfm' },
    },
    code(w, settings, h) {
      const flag = (slot) => (w.slot(slot) === 'false' ? 'false' : 'true');
      const spring = w.has('stiffness') || w.has('damping');
      return [
        ...(spring ? [
          'spring->enableSpring(0, true);  // axis 0: linear x',
          w.line(['stiffness'], (k) => `spring->setStiffness(0, ${k}, ${flag('limitStiffness')});`),
          w.line(['damping'], (c) => `spring->setDamping(0, ${c}, ${flag('limitDamping')});`),
        ] : []),
        ...(w.has('stopErp') || w.has('stopCfm') ? [
          'spring->setLimit(0, 0, 0);  // axis 0 locked: its row is the soft one',
          w.line(['stopErp'], (v) => `spring->setParam(BT_CONSTRAINT_STOP_ERP, ${v}, 0);`),
          w.line(['stopCfm'], (v) => `spring->setParam(BT_CONSTRAINT_STOP_CFM, ${v}, 0);`),
        ] : []),
        ...(isNumber(settings.m_numIterations) ? [`dynamicsWorld->getSolverInfo().m_numIterations = ${settings.m_numIterations};`] : []),
        ...(isNumber(h) ? [`dynamicsWorld->stepSimulation(${cFloat(h)}, 1, ${cFloat(h)});  // timeStep, maxSubSteps, fixedTimeStep`] : []),
      ];
    },
  },
  physx: {
    label: 'PhysX', language: 'C++', comment: slashes, literal: cFloat,
    fields: {
      'PxD6JointDrive::stiffness': { slot: 'stiffness' },
      'PxD6JointDrive::damping': { slot: 'damping' },
      'PxD6JointDrive::isAcceleration': { slot: 'acceleration' },
    },
    code(w, settings, h) {
      const acceleration = w.slot('acceleration') === 'true' || w.slot('acceleration') === 'acceleration';
      return [
        'joint->setMotion(physx::PxD6Axis::eX, physx::PxD6Motion::eFREE);',
        w.line(['stiffness', 'damping'], (k, c) => `joint->setDrive(physx::PxD6Drive::eX, physx::PxD6JointDrive(${k}, ${c}, PX_MAX_F32, ${acceleration}));`),
        'joint->setDrivePosition(physx::PxTransform(physx::PxIdentity));',
        ...(isNumber(h) ? [`scene->simulate(${cFloat(h)});`] : []),
      ];
    },
  },
  chipmunk: {
    label: 'Chipmunk 7', language: 'C', comment: slashes, literal: decimal,
    fields: {
      cpDampedSpringSetStiffness: { slot: 'stiffness', unit: 'N/m' },
      cpDampedSpringSetDamping: { slot: 'damping', unit: 'N s/m' },
    },
    code(w, settings, h) {
      return [
        'cpConstraint *spring = cpSpaceAddConstraint(space, cpDampedSpringNew(staticBody, body, cpvzero, cpvzero, 0.0, 0.0, 0.0));',
        w.line(['stiffness'], (k) => `cpDampedSpringSetStiffness(spring, ${k});`),
        w.line(['damping'], (c) => `cpDampedSpringSetDamping(spring, ${c});`),
        ...(isNumber(settings.cpSpaceSetIterations) ? [`cpSpaceSetIterations(space, ${settings.cpSpaceSetIterations});`] : []),
        ...(isNumber(settings.cpSpaceSetDamping) ? [`cpSpaceSetDamping(space, ${decimal(settings.cpSpaceSetDamping)});`] : []),
        ...(isNumber(h) ? [`cpSpaceStep(space, ${decimal(h)});`] : []),
      ];
    },
  },
  godot_2d: {
    label: 'Godot 3.2 2-D', language: 'GDScript', comment: hashes, literal: decimal,
    fields: {
      'DampedSpringJoint2D.stiffness': { slot: 'stiffness', unit: 'N/m' },
      'DampedSpringJoint2D.damping': { slot: 'damping', unit: 'N s/m' },
      'PinJoint2D.softness': { slot: 'softness', unit: '1/kg' },
      'PinJoint2D.bias': { slot: 'bias' },
    },
    code(w, settings, h) {
      const damp = isNumber(settings.linear_damp) ? decimal(settings.linear_damp) : undefined;
      const pin = w.has('softness') || w.has('bias');
      const joint = pin ? 'PinJoint2D' : 'DampedSpringJoint2D';
      const fields = pin ? ['softness', 'bias'] : ['stiffness', 'damping'];
      return [
        ...fields.map((f) => w.line([f], (v) => `$${joint}.${f} = ${v}`)),
        ...(damp ? [`$RigidBody2D.linear_damp = ${damp}`, `$RigidBody2D.angular_damp = ${damp}`] : []),
        ...(isNumber(h) ? [`Engine.iterations_per_second = ${Math.round(1 / h)}  # physics steps per second: one step of h`] : []),
        ...tscnLines(joint, fields.map((f) => [f, w.slot(f)])),
      ];
    },
  },
  godot_3d: {
    label: 'Godot 3.2 3-D', language: 'GDScript', comment: hashes, literal: decimal,
    fields: {
      'Generic6DOFJoint.linear_spring_x/stiffness': { slot: 'stiffness', unit: 'N/m' },
      'Generic6DOFJoint.linear_spring_x/damping': { slot: 'damping', unit: 'N s/m' },
    },
    code(w, settings, h) {
      const joint = '$Generic6DOFJoint';
      const damp = settings.linear_damp;
      return [
        ...(settings['physics/3d/physics_engine'] === 'GodotPhysics'
          ? [hashes('GodotPhysics 3-D ignores joint springs in Godot 3.2: set physics/3d/physics_engine to DEFAULT (Bullet)')] : []),
        `${joint}.set_flag_x(Generic6DOFJoint.FLAG_ENABLE_LINEAR_LIMIT, false)`,
        `${joint}.set_flag_x(Generic6DOFJoint.FLAG_ENABLE_LINEAR_SPRING, true)`,
        w.line(['stiffness'], (k) => `${joint}.set_param_x(Generic6DOFJoint.PARAM_LINEAR_SPRING_STIFFNESS, ${k})`),
        w.line(['damping'], (c) => `${joint}.set_param_x(Generic6DOFJoint.PARAM_LINEAR_SPRING_DAMPING, ${c})`),
        ...(isNumber(damp) ? [`$RigidBody.linear_damp = ${decimal(damp)}  # added to the project's default_linear_damp when >= 0`] : []),
        ...(isNumber(h) ? [`Engine.iterations_per_second = ${Math.round(1 / h)}  # physics steps per second: one step of h`] : []),
        ...tscnLines('Generic6DOFJoint', [['linear_limit_x/enabled', 'false'], ['linear_spring_x/enabled', 'true'],
          ['linear_spring_x/stiffness', w.slot('stiffness')], ['linear_spring_x/damping', w.slot('damping')]]),
      ];
    },
  },
  matter_js: {
    label: 'matter.js', language: 'JavaScript', comment: slashes, literal: String,
    fields: {
      'Constraint.stiffness': { slot: 'stiffness' },
      'Constraint.damping': { slot: 'damping' },
    },
    // A runnable script given Matter, the body and its anchor: the engine, the body's air friction, the
    // constraint and one update of 1000 h ms.
    code(w, settings, h) {
      return [
        `const engine = Matter.Engine.create({ constraintIterations: ${isNumber(settings.constraintIterations) ? settings.constraintIterations : 2} });`,
        ...(isNumber(settings.frictionAir) ? [`body.frictionAir = ${settings.frictionAir};  // Body.frictionAir of the constrained body`] : []),
        w.line(['stiffness', 'damping'], (k, c) =>
          `const spring = Matter.Constraint.create({ pointA, bodyB: body, pointB, length, stiffness: ${k}, damping: ${c} });`),
        'Matter.Composite.add(engine.world, [body, spring]);',
        ...(isNumber(h) ? [`Matter.Engine.update(engine, ${1000 * h});  // delta in ms, every step`] : []),
      ];
    },
  },
  planck_js: {
    label: 'planck.js', language: 'JavaScript', comment: slashes, literal: String,
    fields: Object.fromEntries(['DistanceJointDef', 'WheelJointDef', 'MouseJointDef'].flatMap((def) => [
      [`${def}.frequencyHz`, { slot: 'frequencyHz', unit: 'Hz' }],
      [`${def}.dampingRatio`, { slot: 'dampingRatio' }],
    ]).concat([['MouseJointDef.maxForce', { slot: 'maxForce', unit: 'N' }]])),
    // A runnable script given planck, world, ground, body and the joint's anchors (or the mouse's target):
    // the joint with the answer's numbers, and one world step.
    code(w, settings, h) {
      const joint = settings.joint === 'wheel' ? 'WheelJoint' : settings.joint === 'mouse' ? 'MouseJoint' : 'DistanceJoint';
      const tail = { DistanceJoint: 'ground, body, anchorA, anchorB', WheelJoint: 'ground, body, anchorA, axis', MouseJoint: 'ground, body, target' }[joint];
      const extra = joint === 'DistanceJoint' ? ', length' : joint === 'WheelJoint' ? ', enableMotor: false' : w.has('maxForce') ? `, maxForce: ${w.slot('maxForce') ?? 0}` : '';
      return [
        w.line(['frequencyHz', 'dampingRatio'], (f, z) =>
          `const joint = world.createJoint(new planck.${joint}({ frequencyHz: ${f}, dampingRatio: ${z}${extra} }, ${tail}));`),
        ...(isNumber(h) ? [`world.step(${h}, ${isNumber(settings.velocityIterations) ? settings.velocityIterations : 8}, 3);  // dt, velocityIterations, positionIterations`] : []),
      ];
    },
  },
  cannon_es: {
    label: 'cannon-es', language: 'JavaScript', comment: slashes, literal: String,
    fields: {
      'Spring.stiffness': { slot: 'stiffness', unit: 'N/m' },
      'Spring.damping': { slot: 'damping', unit: 'N s/m' },
      'setSpookParams.stiffness': { slot: 'spookStiffness', unit: 'N/m' },
      'setSpookParams.relaxation': { slot: 'relaxation', unit: 'steps' },
    },
    // A runnable script given CANNON, world, ground, body (and the spring's restLength and local anchors, or
    // the constraint's distance): the body's damping, the joint with the answer's numbers, one world step.
    code(w, settings, h) {
      const damp = isNumber(settings.linearDamping) ? settings.linearDamping : undefined;
      const spook = w.has('spookStiffness') || w.has('relaxation');
      const bake = isNumber(settings.spookTimeStep) && settings.spookTimeStep > 0 ? settings.spookTimeStep : h;
      return [
        ...(damp !== undefined ? [`body.linearDamping = ${damp};`, `body.angularDamping = ${damp};`] : []),
        ...(isNumber(settings.iterations) ? [`world.solver.iterations = ${settings.iterations};`] : []),
        ...(spook
          ? ['const constraint = new CANNON.DistanceConstraint(ground, body, distance);',
            w.line(['spookStiffness', 'relaxation'], (k, d) =>
              `constraint.distanceEquation.setSpookParams(${k}, ${d}, ${isNumber(bake) ? bake : 'world.dt'});  // stiffness, relaxation, the timeStep they are baked for`),
            'world.addConstraint(constraint);']
          : [w.line(['stiffness', 'damping'], (k, c) =>
            `const spring = new CANNON.Spring(ground, body, { restLength, localAnchorA, localAnchorB, stiffness: ${k}, damping: ${c} });`),
          "world.addEventListener('postStep', () => spring.applyForce());  // the force for the next step"]),
        ...(isNumber(h) ? [`world.step(${h});  // a fixed step of h`] : []),
      ];
    },
  },
};

/// Display names of the engines, including the keys that carry only the older fields.
export const ENGINE_LABELS = {
  ...Object.fromEntries(Object.entries(ENGINE_SYNTAX).map(([k, s]) => [k, s.label])),
  ode_bullet: 'ODE / Bullet',
};

// ---- building a snippet ----------------------------------------------------------------------------

function why(value) {
  return value === null ? 'null in the answer: the engine cannot represent it' : 'not in this answer';
}

/// The writer a syntax's code() uses over one set of values (parameters or exact).
function writer(syntax, values) {
  const slots = {};
  const units = {};
  const unknown = [];
  for (const [name, value] of Object.entries(values)) {
    const field = syntax.fields[name];
    if (!field) {
      unknown.push([name, value]);
      continue;
    }
    slots[field.slot] = { name, value };
    units[field.slot] = field.unit;
  }
  const literal = (v) => (typeof v === 'number' ? syntax.literal(v) : String(v));
  const usable = (s) => slots[s] && (typeof slots[s].value === 'string' || isNumber(slots[s].value));
  const w = {
    has: (s) => s in slots,
    known: () => Object.keys(slots),
    slot: (s) => (usable(s) ? literal(slots[s].value) : undefined),
    missing: (names) => syntax.comment(names.filter((s) => !usable(s))
      .map((s) => `${slots[s]?.name ?? s}: no value (${why(slots[s]?.value)})`).join('; ')),
    line(names, make) {
      if (!names.every(usable)) return w.missing(names);
      const code = make(...names.map(w.slot));
      const unit = names.length === 1 ? units[names[0]] : undefined;
      return unit ? `${code}  ${syntax.comment(unit)}` : code;
    },
    unknown: () => unknown.map(([name, value]) => syntax.comment(
      `${name} = ${value === null || value === undefined ? `no value (${why(value)})` : value} (no API line for this field in web/engines.js)`)),
  };
  return w;
}

/// Whether an engine's answer carries the modelled report (parameters, predicted, exact).
export function isModelled(e) {
  return !!e && typeof e.parameters === 'object' && e.parameters !== null;
}

/// The snippet to paste for engine `key`: `which` = 'exact' (the values that make the engine do what was
/// asked) or 'plain' (the engine's field names for softtune's k, c). An engine without a model gets its
/// older fields' snippet (legacySnippet), one the page has no syntax for its JSON.
export function engineSnippet(key, e, tune, which) {
  const syntax = ENGINE_SYNTAX[key];
  if (!syntax || !isModelled(e)) return legacySnippet(key, e);
  const values = which === 'exact' ? e.exact : e.parameters;
  const settings = e.settings ?? {};
  const requested = comparedTo(e, tune);
  const predicted = which === 'exact' ? e.exact_predicted : e.predicted;
  const c = syntax.comment;
  if (!values) {
    return [c(`${syntax.label}: no exact values. ${notesFor(e, 'exact').join(' ') || 'The engine cannot do what was asked.'}`),
      c('Switch to the plain values to see what softtune would type, and what the engine does with it.')].join('\n');
  }
  const v = verdict(predicted, requested);
  const head = [c(`${syntax.label} (${syntax.language}), ${which === 'exact' ? 'exact' : 'plain'} values: ${describeVerdict(v)}`)];
  if (e.note) head.push(c(e.note));
  if (v.state !== 'ok') head.push(...notesFor(e, which).map(c));
  const w = writer(syntax, values);
  return [...head, ...syntax.code(w, settings, tune.h), ...w.unknown()].join('\n');
}

/// What an engine's prediction is held against: the request, or what the answer names for that engine
/// (`compared_to`: a solved scene joint's per-joint model is held against Box2D 2.4's joint alone).
export function comparedTo(e, tune) {
  return e?.compared_to ?? tune?.requested ?? {};
}

// ---- the verdict of a prediction -------------------------------------------------------------------

/// A prediction against the request: state 'blows_up' (unstable), 'cannot' (asked to oscillate, and the
/// engine shows no frequency: rigid or no spring), 'none' (no prediction) or 'ok'; with the frequency error
/// in percent and the damping ratio's error as a difference (zeta may be asked 0).
export function verdict(predicted, requested) {
  if (!predicted) return { state: 'none', frequencyError: null, dampingError: null };
  const f = predicted.frequency_hz, z = predicted.damping_ratio;
  const rf = requested?.frequency_hz, rz = requested?.damping_ratio;
  const frequencyError = isNumber(f) && isNumber(rf) && rf !== 0 ? (100 * (f - rf)) / rf : null;
  const dampingError = isNumber(z) && isNumber(rz) ? z - rz : null;
  let state = 'ok';
  if (predicted.stable === false) state = 'blows_up';
  else if (isNumber(rf) && rf > 0 && !isNumber(f)) state = 'cannot';
  return { state, frequencyError, dampingError, predicted };
}

/// A difference with its sign and three decimals, rounded first so round-off reads +0.000, not -0.000.
export function formatDifference(d) {
  if (d === null || d === undefined) return '—';
  const shown = Math.round(d * 1000) / 1000 || 0;
  return `${shown < 0 ? '−' : '+'}${Math.abs(shown).toFixed(3)}`;
}

export function describeVerdict(v) {
  const p = v.predicted;
  if (v.state === 'none') return 'no prediction';
  if (v.state === 'blows_up') return `BLOWS UP (spectral radius ${fmt(p.spectral_radius)} per step)`;
  if (v.state === 'cannot') return 'CANNOT: the engine shows no spring with these values';
  return `predicted ${fmt(p.frequency_hz)} Hz, damping ratio ${fmt(p.damping_ratio)}`;
}

const EXACT_WARNING = /exact|inexact|cannot|unrepresent/;

/// Every warning about engine `key`: its report's own and the answer's top-level ones naming it, once each.
export function engineWarnings(tune, key) {
  const all = [...(tune.engines?.[key]?.warnings ?? []), ...(tune.warnings ?? []).filter((w) => w && w.engine === key)];
  return all.filter((w, i) => w && w.message && all.findIndex((x) => x && x.message === w.message) === i);
}

/// The warning messages that explain one set of values: those about exactness for 'exact', the others
/// for 'plain'; every warning of the engine when none matches.
export function notesFor(e, which) {
  const all = (e.warnings ?? []).filter((w) => w && w.message);
  const chosen = all.filter((w) => EXACT_WARNING.test(w.code ?? '') === (which === 'exact'));
  return (chosen.length ? chosen : all).map((w) => w.message);
}

// ---- engines that carry only the older fields ------------------------------------------------------

// A null in an older field: the line that needs it becomes a comment saying why.
const NULL = '\u0000null';
const literalOr = (literal) => (v) => (isNumber(v) ? literal(v) : NULL);
const f = literalOr(cFloat), d = literalOr(String), r = literalOr(decimal);

/// Snippets from the fields every answer had before the engine models (stiffness, hertz, solref...).
const LEGACY = {
  box2d_v2_4: (e) => [`jd.stiffness = ${f(e.stiffness)};  // N/m`, `jd.damping = ${f(e.damping)};  // N s/m`],
  box2d_v3: (e) => ['def.enableSpring = true;', `def.hertz = ${f(e.hertz)};`, `def.dampingRatio = ${f(e.damping_ratio)};`],
  jolt: (e) => [
    `JPH::SpringSettings(JPH::ESpringMode::FrequencyAndDamping, ${f(e.frequency_and_damping?.frequency)}, ${f(e.frequency_and_damping?.damping)});`,
    `JPH::SpringSettings(JPH::ESpringMode::StiffnessAndDamping, ${f(e.stiffness_and_damping?.stiffness)}, ${f(e.stiffness_and_damping?.damping)});`],
  mujoco: (e) => [`<!-- on the soft constraint, in the ${e.form} form -->`,
    `<equality><connect body1="A" body2="B" anchor="0 0 0" solref="${(e.solref ?? [null, null]).map(d).join(' ')}"/></equality>`],
  ode_bullet: (e) => [`dJointSetBallParam(joint, dParamERP, ${d(e.erp)});`, `dJointSetBallParam(joint, dParamCFM, ${d(e.cfm)});`,
    `constraint->setParam(BT_CONSTRAINT_STOP_ERP, ${f(e.erp)}, 0);  // Bullet`, `constraint->setParam(BT_CONSTRAINT_STOP_CFM, ${f(e.cfm)}, 0);  // Bullet`],
  physx: (e) => [
    `physx::PxD6JointDrive(${f(e.acceleration?.stiffness)}, ${f(e.acceleration?.damping)}, PX_MAX_F32, true);  // acceleration drive`,
    `physx::PxD6JointDrive(${f(e.force?.stiffness)}, ${f(e.force?.damping)}, PX_MAX_F32, false);  // force drive`],
  rapier: (e) => [
    `joint.set_motor_model(JointAxis::LinX, MotorModel::AccelerationBased).set_motor_position(JointAxis::LinX, 0.0, ${r(e.acceleration_based?.stiffness)}, ${r(e.acceleration_based?.damping)});`,
    `joint.set_motor_model(JointAxis::LinX, MotorModel::ForceBased).set_motor_position(JointAxis::LinX, 0.0, ${r(e.force_based?.stiffness)}, ${r(e.force_based?.damping)});`],
};

/// Keys whose older fields the modelled engines replace: hidden once every one of those is modelled.
const SUPERSEDED = { ode_bullet: ['ode', 'bullet'] };

export function legacySnippet(key, e) {
  const make = LEGACY[key];
  if (!make) return JSON.stringify(e ?? null, null, 1);
  const comment = key === 'mujoco' ? xmlComment : slashes;
  const lines = make(e ?? {}).map((line) => (line.includes(NULL)
    ? comment(`no value (null in the answer: not representable): ${line.replaceAll(NULL, 'null')}`) : line));
  return [comment('not modelled yet: softtune\'s own numbers, not this engine\'s step'), ...lines].join('\n');
}

/// The older fields as [dotted name, value] pairs, for engines without a model.
export function legacyFields(e, prefix = '') {
  if (!e || typeof e !== 'object') return [];
  return Object.entries(e).flatMap(([k, v]) => {
    const name = Array.isArray(e) ? `${prefix}[${k}]` : prefix ? `${prefix}.${k}` : k;
    return v !== null && typeof v === 'object' ? legacyFields(v, name) : [[name, v]];
  });
}

/// The engines to list, in the answer's order, without older keys that the modelled engines replace.
export function engineKeys(tune) {
  const engines = tune.engines ?? {};
  return Object.keys(engines).filter((key) => !(SUPERSEDED[key]?.every((k) => isModelled(engines[k]))));
}

/// An answer field's short name for a table cell: the member after the last "::" (the full name is the title).
export function shortName(name) {
  const i = name.lastIndexOf('::');
  return i < 0 ? name : name.slice(i + 2);
}
