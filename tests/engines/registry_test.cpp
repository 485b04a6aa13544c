// The real engines linked in process (engines/registry.cpp): Box2D 2.4, ODE, Bullet and MuJoCo, each under the
// name of its model in core (so its report is what verify types in), with the library version it was built
// against; a modelled engine that is not linked is not found.
#include "softtune/engines/verify.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace softtune::engines {
namespace {

TEST(RealEngines, EachLinkedEngineHasItsModelAndVersion) {
  std::set<std::string> names;
  for (const RealEngine* e : real_engines()) {
    EXPECT_TRUE(names.insert(std::string(e->name)).second) << e->name;
    EXPECT_NE(find_engine_model(e->name), nullptr) << e->name;
    EXPECT_FALSE(e->version.empty()) << e->name;
    EXPECT_NE(e->run, nullptr) << e->name;
    EXPECT_EQ(find_real_engine(e->name), e);
  }
  for (const char* linked : {"box2d_v2_4", "ode", "bullet", "mujoco"}) EXPECT_TRUE(names.contains(linked)) << linked;
  EXPECT_EQ(find_real_engine("box2d_v3"), nullptr);  // modelled in core, no library linked
  EXPECT_EQ(find_real_engine("havok"), nullptr);
}

}  // namespace
}  // namespace softtune::engines
