#include "softtune/engines/scene_backends.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "softtune/scene/box2d_backend.h"

using softtune::engines::find_scene_backend;
using softtune::engines::scene_backends;

TEST(SceneBackends, Box2DComesFirstAndEveryNameIsUniqueAndComplete) {
  const auto all = scene_backends();
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.front(), &softtune::scene::kBox2DV24SceneBackend);
  EXPECT_EQ(all.front()->name, "box2d_v2_4");
  std::set<std::string> names;
  for (const softtune::scene::SceneBackend* b : all) {
    EXPECT_TRUE(names.insert(std::string(b->name)).second) << "twice: " << b->name;
    EXPECT_FALSE(b->version.empty()) << b->name;
    EXPECT_NE(b->build, nullptr) << b->name;
    EXPECT_NE(b->fields, nullptr) << b->name;
    EXPECT_NE(b->parse, nullptr) << b->name;
    for (const softtune::engines::SettingSpec& s : b->settings) {
      EXPECT_LE(s.min, s.default_value) << b->name << " " << s.name;
      EXPECT_LE(s.default_value, s.max) << b->name << " " << s.name;
    }
  }
}

TEST(SceneBackends, FindByNameGivesTheRegisteredBackendOrNull) {
  for (const softtune::scene::SceneBackend* b : scene_backends()) EXPECT_EQ(find_scene_backend(b->name), b);
  EXPECT_EQ(find_scene_backend("havok"), nullptr);
  EXPECT_EQ(find_scene_backend(""), nullptr);
  EXPECT_EQ(find_scene_backend("Box2D_v2_4"), nullptr);  // names are exact
}
