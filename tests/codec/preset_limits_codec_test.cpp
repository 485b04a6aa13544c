// The preset search's JSON: the searched range in Hz is the f h range over h, a row without a limit in range
// passes and carries nulls for the side it never found, and an asked frequency above its limit fails the
// summary.
#include "codec/preset_limits_codec.h"

#include <gtest/gtest.h>

namespace softtune::codec {
namespace {

scene::JointStabilityLimit row(const std::string& joint, double asked_hz, LimitKind kind, std::optional<double> stable_hz,
                               std::optional<double> unstable_hz) {
  scene::JointStabilityLimit l;
  l.joint = joint;
  l.joints = {joint};
  l.asked_frequency_hz = asked_hz;
  l.limit.kind = kind;
  l.limit.evaluations = 12;
  l.highest_stable_hz = stable_hz;
  l.stable_side_hz = stable_hz;
  l.unstable_side_hz = unstable_hz;
  if (stable_hz) l.margin = asked_hz / *stable_hz;
  return l;
}

TEST(PresetLimitsCodec, RangeRowsAndSummaryReadAsTheSearchFoundThem) {
  scene::PresetLimitSettings settings;
  scene::PresetStabilityResult result;
  result.h = 1.0 / 60;
  result.steps_per_run = 2400;
  result.joints = {row("spring", 20, LimitKind::none_in_range, 120, std::nullopt),
                   row("upper", 5, LimitKind::found, 8.612, 8.618)};
  nlohmann::json doc = encode_preset_limits("p", settings, result, {});
  const auto& limits = doc["preset_limits"];
  EXPECT_NEAR(limits["searched_hz"][0].get<double>(), settings.lowest_frequency_ratio * 60, 1e-9);
  EXPECT_NEAR(limits["searched_hz"][1].get<double>(), settings.highest_frequency_ratio * 60, 1e-9);
  ASSERT_EQ(limits["limits"].size(), 2u);
  EXPECT_EQ(limits["limits"][0]["kind"], "none_in_range");
  EXPECT_TRUE(limits["limits"][0]["unstable_side_hz"].is_null());
  EXPECT_EQ(limits["limits"][1]["kind"], "found");
  EXPECT_NEAR(limits["limits"][1]["margin"].get<double>(), 5 / 8.612, 1e-12);
  EXPECT_TRUE(doc["summary"]["passed"].get<bool>());
  EXPECT_EQ(doc["summary"]["searches"], 2);

  // Asked 10 Hz on a joint stable only to 8.6 Hz: the summary fails.
  result.joints.push_back(row("lower", 10, LimitKind::found, 8.555, 8.561));
  doc = encode_preset_limits("p", settings, result, {});
  EXPECT_FALSE(doc["summary"]["passed"].get<bool>());
  // Unstable already at the bottom of the scan: no stable side, so the asked frequency is not inside a limit.
  result.joints = {row("weak", 1, LimitKind::unstable_at_lowest, std::nullopt, 0.6)};
  doc = encode_preset_limits("p", settings, result, {});
  EXPECT_FALSE(doc["summary"]["passed"].get<bool>());
  EXPECT_TRUE(doc["preset_limits"]["limits"][0]["highest_stable_hz"].is_null());
}

}  // namespace
}  // namespace softtune::codec
