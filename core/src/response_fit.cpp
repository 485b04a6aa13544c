#include "softtune/response_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "softtune/discrete_analysis.h"

namespace softtune {
namespace {

constexpr int kMinSamples = 8;

}  // namespace

int fit_window(const std::vector<double>& x) {
  if (x.empty()) return 0;
  const double last = x.back();
  double largest = 0.0;
  for (double v : x) largest = std::max(largest, std::abs(v - last));
  int end = 0;
  for (int n = 0; n < static_cast<int>(x.size()); ++n) {
    if (std::abs(x[n] - last) > kFitFloor * largest) end = n;
  }
  return std::min(static_cast<int>(x.size()), end + 3);
}

std::optional<double> overshoot_of(const std::vector<double>& x, double equilibrium) {
  if (x.empty()) return std::nullopt;
  const double dev0 = x.front() - equilibrium;
  if (!(std::abs(dev0) > 0.0)) return std::nullopt;
  const double sign = dev0 > 0.0 ? 1.0 : -1.0;
  double past = 0.0;
  for (double v : x) past = std::max(past, -(v - equilibrium) * sign);
  return past / std::abs(dev0);
}

std::optional<int> settle_index(const std::vector<double>& x, double equilibrium, double band) {
  if (x.empty()) return std::nullopt;
  const double tolerance = band * std::abs(x.front() - equilibrium);
  if (!(tolerance > 0.0)) return std::nullopt;
  int last_outside = -1;
  for (int n = 0; n < static_cast<int>(x.size()); ++n) {
    if (std::abs(x[n] - equilibrium) > tolerance) last_outside = n;
  }
  if (last_outside == static_cast<int>(x.size()) - 1) return std::nullopt;
  return last_outside + 1;
}

ResponseFit fit_response(const std::vector<double>& x, double h) {
  ResponseFit out;
  if (static_cast<int>(x.size()) < kMinSamples || !(h > 0.0)) return out;
  for (double v : x) {
    if (!std::isfinite(v)) return out;
  }
  out.equilibrium = x.back();

  const int n = fit_window(x);
  if (n >= kMinSamples) {
    // Centre and scale so the three columns (x[n-1], x[n-2], 1) are well conditioned.
    double mean = 0.0;
    for (int i = 0; i < n; ++i) mean += x[i];
    mean /= n;
    double scale = 0.0;
    for (int i = 0; i < n; ++i) scale = std::max(scale, std::abs(x[i] - mean));
    if (scale > 0.0) {
      const int rows = n - 2;
      Eigen::Matrix<double, Eigen::Dynamic, 3> a(rows, 3);
      Eigen::VectorXd y(rows);
      for (int i = 0; i < rows; ++i) {
        a(i, 0) = (x[i + 1] - mean) / scale;
        a(i, 1) = (x[i] - mean) / scale;
        a(i, 2) = 1.0;
        y(i) = (x[i + 2] - mean) / scale;
      }
      // Householder QR on three columns; the fit is refused when R is (numerically) singular, e.g. a pure
      // exponential, whose two lagged columns are proportional.
      const Eigen::HouseholderQR<Eigen::Matrix<double, Eigen::Dynamic, 3>> qr(a);
      const Eigen::Matrix3d r = qr.matrixQR().topRows<3>().triangularView<Eigen::Upper>();
      const double largest = r.diagonal().cwiseAbs().maxCoeff();
      if (largest > 0.0 && r.diagonal().cwiseAbs().minCoeff() > 1e-10 * largest) {
        const Eigen::Vector3d p = qr.solve(y);
        out.samples_used = n;
        out.residual = (a * p - y).norm() / std::max(y.norm(), 1e-300);
        const RecurrencePoles poles = poles_of_recurrence(p(0), p(1), h);
        out.z1 = poles.z1;
        out.z2 = poles.z2;
        out.frequency_hz = poles.frequency_hz;
        out.damping_ratio = poles.damping_ratio;
        // x_e = b / (1 - a1 - a2), back in the original units; undefined for an undamped (marginal) fit.
        const double denominator = 1.0 - p(0) - p(1);
        if (std::abs(denominator) > 1e-9) out.equilibrium = mean + scale * p(2) / denominator;
      }
    }
  }
  out.overshoot = overshoot_of(x, *out.equilibrium);
  out.settle_samples = settle_index(x, *out.equilibrium, kSettleBand);
  return out;
}

}  // namespace softtune
