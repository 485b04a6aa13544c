#pragma once
// Runs a scene: core-integrator oscillators (no Box2D), a Box2D world only when the scene has bodies,
// probes sampled once per frame, the response fit of every probe, and snapshots only when asked for.
// Every result lists the stages that ran.

#include <optional>
#include <string>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/scene/engine_tuning_result.h"
#include "softtune/response_fit.h"
#include "softtune/scene/joint_tuning.h"
#include "softtune/scene/modal_tuning.h"
#include "softtune/scene/scene.h"
#include "softtune/scene/scene_world.h"
#include "softtune/scene/snapshot.h"

namespace softtune::scene {

struct RunOptions {
  std::optional<MassModel> mass_model;  ///< overrides the scene's
  bool record_frames = false;           ///< snapshots for a renderer
  int frame_stride = 1;                 ///< record every n-th frame
  /// Game frames to record instead of every frame_stride-th, ascending (a preview's frames spread over
  /// the whole run, render/frame_schedule.h); a frame listed twice is recorded twice.
  std::vector<int> record_at = {};
  /// The engine the scene runs in (scene_world.h); null: Box2D 2.4 (kBox2DV24SceneBackend, box2d_backend.h).
  const SceneBackend* backend = nullptr;
  /// The backend's settings, indexed like backend->settings and within their ranges; empty: its defaults.
  engines::SettingValues engine_settings = {};
  /// Per joint (indexed like scene.joints): a spring that replaces what the joint's own tuning gives, as a
  /// tuning in the engine tries them; empty: the scene's own.
  std::vector<std::optional<JointSpring>> springs = {};
};

struct ProbeResult {
  std::string id;
  std::optional<double> requested_frequency_hz;  ///< Hz, from the probe's joint or its own request
  std::optional<double> requested_damping_ratio;
  ResponseFit measured;                          ///< fit over the probe's window
  std::optional<int> settle_frames;              ///< frames from the window start
  std::optional<double> settle_s;                ///< s, settle_frames / fps
  std::optional<double> frequency_error;         ///< f_measured / f_requested - 1
  std::optional<double> damping_ratio_error;     ///< zeta_measured - zeta_requested
  std::optional<double> predicted_frequency_hz;  ///< Hz, what k on the true m_eff gives (joint probes)
  double max_abs_value = 0.0;                    ///< over the window, probe units
  bool diverged = false;                         ///< oscillator probes: the integrator blew up (series cut)
  std::vector<double> time_s;                    ///< one sample per frame, from t = 0
  std::vector<double> value;
};

struct OscillatorRun {
  std::string id;
  Method method = Method::soft;
  TuneResult tuning;
  double requested_frequency_hz = 0.0;  ///< Hz
  double requested_damping_ratio = 0.0;
  std::optional<double> diverged_at_s;  ///< s, first time |x| exceeded kDivergence
  std::vector<double> x;                ///< m, one sample per frame until divergence
};

/// |x| beyond this (m) counts as blown up; the integration stops there so no infinity reaches the output.
inline constexpr double kDivergence = 1.0e9;

struct SceneResult {
  std::optional<FieldError> error;      ///< a joint or oscillator tuning that failed validation, or a refusal
  std::string engine = "box2d_v2_4";    ///< the backend that ran (SceneBackend::name)
  std::string engine_version;           ///< SceneBackend::version
  engines::Parameters engine_settings;  ///< the settings it ran with, by the engine's own names
  /// Per joint (indexed like scene.joints): what to type into the engine for its spring
  /// (SceneBackend::fields); empty for a rigid joint.
  std::vector<engines::Parameters> joint_fields;
  MassModel mass_model = MassModel::effective;
  StageList stages;
  int frames = 0;
  double h = 0.0;                       ///< s, the solver step 1 / (fps substeps)
  std::vector<JointTuning> joints;      ///< tuned and rigid joints, like scene.joints
  std::vector<OscillatorRun> oscillators;
  std::vector<ProbeResult> probes;
  double max_constraint_error = 0.0;    ///< m, largest rigid-joint error over the run
  bool finite = true;                   ///< no NaN or infinity in any Box2D body state
  std::vector<std::string> left_world;  ///< ids of bodies that left world.bounds
  std::vector<Snapshot> snapshots;
  std::optional<ModalTuningResult> modal_tuning;  ///< when the scene tunes its modes (the joints then carry the solve)
  /// When the scene was tuned in its engine (engine_tuning.h): the springs solved by the engine's own runs, each
  /// target's measured response in the confirming run, and the runs it took.
  std::optional<EngineTuningResult> engine_tuning;
};

/// Runs a scene that passed validate_scene().
SceneResult run_scene(const Scene& scene, const RunOptions& options = {});

/// The response of one sampled probe over its window (exposed for tests).
ProbeResult measure_probe(const ProbeSettings& probe, std::vector<double> value, double fps);

}  // namespace softtune::scene
