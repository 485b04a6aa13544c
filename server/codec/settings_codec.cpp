#include "codec/settings_codec.h"

#include <cstdio>
#include <vector>

#include "codec/problem.h"

namespace softtune::codec {
using nlohmann::json;

bool is_switch_setting(const engines::SettingSpec& spec) {
  return spec.choices.size() == 2 && spec.choices[0] == "false" && spec.choices[1] == "true";
}

engines::SettingValues read_setting_values(const json& doc, const std::string& path,
                                           std::span<const engines::SettingSpec> specs) {
  ObjectReader s = read_object(doc, path);
  engines::SettingValues values(specs.size());
  for (std::size_t i = 0; i < specs.size(); ++i) values[i] = specs[i].default_value;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const engines::SettingSpec& spec = specs[i];
    if (!spec.choices.empty()) {
      // A switch (choices "false", "true") takes a JSON boolean, as the engine's own API does.
      if (is_switch_setting(spec)) {
        const json* raw = s.raw(spec.name);
        if (!raw) continue;
        if (!raw->is_boolean()) throw invalid_field(s.field(spec.name), "must be true or false");
        values[i] = raw->get<bool>() ? 1.0 : 0.0;
        continue;
      }
      const std::vector<std::string_view> choices(spec.choices.begin(), spec.choices.end());
      if (auto c = s.choice(spec.name, choices)) values[i] = static_cast<double>(*c);
      continue;
    }
    std::optional<double> x;
    if (spec.integer) {
      if (auto n = s.integer(spec.name)) x = static_cast<double>(*n);
    } else {
      x = s.number(spec.name);
    }
    if (!x) continue;
    if (!(*x >= spec.min && *x <= spec.max)) {
      char rule[160];
      std::snprintf(rule, sizeof rule, "must be %s in [%.17g, %.17g]", spec.integer ? "an integer" : "a number",
                    spec.min, spec.max);
      throw invalid_field(s.field(spec.name), rule);
    }
    values[i] = *x;
  }
  s.finish();
  return values;
}

}  // namespace softtune::codec
