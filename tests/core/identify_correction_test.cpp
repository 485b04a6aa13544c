// The correction against black-box engines with known errors: one recording scales out a constant factor
// exactly; a second one (the secant) takes out an error that grows with the value.
#include "softtune/identify_correction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace softtune {
namespace {

// An engine whose frequency is off by a power law and whose damping by an affine map.
ResponseValues engine(const ResponseValues& typed) {
  return {0.9 * std::pow(typed.frequency_hz, 1.05), 0.8 * typed.damping_ratio + 0.04};
}

// One recording: a constant factor on the frequency (a wrong mass) and an added damping ratio (a step's
// numerical damping) are taken out exactly.
TEST(IdentifyCorrection, OneRecordingTakesOutAFactorAndAnOffset) {
  const ResponseValues asked{5.0, 0.5};
  const ResponseValues typed = asked;
  const ResponseValues measured{typed.frequency_hz * 0.86, typed.damping_ratio + 0.11};
  const CorrectionRound round{typed, measured};
  const Correction c = correct_response(asked, std::span(&round, 1));
  EXPECT_EQ(c.method, CorrectionMethod::scaled);
  EXPECT_NEAR(c.next.frequency_hz * 0.86, 5.0, 1e-12);
  EXPECT_NEAR(c.next.damping_ratio + 0.11, 0.5, 1e-12);
}

TEST(IdentifyCorrection, SecantConvergesOnAValueDependentError) {
  const ResponseValues asked{5.0, 0.5};
  std::vector<CorrectionRound> rounds = {{asked, engine(asked)}};
  for (int i = 0; i < 4; ++i) {
    const Correction c = correct_response(asked, rounds);
    EXPECT_EQ(c.method, i == 0 ? CorrectionMethod::scaled : CorrectionMethod::secant);
    rounds.push_back({c.next, engine(c.next)});
  }
  const ResponseValues last = rounds.back().measured;
  EXPECT_NEAR(last.frequency_hz / 5.0, 1.0, 1e-6);
  EXPECT_NEAR(last.damping_ratio, 0.5, 1e-6);
}

TEST(IdentifyCorrection, DampingIsNeverNegative) {
  const ResponseValues asked{2.0, 0.0};
  const CorrectionRound round{asked, {2.0, 0.03}};  // numerical damping on a free oscillation
  const Correction c = correct_response(asked, std::span(&round, 1));
  EXPECT_EQ(c.next.damping_ratio, 0.0);
  const CorrectionRound under{{2.0, 0.2}, {2.0, 0.1}};
  EXPECT_NEAR(correct_response({2.0, 0.02}, std::span(&under, 1)).next.damping_ratio, 0.12, 1e-12);
}

}  // namespace
}  // namespace softtune
