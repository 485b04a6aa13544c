#pragma once
// A scene's modal tuning (ModalTuningSettings): linearise it at rest with the joints' own tunings as the first
// guess (linearise.h), solve the groups' k, c for the targeted modes (core modal_tune.h), then linearise again
// at the new rest state (the sag changes with k) and solve once more from there, until the springs settle.
// A first guess too soft to hold the body up (the page's slow requests: a per-spring tuning sags the car onto
// the road, where no mode moves the chassis) is stiffened until the mode is there; a request whose own springs
// sag the body onto its contacts is refused, naming the target. The solved k, c go back into
// the scene as each joint's equivalent standard designer request on its own mass (f = sqrt(k / m) / (2 pi),
// zeta = c / (2 sqrt(k m))), which the runner turns into exactly that k, c for Box2D; a probe a target measures
// is given the target's request, so its frequency_error and damping_ratio_error are against the mode asked.

#include <optional>
#include <string>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/modal_tune.h"
#include "softtune/scene/joint_tuning.h"
#include "softtune/scene/linearise.h"
#include "softtune/scene/scene.h"

namespace softtune::scene {

/// Linearise-and-solve rounds: each starts at the rest state of the last one's springs (the sag changes with
/// k); at least kMinModalRounds, then until the solved k and c change by less than kModalRoundTolerance
/// (in ln k, ln c) from one round to the next, at most kMaxModalRounds.
inline constexpr int kMinModalRounds = 2;
inline constexpr int kMaxModalRounds = 6;
inline constexpr double kModalRoundTolerance = 1e-4;
/// When the first guess (the joints' own tunings) leaves the targeted mode out -- the springs sag the body onto
/// the ground, which then holds it -- and the body hangs on a grouped joint (directly or through other joints),
/// the start is stiffened by this factor in k (sqrt of it in c: the same damping ratio) and the scene settled
/// again, at most kMaxStartStiffenings times (8^4 = 4096 x k: 64 x the frequency).
inline constexpr double kStartStiffening = 8.0;
inline constexpr int kMaxStartStiffenings = 4;

struct ModalTargetResult {
  std::string mode;                     ///< the mode's name in the solved system ("chassis heave")
  std::string probe;                    ///< the probe that measures it in Box2D (empty: none)
  double requested_frequency_hz = 0.0;  ///< Hz
  double requested_damping_ratio = 0.0;
  std::optional<modes::Pole> predicted; ///< the linear model's (discrete in exact mode, else continuous)
  std::optional<modes::Pole> continuous, discrete;
};

struct ModalGroupResult {
  std::string id;
  std::vector<std::string> joints;
  double stiffness = 0.0;  ///< N/m (N m/rad)
  double damping = 0.0;    ///< N s/m (N m s/rad)
};

struct ModalTuningResult {
  std::vector<ModalGroupResult> groups;
  std::vector<ModalTargetResult> targets;
  std::vector<modes::Mode> modes;       ///< of the solved system (indices: LinearisedScene::model.bodies)
  std::vector<std::string> body_ids;    ///< model body -> id
  double residual = 0.0;
  bool least_squares = false;
  int iterations = 0;                   ///< of the last round's solve
  int rounds = 0;                       ///< linearise-and-solve rounds run (kMinModalRounds..kMaxModalRounds)
  int start_stiffenings = 0;            ///< times the first guess was stiffened to find the mode
  /// Exact mode with a target at zeta = 0 (no positive damping gives discrete zeta 0): the continuous poles solved.
  bool fell_back_to_standard = false;
  double at_s = 0.0;                    ///< s, when the last linearisation read the rest state
  bool settled = false;
};

/// Ranges and references of scene.modal_tuning ("modal_tuning.groups.0.joints.1"); called by validate_scene.
std::optional<FieldError> validate_modal_tuning(const Scene& scene);

/// Solves; `tuned` is the scene with the solved springs in its joints and the targets' requests on their probes.
/// Refusals name the field ("modal_tuning.targets.1").
std::optional<FieldError> tune_modes(const Scene& scene, MassModel mass_model, ModalTuningResult& out, Scene& tuned,
                                     StageList& stages);

/// Marks each joint of the run that a group of `modal` solved (JointTuning::solved) and asks the engines'
/// answer for its solved k, c (SolvedJoint::joint_export); `scene` is the one that ran (its world's step).
void mark_solved_joints(const Scene& scene, const ModalTuningResult& modal, std::vector<JointTuning>& joints);

/// The model body and coordinate a target means (its probe's body and axis, or body + motion); false when
/// the probe measures no body coordinate.
bool target_coordinate(const Scene& scene, const ModeTargetSettings& t, const LinearisedScene& lin, int& body, modes::Dof& dof);

/// The probe that measures a target in Box2D: its own, or the first displacement / angle probe on its body and motion.
std::string measuring_probe(const Scene& scene, const ModeTargetSettings& t);

}  // namespace softtune::scene
