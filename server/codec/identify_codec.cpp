#include "codec/identify_codec.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "codec/correction_codec.h"
#include "codec/json_reader.h"
#include "codec/json_writer.h"
#include "codec/problem.h"
#include "codec/tune_codec.h"

namespace softtune::codec {
namespace {

using nlohmann::json;

// A number array of at most kIdentifyMaxSamples entries at `field`.
std::vector<double> read_samples(const json& v, const std::string& field) {
  if (!v.is_array()) throw invalid_field(field, "must be an array of numbers");
  if (v.size() > kIdentifyMaxSamples) throw invalid_field(field, "must have at most 100000 samples");
  std::vector<double> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_number()) throw invalid_field(field + "." + std::to_string(i), "must be a finite number");
    out.push_back(v[i].get<double>());
  }
  return out;
}

// `time_s` and `probes` ({name: [numbers]}), or `csv` (text with a header row).
NamedRecording read_recording(ObjectReader& r) {
  const json* csv = r.raw("csv");
  const json* time = r.raw("time_s");
  const json* probes = r.raw("probes");
  if (csv) {
    if (time || probes) throw invalid_field(r.field("csv"), "give either csv or time_s and probes, not both");
    if (!csv->is_string()) throw invalid_field(r.field("csv"), "must be CSV text with a header row");
    return read_csv_recording(csv->get_ref<const std::string&>(), r.field("csv"));
  }
  if (!time) throw invalid_field(r.field("time_s"), "is required (or csv): the sample times in seconds");
  if (!probes) throw invalid_field(r.field("probes"), "is required: {name: [values]}, one array per probe");
  NamedRecording out;
  out.recording.time_s = read_samples(*time, r.field("time_s"));
  if (!probes->is_object() || probes->empty()) throw invalid_field(r.field("probes"), "must be an object of named arrays");
  if (probes->size() > kIdentifyMaxProbes) throw invalid_field(r.field("probes"), "must hold at most 16 probes");
  for (const auto& [name, values] : probes->items()) {
    if (name.empty() || name.size() > kCsvMaxNameBytes) throw invalid_field(r.field("probes"), "names must have 1 to 64 characters");
    out.probe_names.push_back(name);
    out.recording.probes.push_back(read_samples(values, r.field("probes") + "." + name));
  }
  if (auto e = validate_recording(out.recording)) {
    const std::string column = e->column == 0 ? r.field("time_s")
                                              : r.field("probes") + "." + out.probe_names[std::min(e->column, out.probe_names.size()) - 1];
    throw invalid_field(column + "." + std::to_string(e->row), std::string(e->rule));
  }
  return out;
}

// A measured ratio is >= 0; a typed one may be negative, down to -1 (a correction for an engine that damps
// by itself types one: lowest_typed_damping_ratio).
ResponseValues read_response(ObjectReader r, double lowest_ratio = 0.0) {
  const auto f = r.number("frequency_hz");
  const auto z = r.number("damping_ratio");
  if (!f || !(*f > 0.0 && *f <= 1e4)) throw invalid_field(r.field("frequency_hz"), "must be a number in (0, 10000] Hz");
  if (!z || !(*z >= lowest_ratio && *z <= 100.0)) {
    throw invalid_field(r.field("damping_ratio"), lowest_ratio < 0.0 ? "must be a number in [-1, 100]" : "must be a number in [0, 100]");
  }
  r.finish();
  return {*f, *z};
}

TypedValues read_typed(ObjectReader r) {
  TypedValues out;
  if (r.has("k") || r.has("c")) {
    const auto k = r.number("k");
    const auto c = r.number("c");
    if (!k || !(*k > 0.0 && *k <= 1e15)) throw invalid_field(r.field("k"), "must be a stiffness in (0, 1e15] N/m");
    if (!c || !(std::abs(*c) <= 1e15)) throw invalid_field(r.field("c"), "must be a damping in [-1e15, 1e15] N s/m");
    r.finish();
    out.spring = SpringConstants{*k, *c};
    return out;
  }
  out.response = read_response(std::move(r), kIdentifyLowestTypedRatio);
  return out;
}

json poles_json(const MotionFit& fit) {
  if (!fit.z1 || !fit.z2) return json();
  return json::array({{{"re", number_or_null(fit.z1->real())}, {"im", number_or_null(fit.z1->imag())}},
                      {{"re", number_or_null(fit.z2->real())}, {"im", number_or_null(fit.z2->imag())}}});
}

json verdict_codes(const std::vector<IdentifyVerdict>& list) {
  json out = json::array();
  for (IdentifyVerdict v : list) out.push_back(identify_verdict_name(v));
  return out;
}

