// The scene engine flags (engine_flags.cpp): --engine and --engine-settings name=value,... into the request's
// engine and engine_settings, values typed as a request would carry them; a malformed item names the flag.
#include "cli/engine_flags.h"

#include <gtest/gtest.h>

#include "codec/problem.h"

namespace softtune::cli {
namespace {

using nlohmann::json;

json engine_flags_request(const Args& args) {
  const Flags f = parse_flags(args, with_engine_flags({"preset"}), {});
  json request = {{"preset", "vehicle"}};
  set_engine_from_flags(f, request);
  return request;
}

TEST(EngineFlags, EngineAndSettingsBecomeTheRequestsFields) {
  EXPECT_EQ(engine_flags_request({"--preset", "vehicle"}), (json{{"preset", "vehicle"}}));
  const json r = engine_flags_request({"--engine", "mujoco", "--engine-settings", "iterations=50,integrator=implicit,warm=true,h=0.25"});
  EXPECT_EQ(r["engine"], "mujoco");
  EXPECT_EQ(r["engine_settings"], (json{{"iterations", 50}, {"integrator", "implicit"}, {"warm", true}, {"h", 0.25}}));
  EXPECT_TRUE(r["engine_settings"]["iterations"].is_number_integer());
  EXPECT_EQ(engine_flags_request({"--engine=box2d_v2_4"})["engine"], "box2d_v2_4");
}

TEST(EngineFlags, AMalformedSettingNamesTheFlag) {
  for (const char* bad : {"iterations", "=5", "iterations=", "a=1,,b=2", "a=1,"}) {
    try {
      engine_flags_request({"--engine-settings", bad});
      ADD_FAILURE() << "accepted " << bad;
    } catch (const codec::Problem& p) {
      EXPECT_EQ(p.field, "--engine-settings") << bad;
      EXPECT_EQ(p.status, 422);
    }
  }
}

}  // namespace
}  // namespace softtune::cli
