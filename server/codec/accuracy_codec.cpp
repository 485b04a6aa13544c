#include "codec/accuracy_codec.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <set>

#include "codec/json_writer.h"
#include "codec/list_reader.h"
#include "codec/problem.h"
#include "codec/tune_codec.h"
#include "softtune/analytic.h"
#include "softtune/designer.h"
#include "softtune/discrete_analysis.h"
#include "softtune/validation.h"

namespace softtune::codec {

using nlohmann::json;

namespace {

// Every fps to run: the step rates plus the request's own, ascending, once each.
std::vector<double> frame_rates(const std::vector<double>& step_rates, double request_fps) {
  std::set<double> all(step_rates.begin(), step_rates.end());
  all.insert(request_fps);
  return {all.begin(), all.end()};
}

std::vector<int> substep_counts(const std::vector<int>& counts, int request_substeps) {
  std::set<int> all(counts.begin(), counts.end());
  all.insert(1);
  all.insert(request_substeps);
  return {all.begin(), all.end()};
}

}  // namespace

std::string row_label(const AccuracyRow& row) {
  std::string label = row.method;
  if (row.substeps > 1) label += " x" + std::to_string(row.substeps) + " substeps";
  return label;
}

AccuracyRequest decode_accuracy_request(const json& doc) {
  ObjectReader r = read_object(doc, "");
  AccuracyRequest q;
  q.tune = read_tune_fields(r);
  AccuracySettings& s = q.settings;
  s.mass = requested_effective_mass(q.tune);
  s.omega = angular_frequency(requested_frequency_hz(q.tune));
  s.damping_ratio = requested_damping_ratio(q.tune);

  const auto rates = read_number_list(r, "step_rates", limits::kMaxStepRates, limits::kMinFps, limits::kMaxFps, "Hz");
  s.step_rates_hz = frame_rates(rates.value_or(s.step_rates_hz), q.tune.fps);
  const auto substeps = read_integer_list(r, "soft_substeps", limits::kMaxSoftSubsteps, 1, limits::kMaxSoftSubstepCount);
  s.soft_substeps = substep_counts(substeps.value_or(std::vector<int>{2, 4, 8}), q.tune.substeps);

  if (auto b = r.number("error_budget")) {
    if (!(*b >= limits::kMinErrorBudget && *b <= limits::kMaxErrorBudget)) {
      throw invalid_field("error_budget", fmt::format("must be a number in [{:g}, {:g}] (fraction of the amplitude; 0.05 = 5 %)",
                                                 limits::kMinErrorBudget, limits::kMaxErrorBudget));
    }
    s.error_budget = *b;
  }
  if (auto n = r.integer("timing_repeats")) {
    if (*n < 1 || *n > limits::kMaxTimingRepeats) {
      throw invalid_field("timing_repeats", fmt::format("must be an integer in [1, {}]", limits::kMaxTimingRepeats));
    }
    s.timing_repeats = static_cast<int>(*n);
  }
  if (const json* b = r.raw("box2d")) {
    if (!b->is_boolean()) throw invalid_field("box2d", "must be true or false (run the Box2D 2.4 distance joint row)");
    q.box2d = b->get<bool>();
  }

  // Duration: at least kMinPeriods periods of the asked frequency. The default is that, or
  // kMinFramesAtLowestRate frames of the lowest step rate when longer.
  const double f = requested_frequency_hz(q.tune);
  const double min_duration = f > 0.0 ? limits::kMinPeriods / f : 0.0;
  const double min_rate = *std::min_element(s.step_rates_hz.begin(), s.step_rates_hz.end());
  s.duration_s = f > 0.0 ? std::max(min_duration, limits::kMinFramesAtLowestRate / min_rate)
                         : limits::kDefaultDurationNoSpringS;
  if (auto d = r.number("duration_s")) {
    if (!(*d > 0.0) || *d < min_duration * (1.0 - 1e-12)) {
      throw invalid_field("duration_s", fmt::format("must be at least {:g} periods of {:g} Hz ({:g} s)", limits::kMinPeriods, f,
                                               min_duration));
    }
    s.duration_s = *d;
  }
  const double max_rate = *std::max_element(s.step_rates_hz.begin(), s.step_rates_hz.end());
  const double max_substeps = *std::max_element(s.soft_substeps.begin(), s.soft_substeps.end());
  const double steps = max_rate * max_substeps * s.duration_s;
  if (steps > limits::kMaxAccuracyStepsPerRow) {
    // Blame what the caller chose: the duration, the request's own fps when it is the top rate, the rates.
    const char* field = r.has("duration_s") ? "duration_s"
                        : max_rate == q.tune.fps ? "fps"
                        : rates ? "step_rates"
                                : "frequency_hz";
    throw invalid_field(field, fmt::format("the longest row would take {:g} steps (fps * substeps * duration_s); the limit is "
                                      "{:g}: shorten duration_s, ask a higher frequency or lower the step rates or "
                                      "soft_substeps",
                                      steps, limits::kMaxAccuracyStepsPerRow));
  }
  r.finish();
  return q;
}

namespace {


json row_json(const AccuracyRow& row) {
  return {
      {"method", row.method},
      {"fps", number_or_null(row.fps)},
      {"substeps", row.substeps},
      {"h", number_or_null(row.h)},
      {"frames", row.frames},
      {"max_error", number_or_null(row.max_error)},
      {"rms_error", number_or_null(row.rms_error)},
      {"achieved_frequency_hz", {{"poles", number_or_null(row.pole_frequency_hz)},
                                 {"trajectory", number_or_null(row.trajectory_frequency_hz)}}},
      {"achieved_damping_ratio", {{"poles", number_or_null(row.pole_damping_ratio)},
                                  {"trajectory", number_or_null(row.trajectory_damping_ratio)}}},
      {"spectral_radius", number_or_null(row.pole_spectral_radius)},
      {"blew_up", row.blew_up},
      {"cpu_seconds_per_sim_second", number_or_null(row.cpu_seconds_per_sim_second)},
  };
}

std::string percent(double v) { return fmt::format("{:.3g} %", 100.0 * v); }

std::string config_text(const AccuracyRow& row) {
  return row.method + fmt::format(" at {:g} fps", row.fps) +
         (row.substeps > 1 ? " with " + std::to_string(row.substeps) + " substeps" : std::string());
}

json recommendation_json(const std::vector<AccuracyRow>& rows, const Recommendation& rec) {
  json out = {{"error_budget", number_or_null(rec.error_budget)},
              {"rows_meeting_budget", rec.rows_meeting_budget}};
  if (!rec.row) {
    out["method"] = nullptr;
    out["fps"] = nullptr;
    out["substeps"] = nullptr;
    out["row"] = nullptr;
    std::string reason = "no configuration keeps the position error within " + percent(rec.error_budget) +
                         " of the amplitude";
    if (rec.most_accurate) {
      const AccuracyRow& best = rows[*rec.most_accurate];
      reason += "; the most accurate is " + config_text(best) + " with " + percent(*best.max_error) +
                ": raise the step rate or the substeps, or use soft_exact";
    }
    out["reason"] = reason;
    return out;
  }
  const AccuracyRow& row = rows[*rec.row];
  out["method"] = row.method;
  out["fps"] = number_or_null(row.fps);
  out["substeps"] = row.substeps;
  out["row"] = *rec.row;
  out["max_error"] = number_or_null(row.max_error);
  out["cpu_seconds_per_sim_second"] = number_or_null(row.cpu_seconds_per_sim_second);
  out["reason"] = config_text(row) + " keeps the position error within " + percent(*row.max_error) +
                  " of the amplitude (budget " + percent(rec.error_budget) + ") and is the cheapest of the " +
                  std::to_string(rec.rows_meeting_budget) + " configurations that meet the budget (" +
                  fmt::format("{:.3g}", row.cpu_seconds_per_sim_second) +
                  " CPU s per simulated s; costs within " + fmt::format("{:.0f} %", 100.0 * (rec.cost_tie_factor - 1.0)) +
                  " of the cheapest count as equal, and the more accurate one wins)";
  return out;
}

}  // namespace

json encode_accuracy_report(const AccuracyRequest& q, const AccuracyReport& report, bool engine_ran) {
  StageList stages;
  stages.add(Stage::validate);
  stages.add(Stage::designer_mapping);
  if (q.tune.constraint) stages.add(Stage::effective_mass);
  stages.add(Stage::softness);
  stages.add(Stage::exact_softness);
  stages.add(Stage::discrete_analysis);
  stages.add(Stage::accuracy_runs);
  if (engine_ran) stages.add(Stage::box2d_distance_joint);
  stages.add(Stage::recommendation);

  json rows = json::array();
  for (const AccuracyRow& row : report.rows) rows.push_back(row_json(row));
  return {
      {"request", {{"frequency_hz", number_or_null(requested_frequency_hz(q.tune))},
                   {"damping_ratio", number_or_null(q.settings.damping_ratio)},
                   {"effective_mass", number_or_null(q.settings.mass)},
                   {"fps", number_or_null(q.tune.fps)},
                   {"substeps", q.tune.substeps},
                   {"x0", number_or_null(kStandardX0)},
                   {"v0", 0.0}}},
      {"duration_s", number_or_null(report.duration_s)},
      {"error_budget", number_or_null(q.settings.error_budget)},
      {"timing", {{"clock", "steady"}, {"statistic", "median"}, {"repeats", q.settings.timing_repeats}}},
      {"rows", std::move(rows)},
      {"recommendation", recommendation_json(report.rows, report.recommendation)},
      {"stages", stages_json(stages)},
  };
}

}  // namespace softtune::codec