json motion_json(const MotionFit& fit, const std::vector<std::string>& names) {
  json equilibrium = json::object();
  for (std::size_t k = 0; k < names.size() && k < fit.equilibrium.size(); ++k) equilibrium[names[k]] = number_or_null(fit.equilibrium[k]);
  return {{"frequency_hz", number_or_null(fit.frequency_hz)},
          {"damping_ratio", number_or_null(fit.damping_ratio)},
          {"damped_frequency_hz", number_or_null(fit.damped_frequency_hz)},
          {"residual", number_or_null(fit.residual)},
          {"equilibrium", fit.equilibrium.empty() ? json() : equilibrium},
          {"poles", poles_json(fit)},
          {"samples_used", fit.samples_used}};
}

json strided(const std::vector<double>& x) {
  const std::size_t stride = std::max<std::size_t>(1, (x.size() + kIdentifyMaxPlotSamples - 1) / kIdentifyMaxPlotSamples);
  json out = json::array();
  for (std::size_t i = 0; i < x.size(); i += stride) out.push_back(number_or_null(x[i]));
  return out;
}

// The recording and the joint fit, each strided to at most kIdentifyMaxPlotSamples per probe.
json plot_json(const NamedRecording& rec, const Identification& id) {
  json recorded = json::object(), fitted = json::object();
  for (std::size_t k = 0; k < rec.probe_names.size(); ++k) {
    recorded[rec.probe_names[k]] = strided(rec.recording.probes[k]);
    if (k < id.joint.fitted.size()) fitted[rec.probe_names[k]] = strided(id.joint.fitted[k]);
  }
  std::vector<double> fit_time;
  const std::size_t n = id.joint.fitted.empty() ? 0 : id.joint.fitted.front().size();
  for (std::size_t i = 0; i < n; ++i) fit_time.push_back(rec.recording.time_s.front() + id.fit_interval_s * static_cast<double>(i));
  return {{"time_s", strided(rec.recording.time_s)}, {"recorded", std::move(recorded)},
          {"fit_time_s", strided(fit_time)}, {"fitted", std::move(fitted)}};
}

bool valid_engine_name(const std::string& s) {
  if (s.empty() || s.size() > kIdentifyMaxEngineName) return false;
  return std::all_of(s.begin(), s.end(), [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.'; });
}

}  // namespace

std::string identify_verdict_message(IdentifyVerdict v) {
  switch (v) {
    case IdentifyVerdict::too_short:
      return "too short: fewer than 16 moving samples or under half an oscillation; record longer, or at a higher rate";
    case IdentifyVerdict::too_noisy:
      return "too noisy: the fit leaves more than 10 % of the motion unexplained; record a larger motion or less noise "
             "(the values are still the best fit)";
    case IdentifyVerdict::not_oscillating:
      return "not oscillating: no oscillation was seen (over-damped or no motion), so frequency and damping ratio rest "
             "on the decay alone";
    case IdentifyVerdict::non_uniform_sampling:
      return "non-uniform sampling: timestamps stray from a uniform grid, so the recording was resampled by linear "
             "interpolation; record from the fixed physics step for exact values";
    case IdentifyVerdict::clipped:
      return "clipped or saturated: the motion sits on a plateau at its largest or smallest value (a limit, a clamp, "
             "a saturated sensor); a linear fit cannot explain it";
  }
  return "";
}

IdentifyRequest decode_identify_request(const json& doc) {
  ObjectReader r = read_object(doc, "");
  IdentifyRequest q;
  q.recording = read_recording(r);
  if (auto e = r.string("engine")) {
    if (!valid_engine_name(*e)) throw invalid_field(r.field("engine"), "must be 1 to 64 letters, digits, '_', '-' or '.'");
    q.engine = *e;
  }
  if (r.has("request")) {
    ObjectReader t = read_object(*r.raw("request"), "request");
    q.tune = read_tune_fields(t);
    t.finish();
  }
  if (auto t = r.object("typed")) q.typed = read_typed(std::move(*t));
  if (const json* b = r.raw("negative_damping")) {
    if (!b->is_boolean()) throw invalid_field(r.field("negative_damping"), "must be true or false (whether the engine takes a negative damping)");
    q.negative_damping = b->get<bool>();
  }
  if (const json* prev = r.raw("previous")) {
    if (!prev->is_array()) throw invalid_field(r.field("previous"), "must be an array of earlier rounds, oldest first");
    if (prev->size() > kIdentifyMaxPrevious) throw invalid_field(r.field("previous"), "must hold at most 4 earlier rounds");
    for (std::size_t i = 0; i < prev->size(); ++i) {
      const std::string field = "previous." + std::to_string(i);
      ObjectReader p = read_object((*prev)[i], field);
      PreviousRound round;
      if (auto m = p.object("measured")) {
        round.measured = read_response(std::move(*m));
      } else {
        round.recording = read_recording(p);
      }
      auto typed = p.object("typed");
      if (!typed) throw invalid_field(field + ".typed", "is required: what was typed for that recording");
      round.typed = read_typed(std::move(*typed));
      p.finish();
      q.previous.push_back(std::move(round));
    }
  }
  r.finish();
  const bool needs_mass = (q.typed && q.typed->spring) ||
                          std::any_of(q.previous.begin(), q.previous.end(), [](const PreviousRound& p) { return p.typed.spring.has_value(); });
  if (needs_mass && !q.tune) throw invalid_field("request", "is required when typed gives k and c (its effective mass converts them)");
  if (!q.previous.empty() && !q.tune) throw invalid_field("request", "is required with previous rounds: they correct towards it");
  return q;
}

json identify_request_from_csv(std::string body, const std::multimap<std::string, std::string>& query) {
  json doc = {{"csv", std::move(body)}};
  json request = json::object(), typed = json::object();
  for (const auto& [key, value] : query) {
    double number = 0.0;
    const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), number);
    const json v = ec == std::errc() && ptr == value.data() + value.size() ? json(number) : json(value);
    if (key == "engine") {
      doc["engine"] = value;
    } else if (key == "negative_damping") {
      doc["negative_damping"] = value == "true" ? json(true) : value == "false" ? json(false) : json(value);
    } else if (key.rfind("typed_", 0) == 0) {
      typed[key.substr(6)] = v;
    } else {
      request[key] = v;
    }
  }
  if (!request.empty()) doc["request"] = std::move(request);
  if (!typed.empty()) doc["typed"] = std::move(typed);
  return doc;
}

