// The probe inset (server/app/probe_inset.cpp): the trace is the probe's own samples, the fitted curve
// reproduces an exactly sampled damped oscillation, the asked curve is the analytic motion, and every
// frame's cursor sits at that frame's time.
#include "app/probe_inset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "app/preset_store.h"
#include "app/scene_frames.h"
#include "codec/scene_codec.h"
#include "softtune/analytic.h"
#include "softtune/render/frame_schedule.h"
#include "../presets_dir.h"

namespace softtune::app {
namespace {

// A probe whose samples are the damped oscillation x_e + x(t) of `hz`, `zeta` from (x0, v0), fitted as
// the runner fits it (measure_probe), asked for `asked_hz`, `asked_zeta`.
scene::ProbeResult oscillation(double hz, double zeta, double asked_hz, double asked_zeta, double fps, double from_s,
                               scene::ProbeSettings& settings) {
  settings.id = "test";
  settings.from_s = from_s;
  const double omega = 2.0 * std::numbers::pi * hz, xe = 0.25;
  std::vector<double> value;
  for (int n = 0; n <= 240; ++n) {
    const double t = n / fps - from_s;
    value.push_back(t < 0.0 ? 0.0 : xe + analytic_state({0.1, -0.3}, omega, zeta, t).x);
  }
  scene::ProbeResult r = scene::measure_probe(settings, value, fps);
  r.requested_frequency_hz = asked_hz;
  r.requested_damping_ratio = asked_zeta;
  return r;
}

TEST(ProbeInset, TheFitReproducesAnExactlySampledOscillation) {
  // A linear oscillator sampled exactly obeys the fit's recurrence, so the fitted curve is the samples.
  for (const double zeta : {0.1, 0.5, 1.3}) {
    scene::ProbeSettings settings;
    const scene::ProbeResult r = oscillation(2.0, zeta, 3.0, 0.5, 60.0, 0.5, settings);
    ASSERT_TRUE(r.measured.frequency_hz) << zeta;
    const std::vector<double> fit = fitted_response(settings, r, 60.0);
    ASSERT_EQ(fit.size(), r.value.size());
    for (int n = 0; n < 30; ++n) EXPECT_TRUE(std::isnan(fit[n])) << "before the window, sample " << n;
    for (std::size_t n = 30; n < fit.size(); ++n) EXPECT_NEAR(fit[n], r.value[n], 1e-9) << "zeta " << zeta << " sample " << n;
  }
}

TEST(ProbeInset, TheAskedCurveIsTheAnalyticMotionOfTheRequest) {
  // Asked for what it does: the asked curve is its own samples. Asked for 3 Hz, zeta 0.5: the analytic
  // motion of that request from the same start, about the same rest.
  scene::ProbeSettings settings;
  const scene::ProbeResult same = oscillation(2.0, 0.2, 2.0, 0.2, 60.0, 0.0, settings);
  const std::vector<double> asked_same = asked_response(settings, same, 60.0);
  for (std::size_t n = 0; n < same.value.size(); ++n) EXPECT_NEAR(asked_same[n], same.value[n], 1e-7) << n;
  const scene::ProbeResult other = oscillation(2.0, 0.2, 3.0, 0.5, 60.0, 0.0, settings);
  const std::vector<double> asked = asked_response(settings, other, 60.0);
  const double omega = 2.0 * std::numbers::pi * 3.0;
  for (std::size_t n = 0; n < other.value.size(); ++n) {
    EXPECT_NEAR(asked[n], 0.25 + analytic_state({0.1, -0.3}, omega, 0.5, n / 60.0).x, 1e-7) << n;
  }
}

TEST(ProbeInset, TheTraceIsTheProbesSamplesAndTheCursorTheFramesTime) {
  for (const std::string name : {"vehicle", "heavy_on_light", "buddhas", "chain", "bridge"}) {
    const scene::Scene scene = codec::decode_scene(load_preset(test_support::kPresets, name));
    scene::RunOptions options;
    options.record_frames = true;
    options.record_at = render::spread_frames(scene::frame_count(scene.world), 30);
    const scene::SceneResult result = scene::run_scene(scene, options);
    const int p = inset_probe(scene, result);
    ASSERT_GE(p, 0) << name;
    const render::FrameSet set = scene_frames(scene, result.snapshots, &result);
    for (std::size_t i = 0; i < set.frames.size(); ++i) {
      ASSERT_TRUE(set.frames[i].inset) << name;
      const render::Inset& inset = *set.frames[i].inset;
      EXPECT_EQ(inset.value, result.probes[p].value) << name;
      EXPECT_EQ(inset.t_s, result.probes[p].time_s) << name;
      EXPECT_DOUBLE_EQ(inset.cursor_s, result.snapshots[i].time_s) << name;
      EXPECT_NE(inset.title.find(result.probes[p].id), std::string::npos) << inset.title;
    }
    // Switched off, no inset.
    SceneLayers off = default_layers(scene);
    off.inset = false;
    EXPECT_FALSE(scene_frames(scene, result.snapshots, &result, off).frames.front().inset) << name;
  }
}

}  // namespace
}  // namespace softtune::app
