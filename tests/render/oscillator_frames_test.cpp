// The oscillator preview against the physics: the ghost is the analytic solution, the simulated block
// is the soft constraint (implicit Euler to round-off in standard mode), and the rendered frames show
// each block at its projected position.
#include "softtune/render/oscillator_frames.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "png_decode.h"
#include "softtune/analytic.h"
#include "softtune/designer.h"
#include "softtune/render/camera_path.h"
#include "softtune/render/palette.h"

namespace softtune::render {
namespace {

OscillatorScene scene(double hz, double zeta, double fps, int substeps, Method m) {
  OscillatorScene s;
  s.omega = 2.0 * std::numbers::pi * hz;
  s.damping_ratio = zeta;
  s.fps = fps;
  s.substeps = substeps;
  s.method = m;
  return s;
}

TEST(OscillatorFrames, GhostIsTheAnalyticSolutionAtFrameTimes) {
  const OscillatorScene s = scene(2.0, 0.3, 60.0, 1, Method::soft);
  const auto samples = simulate_oscillator(s, 40);
  ASSERT_EQ(samples.size(), 40u);
  for (int k = 0; k < 40; ++k) {
    EXPECT_DOUBLE_EQ(samples[k].t_s, k / 60.0);
    const State exact = analytic_state({s.initial_displacement_m, 0.0}, s.omega, s.damping_ratio, k / 60.0);
    EXPECT_DOUBLE_EQ(samples[k].analytic.x, exact.x);
  }
  EXPECT_DOUBLE_EQ(samples[0].simulated.x, s.initial_displacement_m);
  EXPECT_DOUBLE_EQ(samples[0].simulated.v, 0.0);
}

TEST(OscillatorFrames, StandardSoftIsImplicitEulerToRoundOff) {
  // Catto GDC 2011: the soft constraint with gamma, beta from (k, c, h) is implicit Euler.
  const OscillatorScene s = scene(3.0, 0.5, 60.0, 4, Method::soft);
  const auto samples = simulate_oscillator(s, 30);
  const double h = step_size(s.fps, s.substeps);
  const Oscillator o{s.mass_kg, s.mass_kg * s.omega * s.omega, 2.0 * s.mass_kg * s.damping_ratio * s.omega};
  State x{s.initial_displacement_m, 0.0};
  for (int k = 1; k < 30; ++k) {
    for (int i = 0; i < s.substeps; ++i) x = implicit_euler_step(x, o, h);
    EXPECT_NEAR(samples[k].simulated.x, x.x, 1e-12);
  }
}

TEST(OscillatorFrames, SubstepsShrinkTheErrorAtFirstOrder) {
  // Implicit Euler is first order: halving h about halves the error against the analytic motion.
  auto max_error = [](int substeps) {
    double e = 0.0;
    for (const auto& sm : simulate_oscillator(scene(2.0, 0.2, 60.0, substeps, Method::soft), 60)) {
      e = std::max(e, std::abs(sm.simulated.x - sm.analytic.x));
    }
    return e;
  };
  const double e2 = max_error(2), e4 = max_error(4), e8 = max_error(8);
  EXPECT_GT(e2 / e4, 1.6);
  EXPECT_LT(e2 / e4, 2.4);
  EXPECT_GT(e4 / e8, 1.7);
  EXPECT_LT(e4 / e8, 2.3);
}

TEST(OscillatorFrames, ExactModeHasTheContinuousPoles) {
  // Samples of the analytic motion obey x[k+1] = S x[k] - P x[k-1] with the continuous poles
  // z = exp(s h): S = 2 exp(-zeta omega h) cos(omega_d h), P = exp(-2 zeta omega h). soft_exact matches
  // those poles (docs/math.md), so its frames obey the same recurrence; standard soft does not.
  const double hz = 10.0, zeta = 0.05, fps = 60.0;
  const double omega = 2.0 * std::numbers::pi * hz, h = 1.0 / fps;
  const double S = 2.0 * std::exp(-zeta * omega * h) * std::cos(omega * std::sqrt(1.0 - zeta * zeta) * h);
  const double P = std::exp(-2.0 * zeta * omega * h);
  auto worst_residual = [&](Method m, bool analytic) {
    const auto sm = simulate_oscillator(scene(hz, zeta, fps, 1, m), 40);
    double worst = 0.0;
    for (int k = 2; k + 1 < 40; ++k) {
      auto x = [&](int i) { return analytic ? sm[i].analytic.x : sm[i].simulated.x; };
      worst = std::max(worst, std::abs(x(k + 1) - S * x(k) + P * x(k - 1)));
    }
    return worst;
  };
  EXPECT_LT(worst_residual(Method::soft, true), 1e-12);
  EXPECT_LT(worst_residual(Method::soft_exact, false), 1e-12);
  EXPECT_GT(worst_residual(Method::soft, false), 1e-3);
}

TEST(OscillatorFrames, SceneComesFromTheTuneResult) {
  TuneRequest q;
  q.fps = 120.0;
  q.substeps = 2;
  q.response_frames = 24.0;
  q.oscillation = Oscillation::some;
  q.effective_mass = 3.0;
  q.mode = SoftMode::exact;
  const TuneResult r = tune(q);
  const OscillatorScene s = oscillator_scene(q, r);
  EXPECT_EQ(s.method, Method::soft_exact);
  EXPECT_DOUBLE_EQ(s.omega, r.omega);
  EXPECT_DOUBLE_EQ(s.damping_ratio, 0.5);
  EXPECT_DOUBLE_EQ(s.mass_kg, 3.0);
  EXPECT_DOUBLE_EQ(s.fps, 120.0);
  EXPECT_EQ(s.substeps, 2);
}

TEST(OscillatorFrames, DrawModelPlacesBlocksSpringsAndGhosts) {
  const OscillatorScene s = scene(2.0, 0.5, 60.0, 1, Method::soft);
  const OscillatorSample sample{0.25, {0.3, 0.0}, {0.2, 0.0}};
  const DrawFrame f = oscillator_frame(s, sample, 15, 60);
  int probed = 0, ghosts = 0;
  for (const PolygonShape& p : f.polygons) {
    double cx = 0.0;
    for (Vec2 v : p.vertices_m) cx += v.x / p.vertices_m.size();
    if (p.role == Role::probed) {
      ++probed;
      EXPECT_NEAR(cx, s.rest_length_m + 0.3, 1e-12);
    }
    if (p.role == Role::ghost) {
      ++ghosts;
      EXPECT_NEAR(cx, s.rest_length_m + 0.2, 1e-12);
    }
  }
  EXPECT_EQ(probed, 1);
  EXPECT_EQ(ghosts, 2);  // on the shelf, and behind the simulated block
  ASSERT_EQ(f.springs.size(), 2u);
  // The spring runs from the wall to the block's near face; at rest it has its rest length.
  EXPECT_DOUBLE_EQ(f.springs[0].a_m.x, 0.0);
  EXPECT_DOUBLE_EQ(f.springs[0].b_m.x, s.rest_length_m + 0.3 - 0.5 * kOscillatorBlockSize);
  EXPECT_DOUBLE_EQ(f.springs[0].rest_length_m, s.rest_length_m - 0.5 * kOscillatorBlockSize);
  EXPECT_TRUE(f.springs[1].ghost);
  EXPECT_NE(f.caption.find("frame 15/59"), std::string::npos) << f.caption;  // counted from 0, like the files
  ASSERT_EQ(f.legend.size(), 2u);
  EXPECT_NE(f.legend[1].find("error +0.100 m"), std::string::npos);
}

TEST(OscillatorFrames, RenderedBlocksSitAtTheirProjectedPositions) {
  const OscillatorScene s = scene(1.5, 0.1, 60.0, 1, Method::soft);
  const PreviewSettings settings{24, {640, 360}, 0};
  const FrameSet set = oscillator_frames(s, settings.frames);
  const View v = make_view(run_camera(set, settings.size), settings.size);
  const auto samples = simulate_oscillator(s, oscillator_run_frames(s) + 1);
  FramePipeline p;
  const auto preview = p.submit("oscillator-test", settings, [&] { return set; })->wait();
  // 24 frames over the 3 s run (180 steps): frame k shows game frame round(180 k / 23).
  for (const auto [k, step] : {std::pair{0, 0}, {11, 86}, {23, 180}}) {
    EXPECT_DOUBLE_EQ(set.times_s[k], step / 60.0);
    const test::Decoded d = test::decode_png(preview->frames_png[k]);
    const double sim_x = oscillator_block_x(s, samples[step].simulated.x);
    const std::uint8_t* q = d.at(static_cast<int>(v.px(sim_x)), static_cast<int>(v.py(oscillator_simulated_lane_y(s))));
    const Rgba probed = role_colours(Role::probed).fill;
    EXPECT_EQ((Rgba{q[0], q[1], q[2], q[3]}), probed) << "frame " << k;
    // The ghost on the shelf: the translucent ghost fill over the background.
    const double exact_x = oscillator_block_x(s, samples[step].analytic.x);
    const std::uint8_t* g = d.at(static_cast<int>(v.px(exact_x)), static_cast<int>(v.py(oscillator_analytic_lane_y(s) + 0.1)));
    // Over the background, or over a faint grid line where one passes under the ghost.
    const Rgba ghost = role_colours(Role::ghost).fill, bg = palette::kBackground, grid = palette::kGrid;
    auto over = [](double top, int alpha, double below) { return (top * alpha + below * (255 - alpha)) / 255.0; };
    const double on_bg = over(ghost.g, ghost.a, bg.g), on_grid = over(ghost.g, ghost.a, over(grid.g, grid.a, bg.g));
    EXPECT_LT(std::min(std::abs(g[1] - on_bg), std::abs(g[1] - on_grid)), 2.0) << "frame " << k << ": " << int(g[1]);
  }
}

TEST(OscillatorFrames, TheExactLaneStaysInViewBelowTheBand) {
  // Its analytic block is drawn as a ghost, but it is half of this preview: the camera frames it (an A/B
  // ghost of a scene it never does, camera_path.h), so both blocks stay whole below the title band.
  const OscillatorScene s = scene(2.0, 0.5, 60.0, 1, Method::soft);
  const FrameSet set = oscillator_frames(s, 30);
  for (const ImageSize size : {ImageSize{640, 360}, ImageSize{360, 640}}) {
    const Bounds view = visible_below_band(run_camera(set, size), size);
    for (const DrawFrame& f : set.frames) {
      for (const PolygonShape& p : f.polygons) {
        for (const Vec2 v : p.vertices_m) {
          EXPECT_GE(v.y, view.lo.y - 1e-9);
          EXPECT_LE(v.y, view.hi.y + 1e-9) << "a block above the band at " << size.width << "x" << size.height;
          EXPECT_GE(v.x, view.lo.x - 1e-9);
          EXPECT_LE(v.x, view.hi.x + 1e-9);
        }
      }
    }
  }
}

}  // namespace
}  // namespace softtune::render
