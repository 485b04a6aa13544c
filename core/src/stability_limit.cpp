#include "softtune/stability_limit.h"

#include <cmath>
#include <vector>

namespace softtune {
namespace {

bool unstable(double rho) { return classify_spectral_radius(rho) == Verdict::unstable; }

}  // namespace

StabilityLimit bisect_stability_limit(const SpectralRadiusOf& rho, double stable, double unstable_p,
                                      double relative_tolerance) {
  StabilityLimit out;
  out.kind = LimitKind::found;
  double lo = stable, hi = unstable_p;
  double rho_lo = rho(lo), rho_hi = rho(hi);
  out.evaluations = 2;
  // Bounded: the relative width halves (in log) every step, from at most 1e300 to 1e-3 in ~60 steps.
  for (int i = 0; i < 200 && std::abs(hi / lo - 1.0) > relative_tolerance; ++i) {
    const double mid = std::sqrt(lo) * std::sqrt(hi);
    const double r = rho(mid);
    ++out.evaluations;
    if (unstable(r)) {
      hi = mid;
      rho_hi = r;
    } else {
      lo = mid;
      rho_lo = r;
    }
  }
  out.stable_side = lo;
  out.unstable_side = hi;
  out.stable_side_radius = rho_lo;
  out.unstable_side_radius = rho_hi;
  return out;
}

StabilityLimit find_stability_limit(const SpectralRadiusOf& rho, std::span<const double> scan,
                                    double relative_tolerance) {
  StabilityLimit out;
  std::optional<double> last_stable;
  double last_radius = 0.0;
  for (double p : scan) {
    const double r = rho(p);
    ++out.evaluations;
    if (unstable(r)) {
      if (!last_stable) {
        out.kind = LimitKind::unstable_at_lowest;
        out.unstable_side = p;
        out.unstable_side_radius = r;
        return out;
      }
      const int scanned = out.evaluations;
      out = bisect_stability_limit(rho, *last_stable, p, relative_tolerance);
      out.evaluations += scanned;
      return out;
    }
    last_stable = p;
    last_radius = r;
  }
  out.kind = LimitKind::none_in_range;
  out.stable_side = last_stable;
  out.stable_side_radius = last_radius;
  return out;
}

std::vector<double> log_scan(double lo, double hi, int n) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(i + 1 == n ? hi : lo * std::pow(hi / lo, i / double(n - 1)));
  return out;
}

}  // namespace softtune
