#pragma once
// The generator of the bad-input matrix: from one valid request per route (a few for routes with
// alternative shapes), every field is replaced by non-finite numbers (as huge exponents and as strings),
// negatives, zeros, huge finite values, wrong types and null, removed, and given an unknown sibling;
// arrays are blown up; then come the whole-body cases (empty, malformed, invalid UTF-8, deep nesting,
// duplicated keys, exclusive fields together, wrong content type).

#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace softtune::security {

struct Case {
  std::string route;  ///< tune | simulate | accuracy | stability | preview | verify | presets
  std::string name;   ///< what was done, for the failure message
  std::string body;   ///< the request body (for presets: the preset name)
  std::optional<std::string> field;  ///< the field a refusal must name; nullopt: any (whole-body cases)
  bool must_fail = false;            ///< no reading of this value is legal: a 2xx is a bug
  std::string content_type = "application/json";
};

/// "constraint.body_b[0]", "/constraint/body_b/0" and "constraint.body_b.0" all become "constraint.body_b.0".
inline std::string normalize_path(const std::string& path) {
  std::string out;
  for (char ch : path) {
    if (ch == '/' || ch == '[') {
      out += '.';
    } else if (ch != ']') {
      out += ch;
    }
  }
  while (!out.empty() && out.front() == '.') out.erase(out.begin());
  return out;
}

/// Case::field for a refusal that may name another field (its non-empty `field` is all that is checked).
inline const std::string kAnyField = "*";

