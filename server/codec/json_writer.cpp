#include "codec/json_writer.h"

#include <cmath>

namespace softtune::codec {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

nlohmann::json number_or_null(const std::optional<double>& v) { return v ? number_or_null(*v) : nlohmann::json(); }

nlohmann::json warnings_json(const Warnings& warnings) {
  nlohmann::json out = nlohmann::json::array();
  for (const Warning& w : warnings) {
    nlohmann::json j = {{"code", warning_code_name(w.code)}, {"message", warning_message(w)}};
    if (!w.engine.empty()) j["engine"] = w.engine;
    out.push_back(std::move(j));
  }
  return out;
}

nlohmann::json stages_json(const StageList& stages) {
  nlohmann::json out = nlohmann::json::array();
  for (Stage s : stages.items) out.push_back(stage_name(s));
  return out;
}

nlohmann::json engine_values_json(const engines::Parameters& values) {
  nlohmann::json out = nlohmann::json::object();
  for (const engines::Parameter& p : values) {
    nlohmann::json& v = out[std::string(p.name)];
    if (p.choice.empty()) {
      v = number_or_null(p.value);
    } else if (p.choice == "true" || p.choice == "false") {
      v = p.choice == "true";  // a switch reads back as the boolean a request gives
    } else {
      v = p.choice;
    }
  }
  return out;
}

nlohmann::json engine_prediction_json(const engines::Prediction& p) {
  return {{"frequency_hz", number_or_null(p.frequency_hz)},
          {"damping_ratio", number_or_null(p.damping_ratio)},
          {"spectral_radius", number_or_null(p.spectral_radius)},
          {"stable", p.stable}};
}

}  // namespace softtune::codec
