#include "softtune/identify_correction.h"

#include <algorithm>
#include <cmath>

namespace softtune {
namespace {

// zeta_typed + zeta_asked - zeta_measured: a step's numerical damping adds to the ratio.
double scaled_damping(double typed, double asked, double measured) { return std::max(0.0, typed + asked - measured); }

bool trusted(double slope) { return std::isfinite(slope) && slope >= 1.0 / kCorrectionMaxSlope && slope <= kCorrectionMaxSlope; }

}  // namespace

Correction correct_response(const ResponseValues& asked, std::span<const CorrectionRound> rounds) {
  const CorrectionRound& last = rounds.back();
  Correction out;
  out.next.frequency_hz = last.typed.frequency_hz * asked.frequency_hz / last.measured.frequency_hz;
  out.next.damping_ratio = scaled_damping(last.typed.damping_ratio, asked.damping_ratio, last.measured.damping_ratio);
  if (rounds.size() < 2) return out;
  const CorrectionRound& before = rounds[rounds.size() - 2];
  // ln f_measured = a + b ln f_typed through both recordings, solved for f_measured = f_asked.
  const double df_typed = std::log(last.typed.frequency_hz / before.typed.frequency_hz);
  const double frequency_slope = std::log(last.measured.frequency_hz / before.measured.frequency_hz) / df_typed;
  bool secant = false;
  if (trusted(frequency_slope)) {
    out.next.frequency_hz = last.typed.frequency_hz *
                            std::exp(std::log(asked.frequency_hz / last.measured.frequency_hz) / frequency_slope);
    secant = true;
  }
  // zeta_measured = a + b zeta_typed, the same way.
  const double damping_slope = (last.measured.damping_ratio - before.measured.damping_ratio) /
                               (last.typed.damping_ratio - before.typed.damping_ratio);
  if (trusted(damping_slope)) {
    out.next.damping_ratio =
        std::max(0.0, last.typed.damping_ratio + (asked.damping_ratio - last.measured.damping_ratio) / damping_slope);
    secant = true;
  }
  out.method = secant ? CorrectionMethod::secant : CorrectionMethod::scaled;
  return out;
}

}  // namespace softtune
