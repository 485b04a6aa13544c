#pragma once
// What a tuning in the engine (engine_tuning.h) solved and measured: the scene's request for each target, what
// the engine's own run of the whole scene measured with the solved springs, the springs it started from (the
// Box2D 2.4 solve) and the ones it solved, and how many engine runs it took. Plain data, read by the answer.

#include <optional>
#include <string>
#include <vector>

#include "softtune/scene/scene_world.h"

namespace softtune::scene {

/// One request the engine's run has to meet, measured by one probe.
struct EngineTarget {
  std::string probe;                          ///< the probe that measures it
  std::string request;                        ///< the modal target's mode ("heave") or the tuned joint's id
  double requested_frequency_hz = 0.0;        ///< Hz
  double requested_damping_ratio = 0.0;
  std::optional<double> box2d_frequency_hz;   ///< Hz, what Box2D 2.4 measures with its own solve
  std::optional<double> box2d_damping_ratio;
  std::optional<double> start_frequency_hz;   ///< Hz, the engine's run with Box2D 2.4's solve (before tuning)
  std::optional<double> start_damping_ratio;
  std::optional<double> measured_frequency_hz;  ///< Hz, the engine's run with the solved springs
  std::optional<double> measured_damping_ratio;
  std::optional<double> frequency_error;      ///< measured / requested - 1
  std::optional<double> damping_ratio_error;  ///< measured - requested
};

/// One solved spring: a modal group (every joint in it shares the spring) or one tuned joint.
struct EngineUnknown {
  std::string id;                  ///< group id or joint id
  std::vector<int> joints;         ///< indices into scene.joints
  JointSpring start;               ///< Box2D 2.4's solve (the first guess)
  JointSpring solved;              ///< what the engine runs with
};

struct EngineTuningResult {
  std::string engine;                        ///< SceneBackend::name
  bool modal = false;                        ///< the scene's modal targets (else its tuned joints' own probes)
  std::vector<EngineUnknown> unknowns;
  std::vector<EngineTarget> targets;
  /// Tuned joints' own probes left out: Box2D 2.4's per-joint solve does not meet them either (the joint is
  /// coupled to others, so its request is not the scene's response); their springs stay Box2D's k, c.
  std::vector<std::string> coupled_probes;
  double window_s = 0.0;                     ///< s, each solve run ends here (the targets' windows' end)
  int runs = 0;                              ///< engine runs of the solve, the confirming full run not counted
  int iterations = 0;                        ///< Newton steps taken
  bool converged = false;                    ///< every target within kEngineFrequencyTolerance / kEngineDampingTolerance
};

}  // namespace softtune::scene
