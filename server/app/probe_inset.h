#pragma once
// The probe inset of a scene preview (render::Inset): the tuned probe's samples over the run, the response
// its fit gives, the response that was asked for, and a cursor at each frame's time. It tells in a curve
// what the legend tells in numbers (asked 3.00 Hz ζ 0.50 → measured 2.13, ζ 0.36).

#include <optional>
#include <vector>

#include "softtune/render/draw_model.h"
#include "softtune/scene/runner.h"
#include "softtune/scene/scene.h"

namespace softtune::app {

/// The probe the inset plots: a modal tuning's first measured target, else the first probe with both a
/// request and a fitted frequency and damping ratio, else the first with a fit; -1 for none. A modal
/// target's curve is asked for with the target's request (the designer's), not its probe's own.
int inset_probe(const scene::Scene& scene, const scene::SceneResult& result);

/// The fitted response over the fit's window, from its discrete poles z1, z2 (response_fit.h): the
/// recurrence x[n] = x_e + A z1^n + B z2^n (or (A + B n) z^n for a double pole) through the window's first
/// two samples; NaN outside the window or without poles. One value per sample of `probe`.
std::vector<double> fitted_response(const scene::ProbeSettings& settings, const scene::ProbeResult& probe, double fps);

/// The asked response over the window: the analytic motion at the requested frequency and damping ratio
/// (analytic.h) about the fit's equilibrium, from the window's first sample with the fitted motion's
/// velocity there (without a fit: the last sample as rest, the first difference as velocity); NaN outside
/// the window or without a request. A probe that moves exactly as asked gives back its own samples.
std::vector<double> asked_response(const scene::ProbeSettings& settings, const scene::ProbeResult& probe, double fps);

/// The inset of probe `index` with its cursor at 0 (scene_frames moves it to each frame's time), or
/// nothing without a probe to plot.
std::optional<render::Inset> probe_inset(const scene::Scene& scene, const scene::SceneResult& result, int index);

}  // namespace softtune::app