json encode_identify_result(const IdentifyRequest& q, const IdentifyOutcome& o) {
  const Identification& id = o.identification;
  json probes = json::object();
  for (std::size_t k = 0; k < q.recording.probe_names.size() && k < id.probes.size(); ++k) {
    json p = motion_json(id.probes[k], {q.recording.probe_names[k]});
    p["verdicts"] = verdict_codes(id.probes[k].verdicts);
    probes[q.recording.probe_names[k]] = std::move(p);
  }
  json verdicts = json::array();
  for (IdentifyVerdict v : id.verdicts) verdicts.push_back({{"code", identify_verdict_name(v)}, {"message", identify_verdict_message(v)}});
  json out = motion_json(id.joint, q.recording.probe_names);
  out["samples"] = id.samples;
  out["sample_interval_s"] = number_or_null(id.sample_interval_s);
  out["sample_rate_hz"] = number_or_null(id.sample_rate_hz);
  out["grid_deviation"] = number_or_null(id.grid_deviation);
  out["resampled"] = id.resampled;
  out["step_rate_hz"] = number_or_null(id.step_rate_hz);
  out["fit_interval_s"] = number_or_null(id.fit_interval_s);
  out["verdict"] = id.verdicts.empty() ? "ok" : std::string(identify_verdict_name(id.verdicts.front()));
  out["verdicts"] = std::move(verdicts);
  out["probes"] = std::move(probes);
  out["plot"] = plot_json(q.recording, id);
  out["engine"] = q.engine ? json(*q.engine) : json();
  out["modelled"] = o.model != nullptr;
  out["model"] = o.model ? json(o.model->modelled) : json();
  out["requested"] = o.asked ? json{{"frequency_hz", number_or_null(o.asked->frequency_hz)},
                                    {"damping_ratio", number_or_null(o.asked->damping_ratio)}}
                             : json();
  const bool measured = id.joint.frequency_hz && id.joint.damping_ratio;
  out["error"] = o.asked && measured ? json{{"frequency", number_or_null(*id.joint.frequency_hz / o.asked->frequency_hz - 1.0)},
                                            {"damping_ratio", number_or_null(*id.joint.damping_ratio - o.asked->damping_ratio)}}
                                     : json();
  out["correction"] = o.correction && o.typed
                          ? correction_json(*o.correction, *o.typed, o.rounds, o.effective_mass, o.next_report)
                          : json();
  const engines::EngineReport* report = nullptr;
  if (o.model && o.tuned) {
    const auto models = engines::engine_models();
    for (std::size_t i = 0; i < models.size(); ++i) {
      if (models[i] == o.model) report = &o.tuned->engine_reports[i];
    }
  }
  out["exact"] = report && report->exact ? engine_values_json(*report->exact) : json();
  out["exact_predicted"] = report && report->exact_predicted ? engine_prediction_json(*report->exact_predicted) : json();
  out["warnings"] = o.tuned ? warnings_json(o.tuned->warnings) : json::array();
  if (report) {
    for (const json& w : warnings_json(report->warnings)) out["warnings"].push_back(w);
  }
  return out;
}

}  // namespace softtune::codec
