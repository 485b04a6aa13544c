# Runs softtune's cases in Godot 3.2's physics, many per process (tests/engines/godot/godot_conformance_test.cpp
# writes them): `godot3-server --fixed-fps RATE -s godot_run.gd` with SOFTTUNE_CASES naming the case file and
# SOFTTUNE_OUT the output. Every case runs at once in the one space of its dimension, each on its own static
# body (no shapes, so nothing collides); the physics rate is RATE, one physics step per frame.
#
# A case line: id dim body m x0 steps stiffness damping linear_damp [joint]
#   (dim 2, joint 1: a PinJoint2D, and the two values are its softness and bias)
#   dim 2: a RigidBody2D on a DampedSpringJoint2D (Physics2DServer, what the node calls) from a static anchor
#   REST along -x, rest length REST (a rest length of 0 would turn the damper's direction, the anchors'
#   direction, through 90 degrees whenever the anchors pass each other; a short one keeps float's rounding of
#   the distance small against x0); the body starts with its anchor at
#   (x0, 0). body 0: a point of mass m; 1: the plank (mass 2 m, inertia 2 m 0.25, anchor 0.5 m off its
#   centre along y), so it turns as it swings. The stretch is the anchors' distance minus REST.
#   dim 3: a RigidBody (with a sphere shape on no collision layer: GodotPhysics needs a shape for its inertia)
#   on a Generic6DOFJoint from a static body, both frames at the origin, the X linear limit off and the X
#   linear spring on (PhysicsServer's generic_6dof_joint_*, what the node calls; the spring's flag and
#   parameters by number, as Godot 3.2 does not bind their constants on PhysicsServer), moved by x0 along X
#   after the first physics step, as the 2-D bodies are.
#   body 0 only. The stretch is the body's X. The backend is the project's (godot_conformance_test runs
#   Bullet and GodotPhysics in two project folders).
# Output: one line per case, "id x[0] x[1] ... x[steps]": the stretch over x0 before each physics step and
# after the last (SceneTree._iteration runs before each Physics2DServer step).
extends SceneTree

const REST = 0.1  # m, the spring's rest length

var cases = []
var done = 0
var out_lines = []

func _body_2d(space, m, plank, x0):
	var body = Physics2DServer.body_create()
	Physics2DServer.body_set_mode(body, Physics2DServer.BODY_MODE_RIGID)
	Physics2DServer.body_set_space(body, space)
	var mass = 2.0 * m if plank else m
	Physics2DServer.body_set_param(body, Physics2DServer.BODY_PARAM_MASS, mass)
	Physics2DServer.body_set_param(body, Physics2DServer.BODY_PARAM_GRAVITY_SCALE, 0.0)
	Physics2DServer.body_set_state(body, Physics2DServer.BODY_STATE_CAN_SLEEP, false)
	return body

# A PinJoint2D case, with nodes (Godot 3.2 binds neither pin_joint_set_param nor PIN_JOINT_SOFTNESS on
# Physics2DServer; the node sets them): a RigidBody2D at rest with its anchor at the origin, a StaticBody2D,
# and a PinJoint2D at the origin joining them (Joint2D needs both nodes).
func _add_pin_2d(c, f):
	var plank = int(f[2]) == 1
	var m = float(f[3])
	c.offset = 0.5 if plank else 0.0
	var body = RigidBody2D.new()
	body.mass = 2.0 * m if plank else m
	body.gravity_scale = 0.0
	body.linear_damp = float(f[8])
	body.angular_damp = float(f[8])
	body.can_sleep = false
	body.position = Vector2(0, -c.offset)
	get_root().add_child(body)
	var ground = StaticBody2D.new()
	get_root().add_child(ground)
	var pin = PinJoint2D.new()
	get_root().add_child(pin)
	pin.softness = float(f[6])
	pin.bias = float(f[7])
	pin.node_a = pin.get_path_to(body)
	pin.node_b = pin.get_path_to(ground)
	c.body = body.get_rid()
	c.node = body
	c.f = f

func _add_2d(c, f):
	c.pin = f.size() > 9 and int(f[9]) == 1
	if c.pin:
		_add_pin_2d(c, f)
		return
	var space = get_root().get_world_2d().space
	var ground = Physics2DServer.body_create()
	Physics2DServer.body_set_mode(ground, Physics2DServer.BODY_MODE_STATIC)
	Physics2DServer.body_set_space(ground, space)
	var plank = int(f[2]) == 1
	var m = float(f[3])
	var x0 = float(f[4])
	var offset = 0.5 if plank else 0.0
	var body = _body_2d(space, m, plank, x0)
	c.body = body
	c.f = f
	c.offset = offset
	c.ground = ground

# The second half, one physics step later: Godot 3.2's Body2DSW::update_inertias sets the inverse mass from
# the mass only when the inertia is its own (no user inertia), so the plank's mass must be taken by one step
# before its inertia is set (set first, the body would move as if of 1 kg).
func _join_2d(c):
	var f = c.f
	var body = c.body
	var plank = int(f[2]) == 1
	var m = float(f[3])
	var x0 = float(f[4])
	var offset = c.offset
	if plank:
		Physics2DServer.body_set_param(body, Physics2DServer.BODY_PARAM_INERTIA, 2.0 * m * 0.25)
	if c.pin:
		Physics2DServer.body_set_state(body, Physics2DServer.BODY_STATE_TRANSFORM, Transform2D(0, Vector2(x0, -offset)))
		return
	var ground = c.ground
	# The joint is built at rest; then the body is moved by x0.
	Physics2DServer.body_set_state(body, Physics2DServer.BODY_STATE_TRANSFORM, Transform2D(0, Vector2(0, -offset)))
	var joint = Physics2DServer.damped_spring_joint_create(Vector2(-REST, 0), Vector2(0, 0), ground, body)
	Physics2DServer.damped_string_joint_set_param(joint, Physics2DServer.DAMPED_STRING_REST_LENGTH, REST)
	Physics2DServer.damped_string_joint_set_param(joint, Physics2DServer.DAMPED_STRING_STIFFNESS, float(f[6]))
	Physics2DServer.damped_string_joint_set_param(joint, Physics2DServer.DAMPED_STRING_DAMPING, float(f[7]))
	Physics2DServer.body_set_param(body, Physics2DServer.BODY_PARAM_LINEAR_DAMP, float(f[8]))
	Physics2DServer.body_set_param(body, Physics2DServer.BODY_PARAM_ANGULAR_DAMP, float(f[8]))
	Physics2DServer.body_set_state(body, Physics2DServer.BODY_STATE_TRANSFORM, Transform2D(0, Vector2(x0, -offset)))
	c.joint = joint

