#include "softtune/scene/preset_stability.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "softtune/scene/box2d_scene.h"

namespace softtune::scene {
namespace {

// Mass-weighted rms velocity difference of the dynamic bodies of two worlds built from one scene, m/s
// (angular velocities weighted by I / m, so a spinning body counts its rim speed).
double velocity_difference(const Box2DScene& a, const Box2DScene& b) {
  double energy = 0.0, mass = 0.0;
  for (std::size_t i = 0; i < a.bodies().size(); ++i) {
    const b2Body* p = a.bodies()[i];
    const b2Body* q = b.bodies()[i];
    if (p->GetType() != b2_dynamicBody) continue;
    const b2Vec2 dv = p->GetLinearVelocity() - q->GetLinearVelocity();
    const double dw = static_cast<double>(p->GetAngularVelocity()) - q->GetAngularVelocity();
    energy += p->GetMass() * (static_cast<double>(dv.x) * dv.x + static_cast<double>(dv.y) * dv.y) + p->GetInertia() * dw * dw;
    mass += p->GetMass();
  }
  return mass > 0.0 ? std::sqrt(energy / mass) : 0.0;
}

// Kicks every dynamic body by kTwinKick in a direction that turns with its index, so no single mode is missed.
void kick(Box2DScene& s) {
  for (std::size_t i = 0; i < s.bodies().size(); ++i) {
    b2Body* b = s.bodies()[i];
    if (b->GetType() != b2_dynamicBody) continue;
    const double a = 0.7 + 1.3 * static_cast<double>(i);
    b->SetLinearVelocity(b->GetLinearVelocity() + b2Vec2(static_cast<float>(kTwinKick * std::cos(a)), static_cast<float>(kTwinKick * std::sin(a))));
  }
}

}  // namespace

TwinRun measure_twin_run(const Scene& scene, int steps) {
  TwinRun out;
  Box2DScene a(scene, scene.mass_model), b(scene, scene.mass_model);
  const int substeps = std::max(1, scene.world.substeps);
  const int frames = std::max(4, (steps + substeps - 1) / substeps);
  kick(b);
  const double d0 = velocity_difference(a, b);
  if (!(d0 > 0.0)) return out;  // nothing dynamic: no motion to grow
  const int early_end = frames / 4, late_begin = frames - frames / 4;
  double early = d0, late = 0.0;
  for (int f = 1; f <= frames; ++f) {
    a.step_frame(f - 1);
    b.step_frame(f - 1);
    const double d = velocity_difference(a, b);
    if (!std::isfinite(d) || d > kSaturation) {
      // Left the linear range: the growth so far, from the kick (a non-finite d counts as the saturation).
      const double reached = std::isfinite(d) ? d : kSaturation;
      out.steps = f * substeps;
      out.saturated = true;
      out.growth = reached / d0;
      out.window = out.steps;
      out.spectral_radius = std::pow(out.growth, 1.0 / out.window);
      return out;
    }
    if (f <= early_end) early = std::max(early, d);
    if (f >= late_begin) late = std::max(late, d);
  }
  out.steps = frames * substeps;
  out.growth = late / early;
  out.window = (late_begin - 1) * substeps;
  out.spectral_radius = std::pow(out.growth, 1.0 / out.window);
  return out;
}

int max_evaluations_per_joint(const PresetLimitSettings& s) {
  const double spacing = std::pow(s.highest_frequency_ratio / s.lowest_frequency_ratio, 1.0 / (s.scan_points - 1));
  const int bisections = static_cast<int>(std::ceil(std::log2(std::log(spacing) / std::log1p(s.relative_tolerance))));
  return s.scan_points + std::max(0, bisections);
}

int search_count(const Scene& scene) {
  int tuned = 0;
  for (const JointSettings& j : scene.joints) tuned += j.tuning ? 1 : 0;
  return tuned + (tuned > 1 ? 1 : 0);
}

PresetStabilityResult preset_stability_limits(const Scene& scene, const PresetLimitSettings& settings) {
  PresetStabilityResult out;
  const int substeps = std::max(1, scene.world.substeps);
  out.h = 1.0 / (scene.world.fps * substeps);
  out.steps_per_run = std::max(4, (settings.steps + substeps - 1) / substeps) * substeps;
  std::vector<JointTuning> tunings;
  {
    Box2DScene probe(scene, scene.mass_model);
    if (probe.error()) {
      out.error = probe.error();
      return out;
    }
    tunings = probe.tunings();
  }
  const std::vector<double> scan = log_scan(settings.lowest_frequency_ratio, settings.highest_frequency_ratio, settings.scan_points);
  std::vector<std::size_t> tuned;
  for (std::size_t j = 0; j < scene.joints.size(); ++j) {
    if (scene.joints[j].tuning && tunings[j].tuned) tuned.push_back(j);
  }
  // One search per tuned joint (the others at their targets), then, with two or more, all of them at f
  // together: the mass-ratio chain goes unstable when every link is stiff, not when one is.
  std::vector<std::vector<std::size_t>> searches;
  for (std::size_t j : tuned) searches.push_back({j});
  if (tuned.size() > 1) searches.push_back(tuned);
  for (const std::vector<std::size_t>& group : searches) {
    Scene trial = scene;
    std::map<double, TwinRun> runs;  // f h -> its twin run, for the sides' measured radii
    int evaluations = 0;
    const SpectralRadiusOf rho = [&](double p) {
      // The bisection starts from the bracket the scan found: those two runs are reused, not rerun.
      auto it = runs.find(p);
      if (it == runs.end()) {
        for (std::size_t j : group) {
          TuneRequest& q = *trial.joints[j].tuning;
          q.response_frames.reset();
          q.frequency_hz = p / out.h;
        }
        it = runs.emplace(p, measure_twin_run(trial, settings.steps)).first;
        ++evaluations;
      }
      const TwinRun& run = it->second;
      if (run.window == 0) return 0.0;  // no dynamic body: nothing can grow
      // Growth over the window above growth_allowed counts unstable (see the header): rho scaled so it
      // crosses 1 there (a saturated run's growth, >= 1000, is over its own shorter window).
      return run.spectral_radius / std::pow(settings.growth_allowed, 1.0 / run.window);
    };
    JointStabilityLimit l;
    for (std::size_t j : group) {
      l.joints.push_back(scene.joints[j].id);
      l.asked_frequency_hz = std::max(l.asked_frequency_hz, tunings[j].requested_frequency_hz);
    }
    l.joint = group.size() == 1 ? l.joints.front() : std::string(kAllTunedJoints);
    l.limit = find_stability_limit(rho, scan, settings.relative_tolerance);
    l.limit.evaluations = evaluations;  // twin runs actually made
    if (l.limit.stable_side) {
      l.stable_side_hz = *l.limit.stable_side / out.h;
      l.stable_side_radius = runs[*l.limit.stable_side].spectral_radius;
    }
    if (l.limit.unstable_side) {
      l.unstable_side_hz = *l.limit.unstable_side / out.h;
      l.unstable_side_radius = runs[*l.limit.unstable_side].spectral_radius;
    }
    l.highest_stable_hz = l.stable_side_hz;
    if (l.highest_stable_hz && *l.highest_stable_hz > 0.0) l.margin = l.asked_frequency_hz / *l.highest_stable_hz;
    out.joints.push_back(std::move(l));
  }
  return out;
}

}  // namespace softtune::scene
