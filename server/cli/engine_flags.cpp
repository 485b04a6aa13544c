#include "cli/engine_flags.h"

#include <cmath>

#include "codec/problem.h"

namespace softtune::cli {
namespace {

// "8" -> 8, "true" -> true, "Euler" -> "Euler": the JSON value a request would carry.
nlohmann::json setting_value(const std::string& text) {
  if (text == "true") return true;
  if (text == "false") return false;
  try {
    std::size_t used = 0;
    const double d = std::stod(text, &used);
    if (used == text.size() && std::isfinite(d)) {
      if (d == std::floor(d) && std::fabs(d) < 9.0e15) return static_cast<long long>(d);
      return d;
    }
  } catch (const std::exception&) {
  }
  return text;
}

}  // namespace

void set_engine_from_flags(const Flags& flags, nlohmann::json& request) {
  if (auto engine = flags.get("engine")) request["engine"] = *engine;
  const auto text = flags.get("engine-settings");
  if (!text) return;
  nlohmann::json settings = nlohmann::json::object();
  std::size_t start = 0;
  while (start <= text->size()) {
    const std::size_t comma = std::min(text->find(',', start), text->size());
    const std::string item = text->substr(start, comma - start);
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size()) {
      throw codec::invalid_field("--engine-settings", "must be name=value[,name=value...] (the engine's own setting "
                                                      "names), got \"" + item + "\"");
    }
    settings[item.substr(0, eq)] = setting_value(item.substr(eq + 1));
    start = comma + 1;
  }
  request["engine_settings"] = std::move(settings);
}

std::vector<std::string> with_engine_flags(std::vector<std::string> with_value) {
  with_value.insert(with_value.end(), kEngineFlags.begin(), kEngineFlags.end());
  return with_value;
}

}  // namespace softtune::cli
