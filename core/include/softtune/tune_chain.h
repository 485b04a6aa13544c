#pragma once
// The tune request's chain question (chain_design.h) in the request's own terms: each joint tuned to the
// request's natural frequency and damping ratio (after any clamp), the engine step h of the request
// (1 / (fps substeps), the dt the engine models step with), and each solver's count and warm start read
// from the request's engine_settings (or the engine's defaults):
//   box2d_v2_4 velocityIterations; box2d_v3 subStepCount, enableWarmStarting; jolt numVelocitySteps,
//   collisionSteps, linearDamping; rapier numSolverIterations + additionalSolverIterations (joints not
//   warm-started: warmstart_joints is off by default and not a modelled setting).

#include "softtune/chain_design.h"
#include "softtune/tune.h"

namespace softtune {

/// The design request for `request.chain` (which must be set), with `result` the request's tune.
ChainDesignRequest chain_design_request(const TuneRequest& request, const TuneResult& result);

}  // namespace softtune
