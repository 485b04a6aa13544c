// Godot 3.2.3 in the loop (docs/engines.md, real-engine conformance): for each case softtune::tune() answers, the godot report's
// `parameters` and then its `exact` are typed into the real engine (godot3-server headless running
// godot_run.gd, every case of one physics rate in one process), the recorded trajectory is fitted
// (fit_response), and the fit is held against the model: within 1 % frequency and 0.02 damping ratio of
// `predicted`, and for `exact` also of the request (conformance_grid.h: f/fps 0.02 to 0.3 at 60 fps, zeta 0
// to 2, mass 1e-2 to 1e3, substeps 1 to 8 as physics rates 60, 180 and 480, both modes, a point body and a
// rotating plank), cycling through the body's linear_damp. And Godot 3.2 3-D: Generic6DOFJoint's X spring on
// Bullet (the point body, the same grid, the body's linear_damp over the project's 0.1), and on GodotPhysics,
// where the model refuses every spring and Godot, typed one anyway, never moves the body.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "conformance_grid.h"
#include "softtune/engines/godot_2d.h"
#include "softtune/engines/godot_3d.h"

namespace softtune::engines {
namespace {

using conformance::Case;
using conformance::CaseRuns;

// Godot stores positions in float: on a heavily over-damped motion (the plain export of zeta 2 is damped four
// times over, zeta 8 and more) the fit's damping ratio hinges on round-off in the fast pole's few samples, so
// such runs are held to the model's trajectory instead of fitted.
constexpr double kFloatFitMaxDamping = 2.2;

void hold_overdamped_runs(std::vector<Case>& cases) {
  for (Case& c : cases) {
    if (c.fit_plain && *c.report.predicted.damping_ratio > kFloatFitMaxDamping) c.fit_plain = false;
    if (c.fit_exact && *c.report.exact_predicted->damping_ratio > kFloatFitMaxDamping) c.fit_exact = false;
  }
}

// One run to make: which case, plain or exact, and its case line for godot_run.gd (after the id).
struct GodotRun {
  std::size_t case_index;
  bool exact;
  std::string line;
};

// A Godot project folder whose project.godot picks the 3-D backend ("DEFAULT" is Bullet in Godot 3.2), one
// per test (`tag`): Godot writes its logs there.
std::filesystem::path project(const std::string& physics_engine, const std::string& tag) {
  const std::filesystem::path dir = std::filesystem::path(SOFTTUNE_GODOT_WORK) / ("project_" + tag);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "project.godot") << "config_version=4\n\n[physics]\n\n3d/physics_engine=\"" << physics_engine
                                       << "\"\n";
  return dir;
}

// Runs every run in Godot, one process per physics rate, in the project folder `in_project`; returns the
// trajectories (x over x0) by case. `tag` names the test's files, so that tests run at once (ctest -j) do
// not share them.
std::vector<CaseRuns> run_in_godot(const std::vector<Case>& cases, const std::vector<GodotRun>& runs,
                                   const std::filesystem::path& in_project, const std::string& tag) {
  std::vector<CaseRuns> out(cases.size());
  std::map<int, std::vector<std::size_t>> by_rate;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    by_rate[static_cast<int>(std::lround(1.0 / cases[runs[i].case_index].run.dt))].push_back(i);
  }
  const std::filesystem::path work = SOFTTUNE_GODOT_WORK;
  std::filesystem::create_directories(work / "home");
  for (const auto& [rate, indices] : by_rate) {
    const std::filesystem::path in = work / ("cases_" + tag + "_" + std::to_string(rate) + ".txt");
    const std::filesystem::path result = work / ("out_" + tag + "_" + std::to_string(rate) + ".txt");
    {
      std::ofstream file(in);
      for (std::size_t i : indices) file << i << ' ' << runs[i].line << '\n';
    }
    std::filesystem::remove(result);
    const std::string command = "HOME='" + (work / "home").string() + "' SOFTTUNE_RATE=" + std::to_string(rate) +
                                " SOFTTUNE_CASES='" + in.string() + "' SOFTTUNE_OUT='" + result.string() + "' '" +
                                SOFTTUNE_GODOT + "' --path '" + in_project.string() + "' --fixed-fps " +
                                std::to_string(rate) + " -s '" +
                                SOFTTUNE_GODOT_SCRIPT + "' > '" + (work / ("godot_" + tag + ".log")).string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream file(result);
    std::string line;
    std::size_t read = 0;
    while (std::getline(file, line)) {
      std::istringstream fields(line);
      std::size_t i = 0;
      fields >> i;
      RunTrajectory x;
      for (double v; fields >> v;) x.push_back(v);
      if (i >= runs.size()) continue;
      (runs[i].exact ? out[runs[i].case_index].exact : out[runs[i].case_index].plain) = std::move(x);
      ++read;
    }
    EXPECT_EQ(read, indices.size()) << "rate " << rate << ": Godot answered " << read << " of " << indices.size();
  }
  return out;
}

