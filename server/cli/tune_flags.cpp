#include "cli/tune_flags.h"

namespace softtune::cli {
namespace {

struct FlagField {
  const char* flag;
  const char* field;
  bool numeric;
};
constexpr FlagField kFields[] = {
    {"frames", "response_frames", true}, {"basis-fps", "basis_fps", true}, {"frequency", "frequency_hz", true},
    {"oscillation", "oscillation", false}, {"damping-ratio", "damping_ratio", true}, {"mass", "effective_mass", true},
    {"fps", "fps", true}, {"substeps", "substeps", true}, {"mode", "mode", false},
};

}  // namespace

std::vector<std::string> tune_flag_names() {
  std::vector<std::string> out;
  for (const FlagField& f : kFields) out.emplace_back(f.flag);
  return out;
}

nlohmann::json tune_fields_from_flags(const Flags& flags) {
  nlohmann::json request = nlohmann::json::object();
  for (const FlagField& f : kFields) {
    if (!flags.has(f.flag)) continue;
    if (f.numeric) {
      request[f.field] = flag_number(flags, f.flag);
    } else {
      request[f.field] = *flags.get(f.flag);
    }
  }
  return request;
}

}  // namespace softtune::cli
