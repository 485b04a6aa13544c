#include "app/probe_inset.h"

#include <cmath>
#include <complex>
#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>
#include <numbers>

#include "softtune/analytic.h"

namespace softtune::app {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The window measure_probe fits (runner.cpp): samples begin..end.
std::pair<int, int> window_of(const scene::ProbeSettings& p, const scene::ProbeResult& r, double fps) {
  const int last = static_cast<int>(r.value.size()) - 1;
  const int begin = std::min(last, static_cast<int>(std::ceil(p.from_s * fps - 1e-9)));
  const int end = p.to_s ? std::min(last, static_cast<int>(std::floor(*p.to_s * fps + 1e-9))) : last;
  return {begin, end};
}

// The fit's motion through the window's first two samples: x[n] = x_e + A z1^n + B z2^n (distinct poles).
struct Modes {
  std::complex<double> z1, z2, a, b;
  bool double_pole = false;  // then x[n] = x_e + (a + b n) z1^n
  double xe = 0.0;
};
std::optional<Modes> modes_of(const ResponseFit& fit, const std::vector<double>& value, int begin) {
  if (!fit.z1 || !fit.z2 || !fit.equilibrium || begin < 0 || begin + 1 >= static_cast<int>(value.size())) return std::nullopt;
  Modes m;
  m.z1 = *fit.z1, m.z2 = *fit.z2, m.xe = *fit.equilibrium;
  const double d0 = value[begin] - m.xe, d1 = value[begin + 1] - m.xe;
  if (std::abs(m.z1 - m.z2) > 1e-9 * std::max(1.0, std::abs(m.z1))) {
    m.b = (d1 - m.z1 * d0) / (m.z2 - m.z1);  // A + B = d0, A z1 + B z2 = d1
    m.a = d0 - m.b;
  } else {
    m.double_pole = true;
    m.z1 = 0.5 * (m.z1 + m.z2);
    m.a = d0;  // (A + B) z = d1
    m.b = d1 / m.z1 - m.a;
  }
  return m;
}

// What was asked of probe i: a modal tuning's target it measures (the designer asked for the mode; the
// probe's own request is then the solve's per-spring equivalent, which nobody asked for), else its own.
scene::ProbeResult with_designers_ask(const scene::Scene& scene, const scene::SceneResult& result, int i) {
  scene::ProbeResult p = result.probes[i];
  if (!result.modal_tuning) return p;
  for (const scene::ModalTargetResult& t : result.modal_tuning->targets) {
    if (t.probe != scene.probes[i].id) continue;
    p.requested_frequency_hz = t.requested_frequency_hz;
    p.requested_damping_ratio = t.requested_damping_ratio;
  }
  return p;
}

}  // namespace

int inset_probe(const scene::Scene& scene, const scene::SceneResult& result) {
  // A modal tuning's first measured target first: the motion the designer asked for.
  if (result.modal_tuning) {
    for (const scene::ModalTargetResult& t : result.modal_tuning->targets) {
      for (std::size_t i = 0; i < result.probes.size() && i < scene.probes.size(); ++i) {
        if (scene.probes[i].id == t.probe && result.probes[i].measured.frequency_hz && result.probes[i].value.size() >= 2) {
          return static_cast<int>(i);
        }
      }
    }
  }
  int fitted = -1;
  for (std::size_t i = 0; i < result.probes.size() && i < scene.probes.size(); ++i) {
    const scene::ProbeResult& p = result.probes[i];
    if (p.value.size() < 2 || !p.measured.frequency_hz || !p.measured.damping_ratio) continue;
    if (p.requested_frequency_hz && p.requested_damping_ratio) return static_cast<int>(i);
    if (fitted < 0) fitted = static_cast<int>(i);
  }
  return fitted;
}