bool pinned(const Case& c) { return c.run.settings[kGodot2DJoint] != 0.0; }

// A 2-D case line: the spring's stiffness and damping, or the pin's softness and bias, then the damp and
// the joint (0 spring, 1 pin).
std::string line_2d(const Case& c, const Parameters& p) {
  const bool pin = pinned(c);
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, "2 %d %.17g %.17g %d %.17g %.17g %.17g %d", c.run.body == RunBody::point ? 0 : 1,
                c.run.effective_mass, c.run.x0, c.run.steps,
                *parameter_value(p, pin ? "PinJoint2D.softness" : "DampedSpringJoint2D.stiffness"),
                *parameter_value(p, pin ? "PinJoint2D.bias" : "DampedSpringJoint2D.damping"),
                c.run.settings[kGodot2DLinearDamp], pin ? 1 : 0);
  return buffer;
}

// The model's trajectory of a run from x = 1 at rest: Step2DSW::step as godot_2d_step_map has it.
RunTrajectory model_2d(const Case& c, const Parameters& p) {
  if (pinned(c)) {
    return conformance::step_map_trajectory(
        godot_2d_pin_step_map(c.run.effective_mass, *parameter_value(p, "PinJoint2D.softness"),
                              *parameter_value(p, "PinJoint2D.bias"), c.run.dt, c.run.settings[kGodot2DLinearDamp]),
        c.run.steps);
  }
  const Eigen::Matrix2d a = godot_2d_step_map(c.run.effective_mass, *parameter_value(p, "DampedSpringJoint2D.stiffness"),
                                              *parameter_value(p, "DampedSpringJoint2D.damping"), c.run.dt,
                                              c.run.settings[kGodot2DLinearDamp]);
  return conformance::step_map_trajectory(a, c.run.steps);
}

TEST(Godot2DConformance, RealEngineMatchesTheModel) {
  const std::vector<conformance::Variant> variants = {
      {"spring damp0.1", {0.1, 0}}, {"spring damp0", {0.0, 0}}, {"pin damp0.1", {0.1, 1}}, {"spring damp1", {1.0, 0}},
      {"pin damp0", {0.0, 1}},         {"spring damp5", {5.0, 0}}, {"pin damp3", {3.0, 1}},
  };
  std::vector<Case> cases = conformance::build_cases(kGodot2DModel, variants, {1e-2, 1.0, 1e3}, 1e-3);
  hold_overdamped_runs(cases);
  std::vector<GodotRun> runs;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (cases[i].plain) runs.push_back({i, false, line_2d(cases[i], cases[i].report.parameters)});
    if (cases[i].exact) runs.push_back({i, true, line_2d(cases[i], *cases[i].report.exact)});
  }
  const std::vector<CaseRuns> trajectories = run_in_godot(cases, runs, project("DEFAULT", "2d"), "2d");
  conformance::check_cases("Godot 3.2.3 2-D DampedSpringJoint2D and PinJoint2D", kGodot2DModel.name, cases, trajectories, model_2d);
  EXPECT_GE(cases.size(), 300u);
}

std::string line_3d(const Case& c, const Parameters& p) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, "3 0 %.17g %.17g %d %.17g %.17g %.17g", c.run.effective_mass, c.run.x0, c.run.steps,
                *parameter_value(p, "Generic6DOFJoint.linear_spring_x/stiffness"),
                *parameter_value(p, "Generic6DOFJoint.linear_spring_x/damping"), c.run.settings[kGodot3DLinearDamp]);
  return buffer;
}

