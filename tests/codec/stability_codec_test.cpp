// The stability request decode (stability_codec.cpp): Problems naming the field.
#include "codec/stability_codec.h"
#include "app/stability_app.h"

#include <gtest/gtest.h>

#include "codec/problem.h"
#include "stability_sweeps.h"

namespace softtune::codec {
namespace {

using app::run_stability;

using nlohmann::json;

using test::small_sweep;

TEST(StabilityCodec, BadFieldsNameTheField) {
  auto expect_problem = [](const char* key, json value, const std::string& field) {
    json r = small_sweep();
    r[key] = std::move(value);
    try {
      run_stability(r);
      ADD_FAILURE() << "accepted " << key;
    } catch (const Problem& p) {
      EXPECT_EQ(p.status, 422);
      EXPECT_EQ(p.field, field);
    }
  };
  expect_problem("methods", {"soft", "rk4"}, "methods.1");
  expect_problem("masses", {0.0}, "masses.0");
  expect_problem("steps", {1.0 / 60, 5.0}, "steps.1");
  expect_problem("observe_steps", 10, "observe_steps");
  expect_problem("chain", {{"iterations", {0}}}, "chain.iterations.0");
  expect_problem("chain", {{"solvers", {"jolt", "physx"}}}, "chain.solvers.1");
  expect_problem("chain", {{"solvers", json::array()}}, "chain.solvers");
  expect_problem("frequency_ratios", json::array(), "frequency_ratios");
  expect_problem("colour", 1, "colour");
}

}  // namespace
}  // namespace softtune::codec