const G6DOF_FLAG_ENABLE_LINEAR_LIMIT = 0
const G6DOF_FLAG_ENABLE_LINEAR_SPRING = 3   # Generic6DOFJoint.FLAG_ENABLE_LINEAR_SPRING
const G6DOF_LINEAR_SPRING_STIFFNESS = 7     # Generic6DOFJoint.PARAM_LINEAR_SPRING_STIFFNESS
const G6DOF_LINEAR_SPRING_DAMPING = 8       # Generic6DOFJoint.PARAM_LINEAR_SPRING_DAMPING

func _add_3d(c, f):
	var space = get_root().get_world().space
	var ground = PhysicsServer.body_create(PhysicsServer.BODY_MODE_STATIC)
	PhysicsServer.body_set_space(ground, space)
	var body = PhysicsServer.body_create(PhysicsServer.BODY_MODE_RIGID)
	var shape = PhysicsServer.shape_create(PhysicsServer.SHAPE_SPHERE)
	PhysicsServer.shape_set_data(shape, 0.5)
	PhysicsServer.body_add_shape(body, shape)
	PhysicsServer.body_set_collision_layer(body, 0)
	PhysicsServer.body_set_collision_mask(body, 0)
	PhysicsServer.body_set_space(body, space)
	PhysicsServer.body_set_param(body, PhysicsServer.BODY_PARAM_MASS, float(f[3]))
	PhysicsServer.body_set_param(body, PhysicsServer.BODY_PARAM_GRAVITY_SCALE, 0.0)
	PhysicsServer.body_set_param(body, PhysicsServer.BODY_PARAM_LINEAR_DAMP, float(f[8]))
	PhysicsServer.body_set_state(body, PhysicsServer.BODY_STATE_CAN_SLEEP, false)
	var joint = PhysicsServer.joint_create_generic_6dof(ground, Transform(), body, Transform())
	PhysicsServer.generic_6dof_joint_set_flag(joint, Vector3.AXIS_X, G6DOF_FLAG_ENABLE_LINEAR_LIMIT, false)
	PhysicsServer.generic_6dof_joint_set_flag(joint, Vector3.AXIS_X, G6DOF_FLAG_ENABLE_LINEAR_SPRING, true)
	PhysicsServer.generic_6dof_joint_set_param(joint, Vector3.AXIS_X, G6DOF_LINEAR_SPRING_STIFFNESS, float(f[6]))
	PhysicsServer.generic_6dof_joint_set_param(joint, Vector3.AXIS_X, G6DOF_LINEAR_SPRING_DAMPING, float(f[7]))
	c.body = body
	c.joint = joint
	c.shape = shape

func _stretch(c):
	if c.dim == 3:
		return PhysicsServer.body_get_state(c.body, PhysicsServer.BODY_STATE_TRANSFORM).origin.x
	var t = Physics2DServer.body_get_state(c.body, Physics2DServer.BODY_STATE_TRANSFORM)
	if c.pin:
		return t.xform(Vector2(0, c.offset)).x
	return t.xform(Vector2(0, c.offset)).distance_to(Vector2(-REST, 0)) - REST

func _init():
	var rate = int(OS.get_environment("SOFTTUNE_RATE"))
	Engine.iterations_per_second = rate
	var file = File.new()
	if file.open(OS.get_environment("SOFTTUNE_CASES"), File.READ) != OK:
		printerr("godot_run: cannot read SOFTTUNE_CASES")
		quit(1)
		return
	while not file.eof_reached():
		var line = file.get_line().strip_edges()
		if line == "":
			continue
		var f = line.split(" ", false)
		var c = {"id": f[0], "dim": int(f[1]), "steps": int(f[5]), "x0": float(f[4]), "x": []}
		if c.dim == 2:
			_add_2d(c, f)
		else:
			_add_3d(c, f)
		cases.append(c)
	file.close()

var joined = false

func _iteration(_delta):
	if not joined:
		# The first step ran with every body free and at rest; now the joints.
		if Engine.get_physics_frames() < 1:
			return false
		for c in cases:
			if c.dim == 2:
				_join_2d(c)
			else:
				PhysicsServer.body_set_state(c.body, PhysicsServer.BODY_STATE_TRANSFORM, Transform(Basis(), Vector3(c.x0, 0, 0)))
		joined = true
	for c in cases:
		if c.x.size() <= c.steps:
			c.x.append(_stretch(c))
			if c.x.size() == c.steps + 1:
				done += 1
	if done == cases.size():
		var out = File.new()
		out.open(OS.get_environment("SOFTTUNE_OUT"), File.WRITE)
		for c in cases:
			var parts = PoolStringArray([c.id])
			for x in c.x:
				parts.append("%.12f" % (x / c.x0))
			out.store_line(parts.join(" "))
		out.close()
		quit(0)
	return false
