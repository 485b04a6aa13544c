// Warning codes and messages (warnings.cpp): every code has its own snake_case name, and each message
// quotes the numbers and the engine it is about.
#include "softtune/warnings.h"

#include <gtest/gtest.h>

#include <cctype>
#include <regex>
#include <set>
#include <string>

namespace softtune {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Warnings, EveryCodeHasItsOwnSnakeCaseName) {
  std::set<std::string> names;
  const int last = static_cast<int>(WarningCode::engine_unstable);
  for (int i = 0; i <= last; ++i) {
    const std::string name(warning_code_name(static_cast<WarningCode>(i)));
    EXPECT_NE(name, "warning") << i;  // the fallback for a code without a name
    for (char c : name) EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_') << name;
    names.insert(name);
    // Every code has a message of its own, without an unfilled printf conversion.
    const std::string message = warning_message({static_cast<WarningCode>(i), 1.5, 2.5, "ode", "a rule"});
    EXPECT_FALSE(message.empty()) << name;
    EXPECT_FALSE(std::regex_search(message, std::regex("%[-+#0-9.*]*[diouxXeEfgGsc]"))) << message;
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(last + 1));
  EXPECT_EQ(warning_code_name(WarningCode::nyquist_clamped), "nyquist_clamped");
}

TEST(Warnings, MessagesQuoteTheirNumbersAndEngine) {
  const std::string clamped = warning_message({WarningCode::nyquist_clamped, 40.0, 29.5});
  EXPECT_TRUE(has(clamped, "40 Hz")) << clamped;
  EXPECT_TRUE(has(clamped, "29.5 Hz")) << clamped;
  // A relative error is shown in percent.
  const std::string off = warning_message({WarningCode::frequency_error, 0.123, 0.0});
  EXPECT_TRUE(has(off, "12.3%")) << off;
  const std::string steps = warning_message({WarningCode::few_steps_per_period, 2.5, 4.0});
  EXPECT_TRUE(has(steps, "2.5 steps")) << steps;
  const std::string refuses = warning_message({WarningCode::engine_refuses, 1e9, 0.0, "ode", "erp must be in [0, 1]"});
  EXPECT_TRUE(has(refuses, "ode")) << refuses;
  EXPECT_TRUE(has(refuses, "erp must be in [0, 1]")) << refuses;
  EXPECT_TRUE(has(refuses, "1e+09")) << refuses;
  const std::string inexact = warning_message({WarningCode::engine_inexact, -0.05, 0.01, "bullet", "one spring per axis"});
  EXPECT_TRUE(has(inexact, "bullet")) << inexact;
  EXPECT_TRUE(has(inexact, "-5.00%")) << inexact;
  EXPECT_TRUE(has(inexact, "+0.0100")) << inexact;
}

}  // namespace
}  // namespace softtune
