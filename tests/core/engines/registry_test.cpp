// The modelled engines (core/src/engines/registry.cpp): the eight engines SPEC.md names, each once under a
// snake_case name, with the sources it was modelled from and a report; find_engine_model finds each by name.
#include "softtune/engines/engine_model.h"

#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>

namespace softtune::engines {
namespace {

TEST(EngineRegistry, EveryModelOnceWithItsSourcesAndReport) {
  std::set<std::string> names;
  for (const EngineModel* m : engine_models()) {
    const std::string name(m->name);
    EXPECT_TRUE(names.insert(name).second) << name;
    for (char c : name) EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_') << name;
    EXPECT_FALSE(m->modelled.empty()) << name;
    EXPECT_NE(m->report, nullptr) << name;
    EXPECT_EQ(find_engine_model(name), m);
  }
  for (const char* engine : {"box2d_v2_4", "box2d_v3", "jolt", "mujoco", "ode", "bullet", "physx", "rapier"}) {
    EXPECT_TRUE(names.contains(engine)) << engine;
  }
  EXPECT_EQ(find_engine_model("havok"), nullptr);
}

}  // namespace
}  // namespace softtune::engines
