// Flags that map one to one onto request fields (flag_fields.cpp): each present flag sets its field, a number
// as a JSON number and a word as a string; absent flags set nothing; a flag that is not a number is refused by name.
#include "cli/flag_fields.h"

#include <gtest/gtest.h>

#include "codec/problem.h"

namespace softtune::cli {
namespace {

using nlohmann::json;

constexpr FlagField kFields[] = {{"damping-ratio", "damping_ratio", true}, {"mode", "mode", false}, {"fps", "fps", true}};

TEST(FlagFields, NamesAreTheFlags) {
  EXPECT_EQ(flag_names(kFields), (std::vector<std::string>{"damping-ratio", "mode", "fps"}));
}

TEST(FlagFields, PresentFlagsSetTheirFieldsWithTheirType) {
  const Flags flags = parse_flags({"--damping-ratio", "0.5", "--mode", "exact"}, flag_names(kFields), {});
  json request = {{"kept", 1}};
  set_fields_from_flags(flags, kFields, request);
  EXPECT_EQ(request, (json{{"kept", 1}, {"damping_ratio", 0.5}, {"mode", "exact"}}));
  EXPECT_TRUE(request["damping_ratio"].is_number());
  EXPECT_FALSE(request.contains("fps"));
}

TEST(FlagFields, ANonNumberIsRefusedNamingTheFlag) {
  const Flags flags = parse_flags({"--fps", "sixty"}, flag_names(kFields), {});
  json request = json::object();
  try {
    set_fields_from_flags(flags, kFields, request);
    FAIL();
  } catch (const codec::Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "--fps");
  }
}

}  // namespace
}  // namespace softtune::cli
