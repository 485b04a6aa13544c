// Chipmunk 7.0.3 in the loop (docs/engines.md, real-engine conformance): for each case softtune::tune() answers, the chipmunk report's
// `parameters` and then its `exact` are typed into the real engine (engines/chipmunk), the trajectory is
// fitted (fit_response), and the fit is held against the model: within 1 % frequency and 0.02 damping ratio
// of `predicted`, and for `exact` also of the request (conformance_grid.h: f/fps 0.02 to 0.3 at 60 fps, zeta
// 0 to 2, mass 1e-2 to 1e3, substeps 1 to 8, both modes, a point body and a rotating plank), cycling through
// the solver's iterations and the space's damping.
#include <gtest/gtest.h>

#include "chipmunk_engine.h"
#include "conformance_grid.h"
#include "softtune/engines/chipmunk.h"

namespace softtune::engines {
namespace {

using conformance::Variant;

// The model's trajectory of a run from x = 1 at rest: cpSpaceStep as chipmunk_step_map has it.
RunTrajectory model_trajectory(const conformance::Case& c, const Parameters& p) {
  const Eigen::Matrix2d a = chipmunk_step_map(c.run.effective_mass, *parameter_value(p, "cpDampedSpringSetStiffness"),
                                              *parameter_value(p, "cpDampedSpringSetDamping"), c.run.dt,
                                              c.run.settings[kChipmunkDamping]);
  return conformance::step_map_trajectory(a, c.run.steps);
}

TEST(ChipmunkConformance, RealEngineMatchesTheModel) {
  const std::vector<Variant> variants = {
      {"iter10", {10, 1.0}}, {"iter1", {1, 1.0}}, {"iter3 damping0.5", {3, 0.5}}, {"iter10 damping0.05", {10, 0.05}},
      {"iter30", {30, 1.0}},
  };
  const std::vector<conformance::Case> cases =
      conformance::build_cases(kChipmunkModel, variants, {1e-2, 1.0, 1e3}, 1e-3);
  std::vector<conformance::CaseRuns> runs(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EngineRun run = cases[i].run;
    if (cases[i].plain) {
      run.parameters = cases[i].report.parameters;
      runs[i].plain = kChipmunkEngine.run(run);
    }
    if (cases[i].exact) {
      run.parameters = *cases[i].report.exact;
      runs[i].exact = kChipmunkEngine.run(run);
    }
  }
  const std::string title = "Chipmunk " + std::string(kChipmunkEngine.version);
  conformance::check_cases(title.c_str(), kChipmunkModel.name, cases, runs, model_trajectory);
  EXPECT_GE(cases.size(), 300u);
}

}  // namespace
}  // namespace softtune::engines
