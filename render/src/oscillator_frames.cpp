#include "softtune/render/oscillator_frames.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "softtune/analytic.h"
#include "softtune/designer.h"
#include "softtune/render/frame_schedule.h"

namespace softtune::render {
namespace {

constexpr double kHalf = 0.5 * kOscillatorBlockSize;
constexpr double kWallThickness = 0.25;  // m
constexpr double kShelfThickness = 0.1;  // m
constexpr double kLaneGap = 0.35;        // m between the top of the lower block and the shelf

double shelf_top(const OscillatorScene&) { return kOscillatorBlockSize + kLaneGap + kShelfThickness; }

PolygonShape box(double x0, double y0, double x1, double y1, Role role) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, role};
}

PolygonShape block(double cx, double cy, Role role) { return box(cx - kHalf, cy - kHalf, cx + kHalf, cy + kHalf, role); }

// Spring from the wall to the block's near face: rest length is rest_length - half a block.
void add_spring(DrawFrame& f, const OscillatorScene& s, double cx, double cy, bool ghost) {
  const Vec2 wall{0.0, cy}, face{cx - kHalf, cy};
  f.springs.push_back({wall, face, s.rest_length_m - kHalf, std::nullopt, ghost});
  f.anchors.push_back({wall, ghost});
  f.anchors.push_back({face, ghost});
}

const char* method_title(Method m) { return m == Method::soft_exact ? "soft exact" : "soft"; }

}  // namespace

OscillatorScene oscillator_scene(const TuneRequest& request, const TuneResult& result) {
  OscillatorScene s;
  s.mass_kg = result.effective_mass;
  s.omega = result.omega;
  s.damping_ratio = result.damping_ratio;
  s.fps = request.fps;
  s.substeps = request.substeps;
  s.method = request.mode == SoftMode::exact ? Method::soft_exact : Method::soft;
  return s;
}

std::vector<OscillatorSample> simulate_oscillator(const OscillatorScene& s, int frames) {
  const double h = step_size(s.fps, s.substeps);
  const StepModel model = make_step_model(s.mass_kg, s.omega, s.damping_ratio, h);
  const State initial{s.initial_displacement_m, 0.0};
  std::vector<OscillatorSample> out;
  out.reserve(frames);
  State x = initial;
  for (int k = 0; k < frames; ++k) {
    if (k > 0) {
      for (int i = 0; i < s.substeps; ++i) x = step(s.method, x, model);
    }
    const double t = k / s.fps;
    out.push_back({t, x, analytic_state(initial, s.omega, s.damping_ratio, t)});
  }
  return out;
}

int oscillator_run_frames(const OscillatorScene& s) {
  return std::max(0, static_cast<int>(std::lround(s.duration_s * s.fps)));
}

double oscillator_block_x(const OscillatorScene& s, double displacement_m) { return s.rest_length_m + displacement_m; }
double oscillator_simulated_lane_y(const OscillatorScene&) { return kHalf; }
double oscillator_analytic_lane_y(const OscillatorScene& s) { return shelf_top(s) + kHalf; }

DrawFrame oscillator_frame(const OscillatorScene& s, const OscillatorSample& sample, int index, int frames) {
  DrawFrame f;
  f.ground_y_m = 0.0;
  f.ghost_in_camera = true;  // the exact lane is half of what this preview shows
  const double reach = s.rest_length_m + 1.5 * std::abs(s.initial_displacement_m) + kOscillatorBlockSize;
  const double y_sim = oscillator_simulated_lane_y(s), y_exact = oscillator_analytic_lane_y(s);
  const double top = shelf_top(s) + kOscillatorBlockSize + 0.3;
  f.polygons.push_back(box(-kWallThickness, 0.0, 0.0, top, Role::static_body));
  f.polygons.push_back(box(0.0, shelf_top(s) - kShelfThickness, reach, shelf_top(s), Role::static_body));

  const double x_sim = oscillator_block_x(s, sample.simulated.x), x_exact = oscillator_block_x(s, sample.analytic.x);
  // Where the block should be, under the simulated block: it shows only where the two differ.
  f.polygons.push_back(block(x_exact, y_sim, Role::ghost));
  f.polygons.push_back(block(x_sim, y_sim, Role::probed));
  f.polygons.push_back(block(x_exact, y_exact, Role::ghost));
  add_spring(f, s, x_sim, y_sim, false);
  add_spring(f, s, x_exact, y_exact, true);

  f.labels.push_back({std::string("simulated (") + method_title(s.method) + ")", {0.12, kOscillatorBlockSize + 0.06}});
  f.labels.push_back({"exact (analytic)", {0.12, shelf_top(s) + kOscillatorBlockSize + 0.06}});

  const double f_hz = s.omega / (2.0 * 3.141592653589793);
  char line[200];
  std::snprintf(line, sizeof line, "oscillator  \u00b7  t = %.3f s  \u00b7  frame %d/%d", sample.t_s, index,
                std::max(0, frames - 1));
  f.caption = line;
  std::snprintf(line, sizeof line, "%s \u00b7 %g fps \u00d7 %d substep%s", s.method == Method::soft_exact ? "exact" : "standard",
                s.fps, s.substeps, s.substeps == 1 ? "" : "s");
  f.settings = line;
  std::snprintf(line, sizeof line, "asked %.2f Hz \u03b6 %.2f, m %.3g kg", f_hz, s.damping_ratio, s.mass_kg);
  f.legend.push_back(line);
  std::snprintf(line, sizeof line, "error %+.3f m against the exact motion", sample.simulated.x - sample.analytic.x);
  f.legend.push_back(line);
  return f;
}

FrameSet oscillator_frames(const OscillatorScene& s, int frames) {
  FrameSet set;
  const std::vector<int> at = spread_frames(oscillator_run_frames(s), frames);
  set.run_end_s = oscillator_run_frames(s) / s.fps;
  const std::vector<OscillatorSample> samples = simulate_oscillator(s, at.empty() ? 0 : at.back() + 1);
  set.frames.reserve(at.size());
  for (int k = 0; k < static_cast<int>(at.size()); ++k) {
    set.frames.push_back(oscillator_frame(s, samples[at[k]], k, frames));
    set.times_s.push_back(samples[at[k]].t_s);
  }
  return set;
}

}  // namespace softtune::render
