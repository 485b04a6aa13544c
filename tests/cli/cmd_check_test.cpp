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
  // Every declared rate is ctest's preset_check; here 60 fps (each world's substeps) keeps valgrind's run short.
  EXPECT_EQ(run_check({SOFTTUNE_PRESETS_DIR, "--fps", "60"}), 0);

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

// Exit codes as docs/preset-ci.md lists them: 2 for bad input (before any preset runs), 1 for a drift from
// the baseline, 0 after --update-baseline records the drifted figures. One short preset (mouse, 3 s).
TEST(CheckCommand, BadInputIsTwoAndADriftIsOne) {
  const std::string mouse_file = std::string(SOFTTUNE_PRESETS_DIR) + "/mouse.json";
  EXPECT_EQ(run_check({mouse_file, "--fps", "30,abc"}), 2);
  EXPECT_EQ(run_check({mouse_file, "--substeps", "0"}), 2);
  EXPECT_EQ(run_check({mouse_file, "--format", "xml"}), 2);
  EXPECT_EQ(run_check({mouse_file, "-j", "0"}), 2);
  EXPECT_EQ(run_check({mouse_file, "--shard", "2/1"}), 2);
  EXPECT_EQ(run_check({mouse_file, "--update-baseline"}), 2);  // no --baseline FILE
  EXPECT_EQ(run_check({mouse_file, "--baseline", "/nonexistent/baseline.json"}), 2);
  EXPECT_EQ(run_check({"/nonexistent/presets"}), 2);

  const fs::path dir = fs::temp_directory_path() / "softtune_check_baseline_cli";
  fs::create_directories(dir);
  fs::copy_file(fs::path(SOFTTUNE_PRESETS_DIR) / "schema.json", dir / "schema.json", fs::copy_options::overwrite_existing);
  nlohmann::json mouse = app::load_preset(SOFTTUNE_PRESETS_DIR, "mouse");
  std::ofstream(dir / "mouse.json") << mouse.dump();
  const std::string baseline = (fs::temp_directory_path() / "softtune_check_baseline_cli.json").string();  // not in the presets dir
  EXPECT_EQ(run_check({dir.string(), "--baseline", baseline, "--update-baseline", "-j2"}), 0);
  EXPECT_EQ(run_check({dir.string(), "--baseline", baseline, "--format", "junit"}), 0);
  mouse["joints"][0]["response_frames"] = 27;  // 2 Hz -> 2.22 Hz: still within its own expectations
  std::ofstream(dir / "mouse.json") << mouse.dump();
  EXPECT_EQ(run_check({dir.string(), "--baseline", baseline}), 1);
  EXPECT_EQ(run_check({dir.string(), "--baseline", baseline, "--update-baseline"}), 0);
  EXPECT_EQ(run_check({dir.string(), "--baseline", baseline}), 0);
  fs::remove_all(dir);
  fs::remove(baseline);
}

}  // namespace
}  // namespace softtune::cli
