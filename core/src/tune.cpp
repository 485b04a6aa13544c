#include "softtune/tune.h"

#include <cmath>

#include "softtune/exact_softness.h"
#include "softtune/tune_chain.h"

namespace softtune {

double requested_frequency_hz(const TuneRequest& r) {
  return r.frequency_hz ? *r.frequency_hz : frequency_from_frames(*r.response_frames, r.basis_fps);
}

double requested_damping_ratio(const TuneRequest& r) {
  return r.damping_ratio ? *r.damping_ratio : damping_ratio_of(*r.oscillation);
}

namespace {

double constraint_inverse_mass(const AnyConstraint& c) {
  return std::visit([](const auto& x) { return inverse_effective_mass(x); }, c);
}

double constraint_unit_impulse(const AnyConstraint& c) {
  return std::visit([](const auto& x) { return unit_impulse_response(x); }, c);
}

// A copy of the constraint with a unit axis; `length` receives the original axis length.
AnyConstraint with_unit_axis(const AnyConstraint& c, double& length) {
  return std::visit(
      [&length](auto x) -> AnyConstraint {
        length = x.axis.norm();
        x.axis /= length;
        return x;
      },
      c);
}

std::optional<double> reduced_mass_of(const AnyConstraint& c) {
  return std::visit(
      [](const auto& x) -> std::optional<double> {
        if (x.type != ConstraintType::linear) return std::nullopt;
        return box2d_reduced_mass(x.body_a.mass, x.body_a.is_static, x.body_b.mass, x.body_b.is_static);
      },
      c);
}

}  // namespace

double requested_effective_mass(const TuneRequest& r) {
  if (r.effective_mass) return *r.effective_mass;
  double length = 1.0;
  return 1.0 / constraint_inverse_mass(with_unit_axis(*r.constraint, length));
}

const engines::SettingValues& engine_settings_for(const TuneRequest& r, std::size_t index) {
  if (index < r.engine_settings.size() && !r.engine_settings[index].empty()) return r.engine_settings[index];
  return engines::default_settings_of(*engines::engine_models()[index]);
}

namespace {

// The effective mass the spring acts on: given, or the constraint's 1 / (J M^-1 J^T) along a unit axis.
void find_effective_mass(const TuneRequest& r, TuneResult& out) {
  if (!r.constraint) {
    out.effective_mass = *r.effective_mass;
    return;
  }
  out.stages.add(Stage::effective_mass);
  double length = 1.0;
  const AnyConstraint unit = with_unit_axis(*r.constraint, length);
  if (std::abs(length - 1.0) > 1e-9) out.warnings.push_back({WarningCode::axis_normalized, length, 1.0});
  out.effective_mass = 1.0 / constraint_inverse_mass(unit);
  out.inverse_effective_mass_impulse = constraint_unit_impulse(unit);
  out.box2d_reduced_mass = reduced_mass_of(unit);
}

// The step model of the asked spring, and the warnings about what the step can represent. Exact mode may
// clamp omega to Nyquist; everything downstream uses the clamped value.
StepModel soften(const TuneRequest& r, double asked_hz, TuneResult& out) {
  out.stages.add(Stage::softness);
  out.stages.add(Stage::exact_softness);
  StepModel model = make_step_model(out.effective_mass, out.omega, out.damping_ratio, out.h);
  const double nyquist_hz = 0.5 / out.h;
  if (r.mode == SoftMode::exact) {
    if (model.exact.clamped_to_nyquist) {
      out.warnings.push_back({WarningCode::nyquist_clamped, asked_hz, frequency_from_angular(model.exact.omega)});
      out.omega = model.exact.omega;
      model = make_step_model(out.effective_mass, out.omega, out.damping_ratio, out.h);
    }
    if (!model.exact.finite) {
      out.warnings.push_back({WarningCode::exact_overflow, out.damping_ratio * out.omega * out.h, 0.0});
    } else if (model.exact.softness.kind == SoftnessKind::unrepresentable && out.omega > 0.0) {
      out.warnings.push_back({WarningCode::gamma_unrepresentable, 0.0, 0.0});
    }
  } else if (asked_hz * std::sqrt(std::max(0.0, 1.0 - out.damping_ratio * out.damping_ratio)) > nyquist_hz) {
    out.warnings.push_back({WarningCode::above_nyquist, asked_hz, nyquist_hz});
  }
  return model;
}

// The spring and softness of the chosen mode, and Box2D v3's (hertz, ratio) form of that spring.
void choose_spring(const TuneRequest& r, const StepModel& model, TuneResult& out) {
  out.frequency_hz = frequency_from_angular(out.omega);
  out.standard_spring = {model.spring.stiffness, model.spring.damping};
  const bool exact = r.mode == SoftMode::exact;
  out.spring = exact ? model.exact.spring : out.standard_spring;
  out.softness = exact ? model.exact.softness : model.soft;
  if (out.softness.kind == SoftnessKind::no_constraint) out.warnings.push_back({WarningCode::no_constraint});
  // a1 = (c + h k) / (m omega) must be positive for the (hertz, ratio) form to exist.
  const Oscillator used{out.effective_mass, out.spring.stiffness, out.spring.damping};
  const double used_omega = natural_angular_frequency(used);
  if (used_omega == 0.0 || out.spring.damping + out.h * out.spring.stiffness > 0.0) {
    out.box2d_v3 = soft_v3(used_omega, damping_ratio_of(used), out.h);
  }
}

// Every integrator's discrete response to this spring at this step; the chosen mode's is what is achieved.
void analyze_methods(const TuneRequest& r, const StepModel& model, TuneResult& out) {
  out.stages.add(Stage::discrete_analysis);
  for (std::size_t i = 0; i < kAllMethods.size(); ++i) {
    out.stability[i] = analyze(kAllMethods[i], model, out.omega, out.damping_ratio);
  }
  const bool exact = r.mode == SoftMode::exact;
  const DiscreteAnalysis& chosen = out.stability[method_index(exact ? Method::soft_exact : Method::soft)];
  out.achieved_frequency_hz = chosen.achieved_frequency_hz;
  out.achieved_damping_ratio = chosen.achieved_damping_ratio;
  out.achieved_damped_frequency_hz = chosen.achieved_damped_frequency_hz;
  out.achieved_spectral_radius = chosen.spectral_radius;
  if (chosen.steps_per_period && *chosen.steps_per_period < 4.0) {
    out.warnings.push_back({WarningCode::few_steps_per_period, *chosen.steps_per_period, 4.0});
  }
  if (!exact && out.frequency_hz > 0.0 && out.achieved_frequency_hz) {
    const double error = *out.achieved_frequency_hz / out.frequency_hz - 1.0;
    if (std::abs(error) > 0.05) out.warnings.push_back({WarningCode::frequency_error, error, 0.05});
  }
}

// The plain export in each engine's units, then each engine's own step (docs/engines.md): what it does with the
// export, and what makes it do the request.
void export_to_engines(const TuneRequest& r, TuneResult& out) {
  out.stages.add(Stage::engine_export);
  EngineExportInput in;
  in.effective_mass = out.effective_mass;
  in.omega = out.omega;
  in.damping_ratio = out.damping_ratio;
  in.h = out.h;
  in.spring = out.spring;
  in.box2d_reduced_mass = out.box2d_reduced_mass;
  out.engines = export_engines(in, out.warnings);

  out.stages.add(Stage::engine_models);
  engines::Target target;
  target.effective_mass = out.effective_mass;
  target.omega = out.omega;
  target.damping_ratio = out.damping_ratio;
  target.dt = out.h;
  target.spring = out.spring;
  target.box2d_reduced_mass = out.box2d_reduced_mass;
  const auto models = engines::engine_models();
  out.engine_reports.reserve(models.size());
  for (std::size_t i = 0; i < models.size(); ++i) {
    out.engine_reports.push_back(models[i]->report(target, engine_settings_for(r, i)));
  }
}

}  // namespace

TuneResult tune(const TuneRequest& r) {
  TuneResult out;
  out.stages.add(Stage::validate);
  // Designer mapping (docs/math.md): f = B / N or given; zeta from the level or given.
  out.stages.add(Stage::designer_mapping);
  out.h = step_size(r.fps, r.substeps);
  const double asked_hz = requested_frequency_hz(r);
  out.damping_ratio = requested_damping_ratio(r);
  out.omega = angular_frequency(asked_hz);
  find_effective_mass(r, out);
  const StepModel model = soften(r, asked_hz, out);
  choose_spring(r, model, out);
  analyze_methods(r, model, out);
  export_to_engines(r, out);
  if (r.chain) {
    out.stages.add(Stage::sequential_impulse_chain);
    out.chain = design_chain(chain_design_request(r, out));
  }
  return out;
}

}  // namespace softtune
