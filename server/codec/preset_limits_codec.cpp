#include "codec/preset_limits_codec.h"

#include "codec/json_writer.h"
#include "codec/stability_codec.h"

namespace softtune::codec {

using nlohmann::json;

namespace {

json row_json(const scene::JointStabilityLimit& l) {
  return {{"joint", l.joint},
          {"joints", l.joints},
          {"asked_hz", number_or_null(l.asked_frequency_hz)},
          {"highest_stable_hz", number_or_null(l.highest_stable_hz)},
          {"stable_side_hz", number_or_null(l.stable_side_hz)},
          {"unstable_side_hz", number_or_null(l.unstable_side_hz)},
          {"kind", limit_kind_name(l.limit.kind)},
          {"evaluations", l.limit.evaluations},
          {"margin", number_or_null(l.margin)},
          {"stable_side_spectral_radius", number_or_null(l.stable_side_radius)},
          {"unstable_side_spectral_radius", number_or_null(l.unstable_side_radius)}};
}

// Inside its limit: no limit in range, or the asked frequency at or below the stable side.
bool asked_is_stable(const scene::JointStabilityLimit& l) {
  if (l.limit.kind == LimitKind::none_in_range) return true;
  return l.margin && *l.margin <= 1.0;
}

}  // namespace

json encode_preset_limits(const std::string& preset, const scene::PresetLimitSettings& settings,
                          const scene::PresetStabilityResult& result, const StageList& stages) {
  json rows = json::array();
  bool passed = true;
  for (const scene::JointStabilityLimit& l : result.joints) {
    rows.push_back(row_json(l));
    passed = passed && asked_is_stable(l);
  }
  json out;
  out["summary"] = {{"searches", result.joints.size()}, {"passed", passed}};
  out["preset_limits"] = {{"preset", preset},
                          {"h", number_or_null(result.h)},
                          {"searched_hz", {settings.lowest_frequency_ratio / result.h, settings.highest_frequency_ratio / result.h}},
                          {"scan_points", settings.scan_points},
                          {"steps_per_run", result.steps_per_run},
                          {"growth_allowed", settings.growth_allowed},
                          {"limit_relative_tolerance", settings.relative_tolerance},
                          {"limits", std::move(rows)}};
  out["stages"] = stages_json(stages);
  return out;
}

}  // namespace softtune::codec
