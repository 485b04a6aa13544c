// The cases of the mujoco-js (MuJoCo 3.x WebAssembly) conformance script, read from softtune's model: for
// each case of a grid, tune() and the mujoco report -- settings, `parameters`, `predicted`, `exact`,
// `exact_predicted`, the request after any clamp -- as one JSON array on stdout. The script
// (mujoco_js_conformance.mjs) builds the same MJCF as kMujocoEngine and holds MuJoCo 3 to them.
#include <array>
#include <cstdio>
#include <string>

#include "softtune/engines/mujoco.h"
#include "softtune/tune.h"

namespace {

using namespace softtune;
using namespace softtune::engines;

void print_parameters(const Parameters& p) {
  std::printf("{");
  for (std::size_t i = 0; i < p.size(); ++i) std::printf("%s\"%s\": %.17g", i ? ", " : "", p[i].name.data(), p[i].value);
  std::printf("}");
}

void print_prediction(const Prediction& p) {
  std::printf("{\"frequency_hz\": %.17g, \"damping_ratio\": %.17g, \"stable\": %s}", p.frequency_hz.value_or(-1.0),
              p.damping_ratio.value_or(-1.0), p.stable ? "true" : "false");
}

}  // namespace

int main() {
  std::size_t index = 0;
  while (engine_models()[index]->name != "mujoco") ++index;
  constexpr std::array<double, 5> kFOverFps = {0.01, 0.05, 0.1, 0.2, 0.3};
  constexpr std::array<double, 7> kZeta = {0.0, 0.05, 0.2, 0.5, 1.0, 1.5, 2.0};
  constexpr std::array<double, 4> kMass = {1e-3, 1.0, 20.0, 1e3};
  constexpr std::array<int, 4> kSubsteps = {1, 2, 4, 8};
  constexpr std::array<int, 4> kIntegrators = {0, 2, 3, 1};  // Euler, implicit, implicitfast, RK4
  std::printf("[\n");
  for (int i = 0; i < 80; ++i) {
    TuneRequest request;
    request.fps = (i / 13) % 2 == 0 ? 60.0 : 120.0;
    request.substeps = kSubsteps[(i / 5) % kSubsteps.size()];
    request.frequency_hz = kFOverFps[i % kFOverFps.size()] * request.fps;
    request.damping_ratio = kZeta[(i / 2) % kZeta.size()];
    request.effective_mass = kMass[(i / 3) % kMass.size()];
    request.mode = i % 2 == 0 ? SoftMode::standard : SoftMode::exact;
    SettingValues settings = default_settings(kMujocoModel);
    settings[kMujocoIntegrator] = kIntegrators[(i / 11) % kIntegrators.size()];
    request.engine_settings.resize(engine_models().size());
    request.engine_settings[index] = settings;
    const TuneResult result = tune(request);
    const EngineReport& r = result.engine_reports[index];
    std::printf("%s{\"h\": %.17g, \"mass\": %.17g, \"body\": \"%s\", \"mode\": \"%s\", ", i ? ",\n" : "", result.h,
                *request.effective_mass, (i / 7) % 2 == 0 ? "point" : "plank",
                request.mode == SoftMode::exact ? "exact" : "standard");
    std::printf("\"integrator\": \"%s\", \"refsafe\": \"%s\", ", r.settings[kMujocoIntegrator].choice.data(),
                r.settings[kMujocoRefsafe].choice.data());
    std::printf("\"asked\": {\"frequency_hz\": %.17g, \"damping_ratio\": %.17g}, ", result.frequency_hz,
                result.damping_ratio);
    std::printf("\"parameters\": ");
    print_parameters(r.parameters);
    std::printf(", \"predicted\": ");
    print_prediction(r.predicted);
    std::printf(", \"exact\": ");
    if (r.exact) {
      print_parameters(*r.exact);
    } else {
      std::printf("null");
    }
    std::printf(", \"inexact_warned\": %s}", [&] {
      for (const Warning& w : r.warnings) {
        if (w.code == WarningCode::engine_inexact) return "true";
      }
      return "false";
    }());
  }
  std::printf("\n]\n");
  return 0;
}