namespace matrix_detail {

using nlohmann::json;

inline const char* kMark = "\"@@mutation@@\"";

/// `base` with the value at `pointer` replaced by the literal JSON text `literal` (which need not be
/// representable in nlohmann::json: 1e999 is not).
inline std::string with_literal(json base, const json::json_pointer& pointer, const std::string& literal) {
  base[pointer] = "@@mutation@@";
  std::string text = base.dump();
  text.replace(text.find(kMark), std::string(kMark).size(), literal);
  return text;
}

/// The dotted field name of a JSON pointer ("/constraint/body_b/mass" -> "constraint.body_b.mass").
inline std::string dotted(const json::json_pointer& p) { return normalize_path(p.to_string()); }

inline void mutate_value(std::vector<Case>& out, const std::string& route, const json& base,
                         const json::json_pointer& p, const json& value) {
  const std::string f = dotted(p);
  // Values that may be legal here but break a rule elsewhere (an empty list of oscillators leaves the
  // scene without bodies; a changed id leaves a probe's reference dangling) may be refused under the
  // other field's name: kAnyField.
  auto add = [&](const std::string& what, const std::string& literal, bool must_fail, bool elsewhere = false) {
    out.push_back({route, f + " = " + what, with_literal(base, p, literal), elsewhere ? kAnyField : f, must_fail});
  };
  add("1e999", "1e999", true);
  add("-1e999", "-1e999", true);
  // As strings these are wrong types for numbers, but legal names and ids.
  add("\"NaN\"", "\"NaN\"", !value.is_string(), value.is_string());
  add("\"Infinity\"", "\"-Infinity\"", !value.is_string(), value.is_string());
  add("null", "null", true);
  if (value.is_number()) {
    add("-1", "-1", false);
    add("0", "0", false);
    add("1e308", "1e308", false);
    add("-1e-320 (subnormal)", "-1e-320", false);
    add("\"1\" (string)", "\"1\"", true);
    add("true", "true", true);
    add("[] (array)", "[]", true);
  } else if (value.is_string()) {
    add("42 (number)", "42", true);
    add("\"\" (empty)", "\"\"", false, true);
    add("a 100 kB string", "\"" + std::string(100000, 'a') + "\"", false, true);
  } else if (value.is_boolean()) {
    add("\"true\" (string)", "\"true\"", true);
    add("1 (number)", "1", true);
  } else if (value.is_array()) {
    add("{} (object)", "{}", true);
    add("[] (empty)", "[]", false, true);
    std::string huge = "[";
    for (int i = 0; i < 200000; ++i) huge += i ? ",1" : "1";
    add("200000 elements", huge + "]", true);
  } else if (value.is_object()) {
    add("[] (array)", "[]", true);
    add("\"x\" (string)", "\"x\"", true);
  }
  // Removed (a required field is refused by name; an optional one takes its default).
  json removed = base;
  const json::json_pointer parent = p.parent_pointer();
  if (removed[parent].is_object()) {
    removed[parent].erase(p.back());
    out.push_back({route, f + " removed", removed.dump(), kAnyField, false});
  }
}

/// Every value in `base` (depth first): its own mutations; objects also get an unknown key.
inline void walk(std::vector<Case>& out, const std::string& route, const json& base, const json::json_pointer& p) {
  const json& value = base[p];
  if (!p.empty()) mutate_value(out, route, base, p, value);
  if (value.is_object()) {
    json extra = base;
    extra[p / "not_a_field"] = 1;
    out.push_back({route, dotted(p / "not_a_field") + " added", extra.dump(), dotted(p / "not_a_field"), true});
    for (const auto& item : value.items()) walk(out, route, base, p / item.key());
  } else if (value.is_array()) {
    // Elements of short number or string vectors; long lists of objects get their first element only.
    for (std::size_t i = 0; i < value.size() && i < 3; ++i) walk(out, route, base, p / i);
  }
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Cases about the body as a whole: the same for every JSON route. `top_key` is a top-level key of the
/// route's base request (duplicated once), `exclusive` two fields that may not come together.
inline void whole_body(std::vector<Case>& out, const std::string& route, const json& base, const std::string& top_key,
                       const std::string& exclusive) {
  auto add = [&](const std::string& name, const std::string& body, std::optional<std::string> field, bool http = false) {
    Case c{route, name, body, std::move(field), true};
    if (http) c.content_type = "text/plain";
    out.push_back(std::move(c));
  };
  add("empty body", "", std::nullopt);
  add("whitespace only", "  \n ", std::nullopt);
  add("truncated JSON", base.dump().substr(0, base.dump().size() / 2), std::nullopt);
  add("a JSON array", "[1, 2]", std::nullopt);
  add("a JSON string", "\"tune\"", std::nullopt);
  add("a bare NaN", "NaN", std::nullopt);
  add("invalid UTF-8 in a string", "{\"" + top_key + "\": \"\xff\xfe\xc3\x28\"}", std::nullopt);
  add("invalid UTF-8 in a key", "{\"\xc0\xaf\": 1}", std::nullopt);
  add("a NUL byte", std::string("{\"") + top_key + std::string("\": \"a\0b\"}", 9), std::nullopt);
  add("nesting 100000 deep", std::string(100000, '[') + std::string(100000, ']'), std::nullopt);
  add("objects nested 5000 deep", [] {
    std::string s;
    for (int i = 0; i < 5000; ++i) s += "{\"a\":";
    return s + "1" + std::string(5000, '}');
  }(), std::nullopt);
  const std::string dump = base.dump();
  add("duplicated \"" + top_key + "\"", "{\"" + top_key + "\": " + base[top_key].dump() + ", " + dump.substr(1), top_key);
  add("both " + exclusive, exclusive, std::nullopt);
  if (route == "tune" || route == "preview") add("text/plain content type", dump, std::nullopt, true);
}

}  // namespace matrix_detail

/// The whole matrix. `presets_dir` supplies the scene the simulate cases mutate.
inline std::vector<Case> all_cases(const std::string& presets_dir) {
  using nlohmann::json;
  using namespace matrix_detail;
  std::vector<Case> out;
  auto route = [&out](const std::string& name, const json& base) { walk(out, name, base, json::json_pointer()); };

  const json tune_2d = json::parse(R"({"response_frames": 6, "damping_ratio": 0.1, "fps": 60, "substeps": 1,
      "constraint": {"dimension": 2, "type": "linear", "body_a": "static",
                     "body_b": {"mass": 4, "inertia": 1.5, "position": [0, 0]},
                     "anchor_a": [1, 1], "anchor_b": [1, 0], "axis": [0, 1]}})");
  const json tune_simple = json::parse(R"({"frequency_hz": 10, "oscillation": "free", "effective_mass": 1, "mode": "exact"})");
  route("tune", tune_2d);
  route("tune", tune_simple);
  whole_body(out, "tune", tune_simple, "frequency_hz",
             R"({"frequency_hz": 5, "response_frames": 6, "damping_ratio": 0.1, "effective_mass": 1})");
  out.push_back({"tune", "damping_ratio and oscillation together",
                 R"({"frequency_hz": 5, "damping_ratio": 0.1, "oscillation": "some", "effective_mass": 1})",
                 std::nullopt, true});
  out.push_back({"tune", "effective_mass and constraint together",
                 json{{"frequency_hz", 5}, {"damping_ratio", 0.1}, {"effective_mass", 1}, {"constraint", tune_2d["constraint"]}}.dump(),
                 std::nullopt, true});