// The model's trajectory of a run from x = 1 at rest: Bullet 2.89's step as godot_3d_bullet_step has it.
RunTrajectory model_3d(const Case& c, const Parameters& p) {
  return godot_3d_bullet_trajectory(c.run.effective_mass, *parameter_value(p, "Generic6DOFJoint.linear_spring_x/stiffness"),
                                    *parameter_value(p, "Generic6DOFJoint.linear_spring_x/damping"), c.run.dt,
                                    godot_3d_bullet_velocity_kept(c.run.settings, c.run.dt), c.run.steps);
}

// The point body only: Bullet 2.89's spring row damps the body's centre velocity, not the anchor's, and a 3-D
// body takes its inertia from its shapes alone, so the off-centre anchor is not a one-row problem here.
std::vector<Case> point_cases(std::vector<Case> cases) {
  std::erase_if(cases, [](const Case& c) { return c.run.body != RunBody::point; });
  return cases;
}

TEST(Godot3DConformance, BulletMatchesTheModel) {
  // physics/3d/default_linear_damp stays the project's 0.1; the body's linear_damp varies.
  const std::vector<conformance::Variant> variants = {
      {"bullet damp-1", {0, 0.1, -1}}, {"bullet damp0.5", {0, 0.1, 0.5}}, {"bullet damp3", {0, 0.1, 3}},
  };
  std::vector<Case> cases = point_cases(conformance::build_cases(kGodot3DModel, variants, {1e-2, 1.0, 1e3}, 1e-3));
  hold_overdamped_runs(cases);
  // Fitted over the steps the model's prediction fits: the stepped model is not linear, so what a fit reads
  // depends on its window.
  for (Case& c : cases) {
    c.run.steps = godot_3d_fit_steps(2.0 * std::numbers::pi * c.asked_hz, c.asked_zeta, c.run.dt);
  }
  std::vector<GodotRun> runs;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (cases[i].plain) runs.push_back({i, false, line_3d(cases[i], cases[i].report.parameters)});
    if (cases[i].exact) runs.push_back({i, true, line_3d(cases[i], *cases[i].report.exact)});
  }
  const std::vector<CaseRuns> trajectories = run_in_godot(cases, runs, project("DEFAULT", "3d_bullet"), "3d_bullet");
  conformance::check_cases("Godot 3.2.3 3-D Generic6DOFJoint on Bullet", kGodot3DModel.name, cases, trajectories, model_3d);
  EXPECT_GE(cases.size(), 150u);
}

TEST(Godot3DConformance, GodotPhysicsIgnoresTheSpringAsTheModelSays) {
  // The model refuses every spring on GodotPhysics; typed anyway (the Bullet answer's values), the body
  // released 1 mm from rest never moves.
  const std::vector<conformance::Variant> godot_physics = {{"godotphysics", {1, 0.1, -1}}};
  const std::vector<conformance::Variant> bullet = {{"bullet", {0, 0.1, -1}}};
  const std::vector<Case> refused = point_cases(conformance::build_cases(kGodot3DModel, godot_physics, {1.0}, 1e-3));
  const std::vector<Case> typed = point_cases(conformance::build_cases(kGodot3DModel, bullet, {1.0}, 1e-3));
  ASSERT_EQ(refused.size(), typed.size());
  std::vector<GodotRun> runs;
  for (std::size_t i = 0; i < refused.size(); ++i) {
    EXPECT_TRUE(refused[i].report.parameters.empty()) << refused[i].label;
    EXPECT_FALSE(refused[i].report.exact) << refused[i].label;
    if (!typed[i].report.parameters.empty()) runs.push_back({i, false, line_3d(typed[i], typed[i].report.parameters)});
  }
  const std::vector<CaseRuns> trajectories = run_in_godot(typed, runs, project("GodotPhysics", "3d_godotphysics"), "3d_godotphysics");
  double worst = 0.0;
  int moved = 0;
  for (const GodotRun& r : runs) {
    const RunTrajectory& x = trajectories[r.case_index].plain;
    ASSERT_FALSE(x.empty()) << typed[r.case_index].label;
    for (double v : x) worst = std::max(worst, std::abs(v - 1.0));
    moved += std::any_of(x.begin(), x.end(), [](double v) { return std::abs(v - 1.0) > 1e-6; });
  }
  std::printf("Godot 3.2.3 3-D on GodotPhysics: %zu springs typed, %d moved the body (worst %.2g of x0)\n",
              runs.size(), moved, worst);
  EXPECT_EQ(moved, 0);
  EXPECT_GE(runs.size(), 60u);
}

}  // namespace
}  // namespace softtune::engines
