// Replays every committed fuzz input in the plain (and sanitizer) builds: the seeds (fuzz/seeds/<harness>)
// and each crash the fuzzers found, kept once fixed (fuzz/regressions/<harness>), through the same harness
// bodies libFuzzer runs (fuzz/harnesses.h). The grown corpus lives outside the repository
// (scripts/fuzz-dirs.sh) and is not replayed here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "harnesses.h"

namespace softtune::fuzz {
namespace {

namespace fs = std::filesystem;

std::size_t replay(const std::string& harness, const std::function<void(std::string_view)>& body) {
  std::size_t n = 0;
  for (const char* kind : {"seeds", "regressions"}) {
    const fs::path dir = fs::path(SOFTTUNE_SOURCE_DIR) / "fuzz" / kind / harness;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream bytes;
      bytes << in.rdbuf();
      SCOPED_TRACE(entry.path().string());
      body(bytes.str());
      ++n;
    }
  }
  return n;
}

TEST(FuzzRegressions, TuneRequest) { EXPECT_GT(replay("tune_request", tune_request), 0u); }
TEST(FuzzRegressions, RequestDecode) { EXPECT_GT(replay("request_decode", request_decode), 0u); }
TEST(FuzzRegressions, SimulateRequest) { EXPECT_GT(replay("simulate_request", simulate_request), 0u); }
TEST(FuzzRegressions, AccuracyRequest) { EXPECT_GT(replay("accuracy_request", accuracy_request), 0u); }
TEST(FuzzRegressions, PresetLoad) { EXPECT_GT(replay("preset_load", preset_load), 0u); }

}  // namespace
}  // namespace softtune::fuzz
