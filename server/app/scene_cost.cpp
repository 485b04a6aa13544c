#include "app/scene_cost.h"

#include <algorithm>

#include "app/cost_drivers.h"

namespace softtune::app {
namespace {

// Rates measured on the reference machine (scene_cost.h).
constexpr double kBodyStepSeconds = 0.35e-6, kJointIterationSeconds = 11e-9;
constexpr double kProbeFrameBytes = 150, kProbeFrameSeconds = 200e-9;
constexpr double kSnapshotBodyBytes = 600, kSnapshotJointBytes = 400, kSnapshotItemSeconds = 1e-6;

// The default world's own size, what the drivers' factors compare with.
const scene::WorldSettings kDefaultWorld{};

}  // namespace

RequestCost scene_cost(const scene::Scene& s, const scene::RunOptions& options, const std::string& prefix) {
  const scene::WorldSettings& w = s.world;
  const double frames = std::max(0, scene::frame_count(w));
  const double substeps = std::max(1, w.substeps);
  const double iterations = std::max(0, w.velocity_iterations) + std::max(0, w.position_iterations);
  const double items = static_cast<double>(s.bodies.size() + s.joints.size());
  RequestCost cost;
  cost.cpu_seconds = frames * substeps *
                     (static_cast<double>(s.bodies.size()) * kBodyStepSeconds +
                      static_cast<double>(s.joints.size()) * iterations * kJointIterationSeconds);
  const double probes = static_cast<double>(s.probes.size());
  cost.cpu_seconds += probes * frames * kProbeFrameSeconds;
  cost.peak_bytes = probes * frames * kProbeFrameBytes;
  if (options.record_frames) {
    const double recorded = options.record_at.empty() ? frames / std::max(1, options.frame_stride) + 1
                                                      : static_cast<double>(options.record_at.size());
    const double per_frame = static_cast<double>(s.bodies.size()) * kSnapshotBodyBytes +
                             static_cast<double>(s.joints.size()) * kSnapshotJointBytes;
    cost.peak_bytes += recorded * per_frame;
    cost.cpu_seconds += recorded * items * kSnapshotItemSeconds;
  }
  cost.work = std::to_string(static_cast<long long>(frames)) + " frames x " +
              std::to_string(static_cast<long long>(substeps)) + " substeps x " +
              std::to_string(static_cast<long long>(items)) + " bodies and joints";
  if (options.record_frames && options.record_at.empty()) {
    cost.work += ", every " + std::to_string(options.frame_stride) + ". frame recorded";
  } else if (options.record_frames) {
    cost.work += ", " + std::to_string(options.record_at.size()) + " frames recorded";
  }

  const double default_frames = static_cast<double>(scene::frame_count(kDefaultWorld));
  CostDrivers drivers;
  drivers.add(prefix + "world.duration_s", w.duration_s / kDefaultWorld.duration_s);
  drivers.add(prefix + "world.fps", w.fps / kDefaultWorld.fps);
  drivers.add(prefix + "world.substeps", substeps);
  drivers.add(prefix + "world.velocity_iterations", (1.0 + w.velocity_iterations) / (1.0 + kDefaultWorld.velocity_iterations));
  drivers.add(prefix + "world.position_iterations", (1.0 + w.position_iterations) / (1.0 + kDefaultWorld.position_iterations));
  drivers.add(prefix + "bodies", static_cast<double>(s.bodies.size()) / 10.0);
  drivers.add(prefix + "joints", static_cast<double>(s.joints.size()) / 10.0);
  drivers.add(prefix + "probes", probes * frames / (4.0 * default_frames));
  if (options.record_frames && options.record_at.empty()) {
    drivers.add("frame_stride", 1.0 + 1.0 / std::max(1, options.frame_stride));
  } else if (options.record_frames) {
    drivers.add("frames", 1.0 + static_cast<double>(options.record_at.size()) / std::max(1.0, frames + 1.0));
  }
  cost.fields = drivers.fields();
  return cost;
}

}  // namespace softtune::app
