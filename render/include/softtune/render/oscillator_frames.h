#pragma once
// The talk's 1-D oscillator as preview frames: a block on a spring anchored to a wall, stepped with the
// chosen soft method, and above it, on a shelf, the ghost of the exact analytic motion, so the error
// shows as the offset between the two blocks (and as a ghost outline in the simulated lane).

#include <vector>

#include "softtune/integrators.h"
#include "softtune/methods.h"
#include "softtune/render/draw_model.h"
#include "softtune/render/frame_pipeline.h"
#include "softtune/tune.h"

namespace softtune::render {

struct OscillatorScene {
  double mass_kg = 1.0;
  double omega = 6.283185307179586;  ///< rad/s, natural angular frequency
  double damping_ratio = 0.5;
  double fps = 60.0;                 ///< Hz: one preview frame per game frame
  int substeps = 1;                  ///< solver steps per frame, h = 1 / (fps substeps)
  Method method = Method::soft;
  double initial_displacement_m = 0.5;  ///< x0 (released at rest, v0 = 0)
  double rest_length_m = 2.0;           ///< wall to block centre at x = 0
  double duration_s = 3.0;              ///< s the run lasts (the oscillator preset's world.duration_s)
};

/// Game frames the oscillator's run steps: round(duration_s fps), so its frames span 0..run_frames.
int oscillator_run_frames(const OscillatorScene& scene);

inline constexpr double kOscillatorBlockSize = 0.5;  ///< m, side of the square block

/// The scene of a tune request: effective mass, omega and zeta after any clamp, fps and substeps from
/// the request, and soft or soft_exact from its mode.
OscillatorScene oscillator_scene(const TuneRequest& request, const TuneResult& result);

/// Game frame k at t = k / fps: the simulated state after k frames and the analytic state at t.
struct OscillatorSample {
  double t_s = 0.0;
  State simulated;
  State analytic;
};
/// Game frames 0..frames-1.
std::vector<OscillatorSample> simulate_oscillator(const OscillatorScene& scene, int frames);

/// World x of the block centre for displacement x: rest_length + x.
double oscillator_block_x(const OscillatorScene& scene, double displacement_m);
/// World y of the block centres: the simulated lane on the ground, the analytic lane on the shelf.
double oscillator_simulated_lane_y(const OscillatorScene& scene);
double oscillator_analytic_lane_y(const OscillatorScene& scene);

/// Preview frame `index` of `frames` (counted from 0, frame_schedule.h) showing `sample`.
DrawFrame oscillator_frame(const OscillatorScene& scene, const OscillatorSample& sample, int index, int frames);

/// `frames` frames spread over the run (spread_frames: the first at t = 0, the last at duration_s), with
/// an auto-fit camera.
FrameSet oscillator_frames(const OscillatorScene& scene, int frames);

}  // namespace softtune::render
