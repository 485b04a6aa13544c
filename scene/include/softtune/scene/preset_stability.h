#pragma once
// The highest frequency each tuned joint of a Box2D 2.4 scene stays stable at (issue #20): the other joints
// keep their targets, the joint's frequency f is searched in f h (h = 1 / (fps substeps)) by bracketing and
// bisecting on a spectral radius (stability_limit.h).
//
// Whose spectral radius: the instability of such scenes is the sequential-impulse solver's (velocity
// iterations, warm starting, mass ratios; sequential_impulse.h models it on the 1-D chain), not the soft
// constraint's (a single soft joint on a free body is implicit Euler, unconditionally stable), so it must be
// the radius of Box2D's own step, not of scene/linearise's implicit-Euler model. A finite-difference
// Jacobian of one b2World::Step is not available: the joints' accumulated impulses (m_impulse,
// m_lowerImpulse, ... of b2DistanceJoint, warm-started in InitVelocityConstraints, box2d v2.4.1
// src/dynamics/b2_distance_joint.cpp) are hidden state Box2D gives no setter for. So the radius is measured
// on the real solver by a twin run: two worlds built from the same scene, the second with a small velocity
// kick on every dynamic body, stepped together. Their difference follows the linearised step (warm-start
// impulses included, each world carries its own), so its growth is the step's spectral radius per step:
//   rho = (peak |dv| over the last quarter / peak over the first quarter)^(1 / steps between the quarters),
// |dv| the mass-weighted rms velocity difference. A run whose difference leaves the linear range (over
// kSaturation, or not finite) stops there: rho = (|dv| / |dv0|)^(1 / steps so far).
// A measured rho cannot tell 1 + 1e-9 from 1 (neutral modes such as a pendulum's swing wobble the peaks), so
// the decision is growth over the window: a joint counts unstable when its difference grows more than
// `growth_allowed` (2x over 1800 steps: rho above 1.0004) between the quarters. The bisector is handed rho / growth_allowed^(1 / steps), which
// crosses 1 exactly there; the measured rho is reported at both bracket sides.

#include <optional>
#include <string>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/scene/scene.h"
#include "softtune/stability_limit.h"

namespace softtune::scene {

struct PresetLimitSettings {
  double lowest_frequency_ratio = 0.01;   ///< f h, bottom of the scan
  double highest_frequency_ratio = 2.0;   ///< f h, the search ceiling (120 Hz at 60 fps)
  int scan_points = 8;                    ///< log-spaced, a factor 2.1 apart at the defaults
  int steps = 2400;                       ///< solver steps per twin run (rounded up to whole frames)
  double growth_allowed = 2.0;            ///< growth of the difference over the window counted unstable
  double relative_tolerance = kLimitRelativeTolerance;
};

/// Velocity kick of the twin run, m/s (well above float round-off on m/s speeds, well inside linear).
inline constexpr double kTwinKick = 1e-3;
/// |dv| over this (m/s) leaves the linear range: the run stops and the growth so far is the answer.
inline constexpr double kSaturation = 1.0;

struct TwinRun {
  double spectral_radius = 0.0;  ///< measured per solver step
  double growth = 0.0;           ///< peak |dv| late / early (or the saturated growth)
  int steps = 0;                 ///< solver steps run
  int window = 0;                ///< solver steps the growth is measured over (rho = growth^(1 / window))
  bool saturated = false;        ///< stopped early: the difference left the linear range
};

/// One twin run of `scene` (Box2D bodies and joints only) for `steps` solver steps.
TwinRun measure_twin_run(const Scene& scene, int steps);

/// The `joint` of the row that sets every tuned joint to f together.
inline constexpr const char* kAllTunedJoints = "all_tuned";

struct JointStabilityLimit {
  std::string joint;                        ///< the joint's id, or kAllTunedJoints
  std::vector<std::string> joints;          ///< the joints set to f in this search
  double asked_frequency_hz = 0.0;          ///< Hz, the joint's own target (the highest of the group's)
  StabilityLimit limit;                     ///< in f h; radii are the decision's (see the header)
  std::optional<double> highest_stable_hz;  ///< stable side, or the ceiling when none in range
  std::optional<double> stable_side_hz, unstable_side_hz;
  double stable_side_radius = 0.0, unstable_side_radius = 0.0;  ///< measured rho per step at the sides
  std::optional<double> margin;             ///< asked / highest stable (< 1: the asked frequency is stable)
};

struct PresetStabilityResult {
  std::optional<FieldError> error;  ///< a joint tuning that failed
  double h = 0.0;                   ///< s
  int steps_per_run = 0;
  /// One per tuned joint in scene order, then (two or more tuned joints) all of them together.
  std::vector<JointStabilityLimit> joints;
};

/// Twin runs per search at most: the scan plus the bisection from one scan spacing to the tolerance.
int max_evaluations_per_joint(const PresetLimitSettings& s);

/// Searches of a scene: one per tuned joint, plus one with all at once when there are two or more.
int search_count(const Scene& scene);

/// Searches every tuned joint of a validated scene (see the header comment).
PresetStabilityResult preset_stability_limits(const Scene& scene, const PresetLimitSettings& settings = {});

}  // namespace softtune::scene