std::vector<double> fitted_response(const scene::ProbeSettings& settings, const scene::ProbeResult& probe, double fps) {
  std::vector<double> out(probe.value.size(), kNaN);
  const auto [begin, end] = window_of(settings, probe, fps);
  const std::optional<Modes> m = modes_of(probe.measured, probe.value, begin);
  if (!m || end < begin + 1) return out;
  std::complex<double> p1 = 1.0, p2 = 1.0;
  for (int n = 0; begin + n <= end; ++n, p1 *= m->z1, p2 *= m->z2) {
    out[begin + n] = m->xe + std::real(m->double_pole ? (m->a + m->b * static_cast<double>(n)) * p1 : m->a * p1 + m->b * p2);
  }
  return out;
}

std::vector<double> asked_response(const scene::ProbeSettings& settings, const scene::ProbeResult& probe, double fps) {
  std::vector<double> out(probe.value.size(), kNaN);
  const auto [begin, end] = window_of(settings, probe, fps);
  if (!probe.requested_frequency_hz || !probe.requested_damping_ratio || begin < 0 || end < begin + 1) return out;
  // The fit's own start: its equilibrium, the window's first sample and the fitted motion's velocity there
  // (s = ln(z) fps, v0 = Re(A s1 + B s2)), so a probe that moves as asked gives back its own samples;
  // without a fit, the last sample as rest and the first difference as velocity.
  double xe = probe.value[end], v0 = (probe.value[begin + 1] - probe.value[begin]) * fps;
  if (const std::optional<Modes> m = modes_of(probe.measured, probe.value, begin)) {
    xe = m->xe;
    const std::complex<double> s1 = std::log(m->z1) * fps, s2 = std::log(m->z2) * fps;
    v0 = std::real(m->double_pole ? m->a * s1 + m->b * fps : m->a * s1 + m->b * s2);
  }
  const State start{probe.value[begin] - xe, v0};
  const double omega = 2.0 * std::numbers::pi * *probe.requested_frequency_hz;
  for (int n = begin; n <= end; ++n) out[n] = xe + analytic_state(start, omega, *probe.requested_damping_ratio, (n - begin) / fps).x;
  return out;
}

std::optional<render::Inset> probe_inset(const scene::Scene& scene, const scene::SceneResult& result, int index) {
  if (index < 0 || index >= static_cast<int>(result.probes.size()) || index >= static_cast<int>(scene.probes.size())) {
    return std::nullopt;
  }
  const scene::ProbeSettings& settings = scene.probes[index];
  const scene::ProbeResult probe = with_designers_ask(scene, result, index);
  const double fps = scene.world.fps;
  render::Inset inset;
  inset.t_s = probe.time_s;
  inset.value = probe.value;
  inset.fitted = fitted_response(settings, probe, fps);
  inset.asked = asked_response(settings, probe, fps);
  // Two lines: what is plotted and how much it spans (the plot fills its own range, so a motion under a
  // pixel in the scene fills it), then the fit and the request.
  double lo = INFINITY, hi = -INFINITY;
  for (double v : probe.value) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  const bool angular = settings.kind == scene::ProbeKind::angle || settings.kind == scene::ProbeKind::joint_angle;
  const double span = lo <= hi ? (angular ? hi - lo : 100.0 * (hi - lo)) : 0.0;
  char title[240];
  const int n = std::snprintf(title, sizeof title, "%s, spans %.3g %s\nfit %.2f Hz \u03b6 %.2f", probe.id.c_str(), span,
                              angular ? "rad" : "cm",
                              probe.measured.frequency_hz.value_or(0.0), probe.measured.damping_ratio.value_or(0.0));
  if (probe.requested_frequency_hz && probe.requested_damping_ratio && n > 0 && n < static_cast<int>(sizeof title)) {
    std::snprintf(title + n, sizeof title - n, "  \u00b7  asked %.2f Hz \u03b6 %.2f", *probe.requested_frequency_hz,
                  *probe.requested_damping_ratio);
  }
  inset.title = title;
  return inset;
}

}  // namespace softtune::app
