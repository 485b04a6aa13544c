// The preset store (preset_store.cpp) on the real preset files: the talk's seven presets load and pass their
// checks; an invalid one is refused with its file, JSON pointer and rule, and listed as invalid.
#include "app/preset_store.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "app/simulate_app.h"
#include "codec/problem.h"
#include "../presets_dir.h"

namespace softtune::codec {
namespace {

using namespace softtune::app;

using nlohmann::json;
namespace fs = std::filesystem;

using test_support::kPresets;

TEST(Presets, AllSevenFromTheTalkExistAndPassTheirChecks) {
  const auto names = list_presets(kPresets);
  for (const char* name : {"oscillator", "buddhas", "vehicle", "bridge", "mouse", "chain", "stiff"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  for (const std::string& name : names) {
    const json result = check_preset(load_preset(kPresets, name));
    EXPECT_TRUE(result["passed"].get<bool>()) << result.dump(1);
  }
  EXPECT_EQ(presets_index(kPresets)["presets"].size(), names.size());
}

TEST(Presets, AnInvalidPresetIsRefusedWithFilePointerAndRule) {
  const fs::path dir = fs::temp_directory_path() / "softtune_presets_test";
  fs::create_directories(dir);
  fs::copy_file(fs::path(kPresets) / "schema.json", dir / "schema.json", fs::copy_options::overwrite_existing);
  json broken = load_preset(kPresets, "stiff");
  broken["world"]["fps"] = 0;
  std::ofstream(dir / "broken.json") << broken.dump();
  try {
    load_preset(dir.string(), "broken");
    FAIL();
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "world.fps");
    EXPECT_NE(p.detail.find("broken.json"), std::string::npos);
    EXPECT_NE(p.detail.find("world.fps must be >= 1"), std::string::npos);
  }
  EXPECT_THROW(load_preset(dir.string(), "../schema"), Problem);
  const json index = presets_index(dir.string());
  ASSERT_EQ(index["presets"].size(), 1u);
  EXPECT_FALSE(index["presets"][0]["valid"].get<bool>());
  EXPECT_EQ(index["presets"][0]["problem"]["field"], "world.fps");
  try {
    load_preset(dir.string(), "absent");
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 404);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace softtune::codec
