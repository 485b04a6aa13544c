// The tune flags (tune_flags.cpp): the help lists exactly the flags parsed, and the flags give the request
// fields of the tune contract (docs/api.md), which the tune use case accepts: 12 frames at 60 fps is 5 Hz, and
// k = m omega^2.
#include "cli/tune_flags.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>
#include <string>

#include "app/tune_app.h"

namespace softtune::cli {
namespace {

using nlohmann::json;

TEST(TuneFlags, HelpListsExactlyTheFlags) {
  std::vector<std::string> in_help;
  std::istringstream help(kTuneFlagsHelp);
  const std::regex flag(R"(^ +--([a-z-]+) )");
  std::smatch m;
  for (std::string line; std::getline(help, line);) {
    if (std::regex_search(line, m, flag)) in_help.push_back(m[1]);
  }
  EXPECT_EQ(in_help, tune_flag_names());
  EXPECT_EQ(in_help.size(), 9u);
}

TEST(TuneFlags, FlagsGiveTheContractFields) {
  const Flags flags = parse_flags({"--frames", "12", "--basis-fps", "60", "--oscillation", "free", "--mass", "2", "--fps",
                                   "60", "--substeps", "1", "--mode", "standard"},
                                  tune_flag_names(), {});
  const json request = tune_fields_from_flags(flags);
  EXPECT_EQ(request, (json{{"response_frames", 12.0}, {"basis_fps", 60.0}, {"oscillation", "free"}, {"effective_mass", 2.0},
                           {"fps", 60.0}, {"substeps", 1.0}, {"mode", "standard"}}));
  const json r = app::run_tune(request);
  EXPECT_NEAR(r["frequency_hz"].get<double>(), 5.0, 1e-12);
  EXPECT_NEAR(r["k"].get<double>(), 2.0 * std::pow(2.0 * M_PI * 5.0, 2), 1e-9);
  EXPECT_EQ(tune_fields_from_flags(parse_flags({}, tune_flag_names(), {})), json::object());
  const json alt = tune_fields_from_flags(parse_flags({"--frequency", "3", "--damping-ratio", "0.25"}, tune_flag_names(), {}));
  EXPECT_EQ(alt, (json{{"frequency_hz", 3.0}, {"damping_ratio", 0.25}}));
}

}  // namespace
}  // namespace softtune::cli
