#include "app/check_baseline.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "codec/json_reader.h"
#include "codec/json_writer.h"
#include "codec/problem.h"

namespace softtune::app {

using namespace softtune::codec;  // the codec is this layer's JSON vocabulary
using nlohmann::json;

namespace {

constexpr int kBaselineVersion = 1;
/// A baseline of hundreds of presets at four rates is a few MiB at most.
constexpr std::uintmax_t kMaxBaselineBytes = 64u << 20;

std::string last_part(const std::string& figure) {
  const auto dot = figure.rfind('.');
  const auto colon = figure.rfind(':');
  const auto cut = dot == std::string::npos ? colon : (colon == std::string::npos ? dot : std::max(dot, colon));
  return cut == std::string::npos ? figure : figure.substr(cut + 1);
}

std::string figure_text(const std::optional<double>& v) {
  if (!v) return "undefined";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", *v);
  return buffer;
}

void add_run_figures(const scene::SceneResult& run, const std::string& prefix, std::vector<Figure>& out) {
  out.push_back({prefix + "finite", run.finite ? 1.0 : 0.0});
  out.push_back({prefix + "in_world", run.left_world.empty() ? 1.0 : 0.0});
  out.push_back({prefix + "max_constraint_error", run.max_constraint_error});
  for (const scene::ProbeResult& p : run.probes) {
    const std::string at = prefix + p.id + ".";
    out.push_back({at + "frequency_hz", p.measured.frequency_hz});
    out.push_back({at + "damping_ratio", p.measured.damping_ratio});
    out.push_back({at + "overshoot", p.measured.overshoot});
    out.push_back({at + "settle_frames", p.settle_frames ? std::optional<double>(*p.settle_frames) : std::nullopt});
    out.push_back({at + "settle_s", p.settle_s});
    out.push_back({at + "max_abs_value", p.max_abs_value});
  }
}

Tolerance read_tolerance(const json& doc, const std::string& field) {
  ObjectReader r = read_object(doc, field);
  Tolerance t;
  if (auto v = r.number("absolute")) t.absolute = *v;
  if (auto v = r.number("relative")) t.relative = *v;
  r.finish();
  if (!std::isfinite(t.absolute) || t.absolute < 0) throw invalid_field(field + ".absolute", "must be a number >= 0");
  if (!std::isfinite(t.relative) || t.relative < 0) throw invalid_field(field + ".relative", "must be a number >= 0");
  return t;
}

}  // namespace

std::vector<Figure> measured_figures(const scene::CheckResult& check) {
  std::vector<Figure> out;
  for (std::size_t i = 0; i < check.runs.size(); ++i) {
    const scene::SceneResult& run = check.runs[i];
    add_run_figures(run, i == 0 ? "" : std::string(scene::mass_model_name(run.mass_model)) + ":", out);
  }
  return out;
}

Tolerance default_tolerance(const std::string& figure) {
  const std::string kind = last_part(figure);
  if (kind == "frequency_hz") return {1e-6, 0.01};
  if (kind == "damping_ratio" || kind == "overshoot") return {0.01, 0.0};
  if (kind == "settle_frames") return {1.0, 0.0};
  if (kind == "settle_s") return {0.02, 0.0};
  if (kind == "max_abs_value") return {1e-9, 0.02};
  if (kind == "max_constraint_error") return {1e-4, 0.1};
  return {0.0, 0.0};  // finite, in_world: yes or no
}

Tolerance tolerance_for(const Baseline& baseline, const std::string& figure) {
  if (auto it = baseline.tolerances.find(figure); it != baseline.tolerances.end()) return it->second;
  if (auto it = baseline.tolerances.find(last_part(figure)); it != baseline.tolerances.end()) return it->second;
  return default_tolerance(figure);
}

std::vector<Drift> compare_with_baseline(const Baseline& baseline, const std::string& case_key, const std::vector<Figure>& figures) {
  std::vector<Drift> out;
  const auto entry = baseline.cases.find(case_key);
  if (entry == baseline.cases.end()) return out;
  const auto& recorded = entry->second;
  for (const Figure& f : figures) {
    const auto it = recorded.find(f.name);
    if (it == recorded.end()) continue;  // a new figure (a probe added since): nothing to compare with
    const Tolerance t = tolerance_for(baseline, f.name);
    const std::optional<double>& b = it->second;
    bool drifted = b.has_value() != f.value.has_value();
    if (b && f.value) drifted = !(std::abs(*f.value - *b) <= t.absolute + t.relative * std::abs(*b));
    if (drifted) out.push_back({f.name, b, f.value, t, false});
  }
  for (const auto& [name, value] : recorded) {
    const bool measured = std::any_of(figures.begin(), figures.end(), [&wanted = name](const Figure& f) { return f.name == wanted; });
    if (!measured) out.push_back({name, value, std::nullopt, tolerance_for(baseline, name), true});
  }
  return out;
}

std::string drift_message(const Drift& d) {
  std::string out = d.figure + ": baseline " + figure_text(d.baseline) + ", now ";
  if (d.missing) return out + "not measured (the probe is gone)";
  out += figure_text(d.value);
  if (d.baseline && d.value) {
    out += " (tolerance " + figure_text(d.tolerance.absolute + d.tolerance.relative * std::abs(*d.baseline)) + ")";
  }
  return out;
}

Baseline decode_baseline(const json& doc, const std::string& field) {
  ObjectReader r = read_object(doc, field);
  const std::string at = field.empty() ? "" : field + ".";
  const auto version = r.integer("softtune_baseline");
  if (!version || *version != kBaselineVersion) throw invalid_field(at + "softtune_baseline", "must be 1 (the baseline format's version)");
  Baseline b;
  if (const json* cases = r.raw("cases")) {
    if (!cases->is_object()) throw invalid_field(at + "cases", "must be an object: case (\"mouse@60x1\") -> figures");
    for (auto c = cases->begin(); c != cases->end(); ++c) {
      const std::string case_field = at + "cases." + c.key();
      if (!c->is_object()) throw invalid_field(case_field, "must be an object: figure -> number or null");
      auto& figures = b.cases[c.key()];
      for (auto f = c->begin(); f != c->end(); ++f) {
        if (f->is_null()) {
          figures[f.key()] = std::nullopt;
        } else if (f->is_number()) {
          figures[f.key()] = f->get<double>();
        } else {
          throw invalid_field(case_field + "." + f.key(), "must be a number or null");
        }
      }
    }
  }
  if (const json* tolerances = r.raw("tolerances")) {
    if (!tolerances->is_object()) throw invalid_field(at + "tolerances", "must be an object: figure -> {absolute, relative}");
    for (auto t = tolerances->begin(); t != tolerances->end(); ++t) b.tolerances[t.key()] = read_tolerance(*t, at + "tolerances." + t.key());
  }
  r.finish();
  return b;
}

json encode_baseline(const Baseline& baseline) {
  json cases = json::object(), tolerances = json::object();
  std::map<std::string, Tolerance> in_use = baseline.tolerances;
  for (const auto& [key, figures] : baseline.cases) {
    json entry = json::object();
    for (const auto& [name, value] : figures) {
      entry[name] = number_or_null(value);
      const std::string kind = last_part(name);
      if (!in_use.contains(kind)) in_use[kind] = default_tolerance(kind);
    }
    cases[key] = std::move(entry);
  }
  for (const auto& [name, t] : in_use) tolerances[name] = {{"absolute", t.absolute}, {"relative", t.relative}};
  return {{"softtune_baseline", kBaselineVersion}, {"tolerances", std::move(tolerances)}, {"cases", std::move(cases)}};
}

Baseline read_baseline_file(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw Problem(404, "Not found", "baseline", "cannot read baseline \"" + path + "\"");
  if (size > kMaxBaselineBytes) throw Problem(413, "Too large", "baseline", "\"" + path + "\" is larger than 64 MiB");
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  try {
    return decode_baseline(parse_json(text.str()), "");
  } catch (const Problem& p) {
    throw Problem(p.status, p.title, "baseline" + (p.field.empty() ? "" : "." + p.field), path + ": " + p.detail);
  }
}

void write_baseline_file(const std::string& path, const Baseline& baseline) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << encode_baseline(baseline).dump(2) << '\n';
  if (!out) throw Problem(500, "Cannot write", "baseline", "cannot write baseline \"" + path + "\"");
}

}  // namespace softtune::app
