// The modelled engines (core/src/engines/registry.cpp): each found by name with the sources it was modelled from
// and settings whose defaults lie in their ranges; the eight engines docs/engines.md names, each once, snake_case.
#include "softtune/engines/engine_model.h"

#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>

namespace softtune::engines {
namespace {

TEST(EngineRegistry, EveryModelIsFoundByNameAndHasValidDefaults) {
  ASSERT_FALSE(engine_models().empty());
  for (const EngineModel* model : engine_models()) {
    EXPECT_EQ(find_engine_model(model->name), model);
    EXPECT_FALSE(model->modelled.empty()) << model->name;
    for (const SettingSpec& spec : model->settings) {
      EXPECT_LE(spec.min, spec.default_value) << model->name << "." << spec.name;
      EXPECT_LE(spec.default_value, spec.max) << model->name << "." << spec.name;
      if (!spec.choices.empty()) {
        EXPECT_EQ(spec.max, static_cast<double>(spec.choices.size() - 1));
      }
    }
  }
  EXPECT_EQ(find_engine_model("no_such_engine"), nullptr);
}

TEST(EngineRegistry, TheEightEnginesOnceEachUnderSnakeCaseNames) {
  std::set<std::string> names;
  for (const EngineModel* m : engine_models()) {
    const std::string name(m->name);
    EXPECT_TRUE(names.insert(name).second) << name;
    for (char c : name) EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_') << name;
    EXPECT_NE(m->report, nullptr) << name;
  }
  for (const char* engine : {"box2d_v2_4", "box2d_v3", "jolt", "mujoco", "ode", "bullet", "physx", "rapier", "matter_js",
                             "planck_js", "cannon_es"}) {
    EXPECT_TRUE(names.contains(engine)) << engine;
  }
}

}  // namespace
}  // namespace softtune::engines
