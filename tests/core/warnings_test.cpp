// Warning codes and messages (warnings.cpp): every code has its own snake_case name, and each message
// quotes the numbers and the engine it is about.
#include "softtune/warnings.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <cmath>
#include <map>
#include <numbers>
#include <regex>
#include <set>
#include <string>

#include "softtune/engines/engine_model.h"
#include "softtune/softness.h"

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

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// How each code's message ends when it is whole: its last words, or for the codes that end on a number or
// on the engine's rule, that number as the message formats it or the rule itself. A code without an entry
// here fails the tests below.
std::map<WarningCode, std::string> whole_endings(const Warning& w) {
  // printf's own %+.4f, sized first: %f of 1e300 is over 300 digits.
  std::string damping(std::snprintf(nullptr, 0, "damping ratio off by %+.4f", w.limit), '\0');
  std::snprintf(damping.data(), damping.size() + 1, "damping ratio off by %+.4f", w.limit);
  return {
      {WarningCode::nyquist_clamped, "a higher fps to reach it)"},
      {WarningCode::above_nyquist, "more substeps or a higher fps)"},
      {WarningCode::gamma_unrepresentable, "ask for a small damping ratio)"},
      {WarningCode::exact_overflow, "standard softness used instead"},
      {WarningCode::no_constraint, "applies no force at all"},
      {WarningCode::few_steps_per_period, "use substeps or exact mode"},
      {WarningCode::frequency_error, "use exact mode or more substeps"},
      {WarningCode::axis_normalized, "and was normalized"},
      {WarningCode::box2d_v3_clamped, "softer than this spring there"},
      {WarningCode::mujoco_direct_solref, "(-stiffness, -damping) solref instead"},
      {WarningCode::box2d_reduced_mass_error, "frequency on this constraint"},
      {WarningCode::engine_note, "cannot express this tuning exactly"},
      {WarningCode::engine_refuses, std::string(w.detail)},
      {WarningCode::engine_inexact, damping},
      {WarningCode::engine_unstable, "more substeps or a lower frequency"},
  };
}

void expect_whole(const Warning& w) {
  const std::string message = warning_message(w);
  const auto endings = whole_endings(w);
  const auto it = endings.find(w.code);
  ASSERT_NE(it, endings.end()) << warning_code_name(w.code) << " has no ending in whole_endings";
  EXPECT_TRUE(ends_with(message, it->second)) << warning_code_name(w.code) << " cut short (" << message.size()
                                              << " bytes): " << message;
  if (!w.engine.empty() && w.code >= WarningCode::engine_note) {
    EXPECT_TRUE(has(message, std::string(w.engine))) << message;
  }
  if (!w.detail.empty() && (w.code == WarningCode::engine_refuses || w.code == WarningCode::engine_inexact)) {
    EXPECT_TRUE(has(message, std::string(w.detail))) << message;
  }
}

// The longest message of every code: the longest engine name, a rule longer than any engine's, and the
// numbers that print widest (%g of a tiny negative; %f of -1e300 is over 300 digits).
TEST(Warnings, EveryCodesLongestMessageIsWhole) {
  std::string_view longest_name;
  for (const engines::EngineModel* m : engines::engine_models()) {
    if (m->name.size() > longest_name.size()) longest_name = m->name;
  }
  const std::string rule(400, 'r');
  const int last = static_cast<int>(WarningCode::engine_unstable);
  for (int i = 0; i <= last; ++i) {
    for (double v : {-1.2345678901234567e-300, -1.0e300, 1.7976931348623157e308}) {
      SCOPED_TRACE(v);
      expect_whole({static_cast<WarningCode>(i), v, v, longest_name, rule});
    }
  }
  // The 320-byte buffer this replaced cut this one at "runs +0.00% off the ".
  const std::string inexact = warning_message({WarningCode::engine_inexact, 0.0, 0.0125, "box2d_v3",
                                               "its damping floor is about omega h / 2 at this step rate"});
  EXPECT_TRUE(ends_with(inexact, "off the frequency with damping ratio off by +0.0125")) << inexact;
}

// Every warning the engine models raise, over a sweep of frequencies, damping ratios and step rates with
// each setting choice (Box2D v3's substeps, MuJoCo's integrators...), ends as the whole message does.
TEST(Warnings, EveryEngineModelsWarningMessagesAreWhole) {
  std::set<WarningCode> seen;
  for (const engines::EngineModel* m : engines::engine_models()) {
    std::vector<engines::SettingValues> variants{engines::default_settings_of(*m)};
    for (std::size_t s = 0; s < m->settings.size(); ++s) {
      for (std::size_t c = 0; c < m->settings[s].choices.size(); ++c) {
        engines::SettingValues v = engines::default_settings_of(*m);
        v[s] = static_cast<double>(c);
        variants.push_back(v);
      }
    }
    for (const engines::SettingValues& values : variants) {
      for (double hz : {0.2, 2.0, 10.0, 25.0, 60.0}) {
        for (double zeta : {0.0, 0.05, 0.7, 1.0, 4.0}) {
          for (double dt : {1.0 / 30.0, 1.0 / 240.0}) {
            const double omega = 2.0 * std::numbers::pi * hz;
            engines::Target t{2.0, omega, zeta, dt, spring_constants(2.0, omega, zeta), std::nullopt};
            for (const Warning& w : m->report(t, values).warnings) {
              SCOPED_TRACE(std::string(m->name) + " " + std::to_string(hz) + " Hz zeta " + std::to_string(zeta));
              expect_whole(w);
              seen.insert(w.code);
            }
          }
        }
      }
    }
  }
  EXPECT_TRUE(seen.count(WarningCode::engine_inexact)) << "the sweep raised no engine_inexact";
}

}  // namespace
}  // namespace softtune
