#include "softtune/diagnostics.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace softtune {
namespace {

constexpr int kStages = static_cast<int>(Stage::png_encode) + 1;  // the last enumerator

TEST(StageList, KeepsEveryStageInOrderPastAnyFixedSize) {
  // Every stage twice: 44 entries, more than the 16 a fixed array once held (it dropped the rest).
  StageList list;
  for (int round = 0; round < 2; ++round) {
    for (int i = 0; i < kStages; ++i) list.add(static_cast<Stage>(i));
  }
  ASSERT_EQ(list.items.size(), 2u * kStages);
  for (int i = 0; i < 2 * kStages; ++i) EXPECT_EQ(list.items[i], static_cast<Stage>(i % kStages)) << i;
  EXPECT_TRUE(list.contains(Stage::png_encode));  // the last one added is there
}

TEST(StageList, ContainsOnlyWhatWasAdded) {
  StageList list;
  EXPECT_FALSE(list.contains(Stage::validate));
  list.add(Stage::render);
  EXPECT_TRUE(list.contains(Stage::render));
  EXPECT_FALSE(list.contains(Stage::validate));
}

TEST(StageList, AppendKeepsBothListsInOrder) {
  StageList simulation, render;
  simulation.add(Stage::core_integrator);
  render.add(Stage::render);
  render.add(Stage::png_encode);
  simulation.append(render);
  EXPECT_EQ(simulation.items, (std::vector<Stage>{Stage::core_integrator, Stage::render, Stage::png_encode}));
  EXPECT_EQ(render.items.size(), 2u);
}

TEST(StageName, NamesEveryStageOnce) {
  std::set<std::string> names;
  for (int i = 0; i < kStages; ++i) {
    const std::string name(stage_name(static_cast<Stage>(i)));
    EXPECT_NE(name, "unknown") << i;
    EXPECT_TRUE(names.insert(name).second) << name;
  }
  EXPECT_EQ(stage_name(Stage::designer_mapping), "designer_mapping");
  EXPECT_EQ(stage_name(Stage::png_encode), "png_encode");
}

}  // namespace
}  // namespace softtune