  // Engine settings are checked against each engine model's specs (core/engines).
  route("tune", json::parse(R"({"frequency_hz": 4, "damping_ratio": 0.2, "effective_mass": 2,
      "engine_settings": {"box2d_v3": {"subStepCount": 4, "enableWarmStarting": true}, "mujoco": {"integrator": "Euler"}}})"));

  const json verify = json::parse(R"({"frequency_hz": 5, "damping_ratio": 0.1, "effective_mass": 2, "mode": "exact",
      "engines": ["box2d_v2_4", "ode"], "duration_s": 1, "body": "rotating_plank", "x0": 0.01,
      "engine_settings": {"ode": {"stepper": "dWorldQuickStep"}}})");
  route("verify", verify);
  whole_body(out, "verify", verify, "duration_s", R"({"frequency_hz": 5, "damping_ratio": 0.1, "effective_mass": 1,
      "fps": 1000, "substeps": 100, "duration_s": 60, "engines": ["ode"]})");

  json scene = json::parse(read_text(presets_dir + "/oscillator.json"));
  scene.erase("expectations");
  scene.erase("description");
  route("simulate", json{{"preset", "oscillator"}, {"mass_model", "effective"}, {"frames", true}, {"frame_stride", 5}});
  route("simulate", json{{"scene", scene}});
  // The scene engine (issue 32): a name from GET /api/v1/scene-engines and that engine's own settings.
  route("simulate", json{{"preset", "oscillator"}, {"engine", "box2d_v2_4"}, {"engine_settings", json::object()}});
  whole_body(out, "simulate", json{{"preset", "oscillator"}}, "preset",
             json{{"preset", "oscillator"}, {"scene", scene}}.dump());

  const json accuracy = json::parse(R"({"frequency_hz": 5, "damping_ratio": 0.5, "effective_mass": 1,
      "step_rates": [60, 120], "soft_substeps": [1, 4], "error_budget": 0.05, "timing_repeats": 1, "box2d": false})");
  route("accuracy", accuracy);
  whole_body(out, "accuracy", accuracy, "frequency_hz",
             R"({"frequency_hz": 5, "response_frames": 6, "damping_ratio": 0.5, "effective_mass": 1})");

  const json stability = json::parse(R"({"methods": ["soft", "explicit_euler"], "frequency_ratios": [0.1, 1],
      "stiffnesses": [100], "damping_ratios": [0, 1], "masses": [1], "steps": [0.01], "observe_steps": 1000,
      "include_cases": false, "chain": {"mass_ratios": [1, 10], "iterations": [4]}})");
  route("stability", stability);
  whole_body(out, "stability", stability, "masses", R"({"chain": false, "include_cases": "both"})");

  route("preview", json{{"preset", "oscillator"}, {"frames", 12}, {"size", "320x180"}, {"filmstrip_every", 3}, {"wait", true}});
  route("preview", json{{"frequency_hz", 2}, {"damping_ratio", 0.2}, {"effective_mass", 1}, {"frames", 8}});
  route("preview", json{{"preset", "oscillator"}, {"frames", 4}, {"engine", "box2d_v2_4"}, {"engine_settings", json::object()}});
  whole_body(out, "preview", json{{"preset", "oscillator"}, {"frames", 12}}, "preset",
             R"({"preset": "oscillator", "frequency_hz": 2, "damping_ratio": 0.2, "effective_mass": 1})");

  const std::vector<std::string> names = {"../schema", "..%2fschema", "%2e%2e", "schema", "chain.json", "CHAIN", "chain%00",
                                 std::string("chain\0x", 7), "", "/etc/passwd", "....//....//etc/passwd",
                                          std::string(5000, 'a'), "\xff\xfe", "nope"};
  for (const std::string& name : names) {
    out.push_back({"presets", "preset name \"" + name.substr(0, 40) + "\"", name, std::nullopt, true});
  }
  return out;
}

}  // namespace softtune::security
