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

}  // namespace softtune::codec
