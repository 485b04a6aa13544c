#pragma once
// The whole translation: designer request -> oscillator, spring constants, softness in every form,
// exact softness, discrete analysis per integrator, engine export, warnings and the stages that ran.

#include <array>
#include <optional>
#include <variant>

#include "softtune/chain_design.h"
#include "softtune/designer.h"
#include "softtune/diagnostics.h"
#include "softtune/discrete_analysis.h"
#include "softtune/effective_mass.h"
#include "softtune/engine_export.h"
#include "softtune/engines/engine_model.h"
#include "softtune/warnings.h"

namespace softtune {

enum class SoftMode { standard, exact };

using AnyConstraint = std::variant<Constraint2D, Constraint3D>;

/// A tune request (the `softtune tune` / POST /api/v1/tune contract). Ranges: core/validation.h.
struct TuneRequest {
  double fps = 60.0;                        ///< Hz, frames per second of the game step
  int substeps = 1;                         ///< solver substeps per frame; h = 1 / (fps substeps)
  std::optional<double> response_frames;    ///< frames per oscillation period on basis_fps
  double basis_fps = 60.0;                  ///< Hz, the clock response_frames counts
  std::optional<double> frequency_hz;       ///< Hz, instead of response_frames
  std::optional<Oscillation> oscillation;   ///< free / some / none
  std::optional<double> damping_ratio;      ///< instead of oscillation, >= 0
  SoftMode mode = SoftMode::standard;
  std::optional<double> effective_mass;     ///< kg (or kg m^2 for angular)
  std::optional<AnyConstraint> constraint;  ///< instead of effective_mass
  /// Per modelled engine (indexed like engines::engine_models()), the settings its model assumes; a
  /// missing or empty entry means the engine's defaults. Values within each SettingSpec's range.
  std::vector<engines::SettingValues> engine_settings;
  /// A mass-ratio chain to answer for (chain_design.h, tune_chain.h); empty: none.
  std::optional<ChainAsk> chain;
};

struct TuneResult {
  double h = 0.0;               ///< s, the solver (sub)step
  double frequency_hz = 0.0;    ///< Hz, the natural frequency used (after any clamp)
  double omega = 0.0;           ///< rad/s
  double damping_ratio = 0.0;
  double effective_mass = 0.0;  ///< kg
  SpringConstants spring;            ///< k, c used (k', c' in exact mode)
  SpringConstants standard_spring;   ///< k = m omega^2, c = 2 m zeta omega, whatever the mode
  Softness softness;                 ///< gamma, beta of `spring` at h
  std::optional<SoftV3> box2d_v3;    ///< empty when not representable
  std::optional<double> box2d_reduced_mass;  ///< kg, what b2LinearStiffness uses (constraint given)
  double inverse_effective_mass_impulse = 0.0;  ///< 1/kg from the unit-impulse experiment (constraint given)
  std::optional<double> achieved_frequency_hz;  ///< of the chosen soft method's discrete poles
  std::optional<double> achieved_damping_ratio;
  std::optional<double> achieved_damped_frequency_hz;  ///< Hz, Im(s) / (2 pi)
  double achieved_spectral_radius = 0.0;
  std::array<DiscreteAnalysis, kAllMethods.size()> stability;  ///< indexed like kAllMethods
  EngineExport engines;
  /// Per modelled engine (indexed like engines::engine_models()): its settings, what to type, what it
  /// will do, and what to type so it does what was asked.
  std::vector<engines::EngineReport> engine_reports;
  /// Per solver of request.chain: the chain's limit with the request's settings and the fewest counts.
  std::vector<ChainDesign> chain;
  Warnings warnings;
  StageList stages;
};

/// The settings the model at `index` of engines::engine_models() runs with for this request: the request's
/// engine_settings entry when it has one, else that engine's defaults.
const engines::SettingValues& engine_settings_for(const TuneRequest& request, std::size_t index);

/// Runs a request that passed validate_tune_request().
TuneResult tune(const TuneRequest& request);

/// The designer's frequency (Hz) and damping ratio for a valid request.
double requested_frequency_hz(const TuneRequest& request);
double requested_damping_ratio(const TuneRequest& request);

/// The effective mass of a valid request: given directly, or 1 / K of its constraint.
double requested_effective_mass(const TuneRequest& request);

}  // namespace softtune
