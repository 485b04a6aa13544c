#pragma once
// The mass-ratio chain (sequential_impulse.h) as each engine's solver runs it: one ChainModel per engine,
// with the engine's defaults and the count a user turns (iterations or substeps). The sources read are
// cited in core/src/chain_solvers.cpp, beside the one-constraint models of core/src/engines/.
//   box2d_v2_4  velocity iterations (b2World::Step velocityIterations, testbed default 8), warm start
//               (b2World::SetWarmStarting, default on), one step, joint 1 then joint 2
//   box2d_v3    subStepCount (default 4); per substep warm start, solve (ITERATIONS 1), integrate
//               positions, relax (RELAX_ITERATIONS 1) on the moved bodies; link-weight joint first
//   jolt        mNumVelocitySteps (default 10) in one collision step, warm start on, linear damping
//               0.05 1/s (BodyCreationSettings default)
//   rapier      num_solver_iterations (default 4) = substeps; per substep one PGS pass, integrate, one
//               stabilization pass on the substep's right-hand side; warmstart_joints off by default

#include <optional>
#include <string_view>

#include "softtune/sequential_impulse.h"

namespace softtune {

/// "box2d_v2_4", "box2d_v3", "jolt", "rapier" (the engine model names of core/src/engines/).
std::string_view chain_solver_name(ChainSolver s);
std::optional<ChainSolver> chain_solver_from_name(std::string_view name);

/// The engine's own name of the count a user turns, e.g. "subStepCount".
std::string_view chain_count_name(ChainSolver s);
/// Its default in the engine.
int chain_default_count(ChainSolver s);
/// Whether the engine warm-starts the chain's joints by default.
bool chain_default_warm_start(ChainSolver s);

/// The chain as `solver` steps it with `count` (its chain_count_name) and warm starting on or off; each
/// joint tuned to omega (rad/s) and zeta on its own effective mass, step h (s, one engine step).
ChainModel chain_model(ChainSolver solver, int count, bool warm_start, double mass_ratio, double omega,
                       double zeta, double h);

}  // namespace softtune
