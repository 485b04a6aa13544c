// `softtune check` as CI uses it: exit 0 when every preset passes, 1 when one fails or cannot be loaded.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli/commands.h"
#include "app/preset_store.h"

namespace softtune::cli {
namespace {

namespace fs = std::filesystem;

TEST(CheckCommand, ExitCodeFollowsTheExpectations) {
  EXPECT_EQ(run_check({SOFTTUNE_PRESETS_DIR}), 0);

  const fs::path dir = fs::temp_directory_path() / "softtune_check_test";
  fs::create_directories(dir);
  fs::copy_file(fs::path(SOFTTUNE_PRESETS_DIR) / "schema.json", dir / "schema.json", fs::copy_options::overwrite_existing);
  nlohmann::json mouse = app::load_preset(SOFTTUNE_PRESETS_DIR, "mouse");
  std::ofstream(dir / "mouse.json") << mouse.dump();
  EXPECT_EQ(run_check({dir.string()}), 0);

  // Ask the 2 Hz drag for 3 Hz: the measured frequency is 33 % off and the check must fail.
  mouse["probes"][0]["requested"] = {{"frequency_hz", 3.0}};
  std::ofstream(dir / "mouse.json") << mouse.dump();
  EXPECT_EQ(run_check({dir.string()}), 1);

  // A preset its schema refuses fails the run too.
  std::ofstream(dir / "mouse.json") << R"({"name": "mouse"})";
  EXPECT_EQ(run_check({dir.string()}), 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace softtune::cli
