#include "cli/tune_flags.h"

#include "cli/flag_fields.h"

namespace softtune::cli {
namespace {

constexpr FlagField kFields[] = {
    {"frames", "response_frames", true}, {"basis-fps", "basis_fps", true}, {"frequency", "frequency_hz", true},
    {"oscillation", "oscillation", false}, {"damping-ratio", "damping_ratio", true}, {"mass", "effective_mass", true},
    {"fps", "fps", true}, {"substeps", "substeps", true}, {"mode", "mode", false},
};

}  // namespace

std::vector<std::string> tune_flag_names() { return flag_names(kFields); }

nlohmann::json tune_fields_from_flags(const Flags& flags) {
  nlohmann::json request = nlohmann::json::object();
  set_fields_from_flags(flags, kFields, request);
  return request;
}

}  // namespace softtune::cli
