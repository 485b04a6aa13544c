#pragma once
// Tuning a scene in engine E (not Box2D 2.4): the springs of its modal groups (or of its tuned joints) are
// solved so that each target, measured by its probe in E's own run of the whole scene, has the requested
// frequency and damping ratio (docs/scene-backends.md, "Tuning in the engine").
//
// Box2D 2.4's tuning linearises the settled scene (linearise.h) because its state can be read and its step is
// known in closed form. Most engines' state cannot be set from outside and their step is not written down,
// so the engine's step is linearised by measurement instead: start from the Box2D 2.4 solve (tune_modes, or
// the joints' own tunings), run the scene in E up to the targets' window end with trial springs
// (RunOptions::springs), fit each target's probe (the runner's response fit), and take damped Gauss-Newton
// steps on (ln k, c / c0) per unknown with a finite-difference Jacobian, until every target is within
// kEngineFrequencyTolerance / kEngineDampingTolerance or kMaxEngineRuns runs have been spent.
//
// What is a target: a modal target (its measuring probe, the target's request); without modal tuning, a tuned
// joint's own-coordinate probe (joint_length / joint_angle on that joint, its request) -- when Box2D 2.4's own
// run of its per-joint solve meets that request within kPerJointClaim (a joint coupled to others, like the
// per-spring vehicle's, does not: its request is not the scene's response in any engine, so it is listed in
// coupled_probes and keeps Box2D's k, c).

#include <optional>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/scene/engine_tuning_result.h"
#include "softtune/scene/runner.h"
#include "softtune/scene/scene.h"

namespace softtune::scene {

/// Stop when every target is this close: |f / f_req - 1| and |zeta - zeta_req|.
inline constexpr double kEngineFrequencyTolerance = 0.005;
inline constexpr double kEngineDampingTolerance = 0.005;
/// Engine runs a solve may spend (each up to the targets' window end), the confirming run not counted.
inline constexpr int kMaxEngineRuns = 40;
/// Finite-difference steps of the Jacobian: in ln k, and in c as a fraction of its scale c0.
inline constexpr double kLnStiffnessStep = 0.02;
inline constexpr double kDampingStep = 0.02;
/// A Newton step is cut to this in ln k and in c / c0 (a damped step: the response is far from linear in k).
inline constexpr double kMaxLnStiffnessStep = 0.5;
inline constexpr double kMaxDampingStep = 0.5;
/// A tuned joint's own probe is a target when Box2D 2.4's run of its per-joint solve is this close to the
/// request (frequency relative, damping ratio absolute): the conformance bar.
inline constexpr double kPerJointClaimFrequency = 0.03;
inline constexpr double kPerJointClaimDamping = 0.05;

/// Whether run_scene tunes a scene in `backend` (engine_tune_scene below): a backend other than Box2D 2.4, no
/// springs given, and modal targets or tuned joints.
bool tunes_in_engine(const Scene& scene, const RunOptions& options);

/// Solves the springs for `scene` (passed validate_scene) in options.backend. `base` is the scene the runs use
/// (the modal solve's tuned scene, its modal_tuning removed; else the scene), `springs` the solved spring per
/// joint (indexed like scene.joints; empty entries: the joint's own), `modal` the Box2D 2.4 modal solve when
/// the scene has modal targets. Errors: the Box2D solve's refusal, or the engine's build refusal.
std::optional<FieldError> engine_tune_scene(const Scene& scene, const RunOptions& options, Scene& base,
                                            std::vector<std::optional<JointSpring>>& springs,
                                            std::optional<ModalTuningResult>& modal, EngineTuningResult& out,
                                            StageList& stages);

/// run_scene for a scene tunes_in_engine(): the solve, then the confirming full run of the solved springs in
/// the engine, its answer carrying modal_tuning (the groups' springs as solved in the engine) and engine_tuning.
SceneResult run_scene_tuned_in_engine(const Scene& scene, const RunOptions& options);

/// Fills each target's measured response from the confirming full run of the solved springs.
void confirm_engine_tuning(const SceneResult& run, EngineTuningResult& out);

}  // namespace softtune::scene
