// Each engine's solver on the two-joint chain (sequential_impulse.h), read in:
//   Box2D 2.4.1  b2World::Step(dt, velocityIterations, positionIterations), b2Island::Solve: warm start
//                (b2DistanceJoint::InitVelocityConstraints: m_impulse *= dtRatio, applied when
//                m_warmStarting), velocityIterations x SolveVelocityConstraints, then x += h v;
//                SolvePositionConstraints returns at once for a soft joint (m_minLength < m_maxLength).
//                The joint order is the island's (the model keeps ground-link first, what landed).
//   Box2D v3     (erincatto/box2d 617d32a) src/solver.c b2SolverStep: per substep integrate velocities,
//                warm start, solve (ITERATIONS 1, useBias true), integrate positions, relax
//                (RELAX_ITERATIONS 1, useBias false); src/distance_joint.c b2SolveDistanceJoint: the spring
//                branch reads the current separation (deltaPosition) and ignores useBias, so the relax sweep
//                sees the moved bodies; b2PrepareDistanceJoint zeroes joint->impulse once per step when
//                warm starting is off, so within a step the impulse is still carried between substeps;
//                b2MakeSoft's (biasRate, massScale, impulseScale) equal the talk's (beta / h, soft mass,
//                gamma term) at the substep h, so the Gauss-Seidel update is the same; src/constraint_graph.c
//                b2AssignJointColor: the dynamic-dynamic joint (link-weight) takes colour 0, the joint on
//                the static ground a colour from the end, and colours are solved in ascending order.
//   Jolt 5       PhysicsSystem::Update: per collision step ApplyForceTorqueAndDragInternal (v *= 1 - c_L h,
//                mLinearDamping 0.05), warm start (PhysicsSettings::mConstraintWarmStart true),
//                mNumVelocitySteps (10) x AxisConstraintPart::SolveVelocityConstraint over the island's
//                constraints in creation order, x += h v; position steps skip an active spring.
//   Rapier 0.35  (dimforge/rapier ccd01cd2) src/dynamics/integration_parameters.rs: num_solver_iterations 4
//                (substeps), num_internal_pgs_iterations 1, num_internal_stabilization_iterations 1,
//                warmstart_joints false ("re-applied at the start of each substep" when on);
//                staged_island_solver/solve.rs: PGS pass, integrate positions, stabilization pass; the
//                motor row's rhs is rebuilt only at the next substep (joint_constraint_helper.rs).
#include "softtune/chain_solvers.h"

namespace softtune {

std::string_view chain_solver_name(ChainSolver s) {
  switch (s) {
    case ChainSolver::box2d_v2_4: return "box2d_v2_4";
    case ChainSolver::box2d_v3: return "box2d_v3";
    case ChainSolver::jolt: return "jolt";
    case ChainSolver::rapier: return "rapier";
  }
  return "box2d_v2_4";
}

std::optional<ChainSolver> chain_solver_from_name(std::string_view name) {
  for (ChainSolver s : kAllChainSolvers) {
    if (chain_solver_name(s) == name) return s;
  }
  return std::nullopt;
}

std::string_view chain_count_name(ChainSolver s) {
  switch (s) {
    case ChainSolver::box2d_v2_4: return "velocityIterations";
    case ChainSolver::box2d_v3: return "subStepCount";
    case ChainSolver::jolt: return "mNumVelocitySteps";
    case ChainSolver::rapier: return "num_solver_iterations";
  }
  return "velocityIterations";
}

int chain_default_count(ChainSolver s) {
  switch (s) {
    case ChainSolver::box2d_v2_4: return 8;  // the testbed's and the manual's b2World::Step(dt, 8, 3)
    case ChainSolver::box2d_v3: return 4;    // b2World_Step subStepCount: "Usually 4"
    case ChainSolver::jolt: return 10;       // PhysicsSettings::mNumVelocitySteps
    case ChainSolver::rapier: return 4;      // IntegrationParameters::num_solver_iterations
  }
  return 1;
}

bool chain_default_warm_start(ChainSolver s) { return s != ChainSolver::rapier; }

ChainModel chain_model(ChainSolver solver, int count, bool warm_start, double mass_ratio, double omega, double zeta,
                       double h) {
  ChainModel m{1.0, mass_ratio, 1, omega, zeta, h, warm_start};
  switch (solver) {
    case ChainSolver::box2d_v2_4:
      m.iterations = count;
      break;
    case ChainSolver::box2d_v3:
      m.substeps = count;
      m.iterations = 1;        // solver.c ITERATIONS
      m.relax_iterations = 1;  // solver.c RELAX_ITERATIONS
      m.relax_uses_new_positions = true;
      m.weight_joint_first = true;
      m.substeps_carry_impulses = true;
      break;
    case ChainSolver::jolt:
      m.iterations = count;
      m.linear_damping = 0.05;  // BodyCreationSettings::mLinearDamping
      break;
    case ChainSolver::rapier:
      m.substeps = count;
      m.iterations = 1;        // num_internal_pgs_iterations
      m.relax_iterations = 1;  // num_internal_stabilization_iterations
      m.relax_uses_new_positions = false;
      break;
  }
  return m;
}

}  // namespace softtune
