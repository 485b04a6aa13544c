// The tune use case (tune_app.cpp): decode, tune and encode in one call. The designer mapping's closed forms
// hold in the answer: 12 frames at 60 fps is 5 Hz, k = m omega^2, c = 2 m zeta omega, and the soft constraint's
// gamma = 1 / (c + h k), beta = h k / (c + h k) (Catto GDC 2011, force form; the impulse form is gamma / h);
// bad input is a Problem.
#include "app/tune_app.h"

#include <gtest/gtest.h>

#include <cmath>

#include "codec/problem.h"

namespace softtune::app {
namespace {

using nlohmann::json;

TEST(TuneApp, StandardModeAnswerHasTheClosedForms) {
  const json r = run_tune({{"response_frames", 12}, {"damping_ratio", 0.5}, {"effective_mass", 2}, {"fps", 60}});
  const double m = 2.0, omega = 2.0 * M_PI * 5.0, zeta = 0.5, h = 1.0 / 60.0;
  const double k = m * omega * omega, c = 2.0 * m * zeta * omega;
  EXPECT_NEAR(r["frequency_hz"].get<double>(), 5.0, 1e-12);
  EXPECT_NEAR(r["h"].get<double>(), h, 1e-15);
  EXPECT_NEAR(r["k"].get<double>(), k, 1e-9 * k);
  EXPECT_NEAR(r["c"].get<double>(), c, 1e-9 * c);
  EXPECT_NEAR(r["gamma"].get<double>(), 1.0 / (c + h * k), 1e-12);
  EXPECT_NEAR(r["gamma_impulse"].get<double>(), 1.0 / (h * (c + h * k)), 1e-12);
  EXPECT_NEAR(r["beta"].get<double>(), h * k / (c + h * k), 1e-12);
}

TEST(TuneApp, BadInputIsAProblemNamingTheField) {
  try {
    run_tune({{"response_frames", 12}, {"oscillation", "some"}});
    FAIL() << "a request without a mass was accepted";
  } catch (const codec::Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "effective_mass");
  }
}

}  // namespace
}  // namespace softtune::app
