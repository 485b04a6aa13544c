#include "cli/flag_fields.h"

namespace softtune::cli {

std::vector<std::string> flag_names(std::span<const FlagField> fields) {
  std::vector<std::string> names;
  for (const FlagField& f : fields) names.emplace_back(f.flag);
  return names;
}

void set_fields_from_flags(const Flags& flags, std::span<const FlagField> fields, nlohmann::json& request) {
  for (const FlagField& f : fields) {
    if (!flags.has(f.flag)) continue;
    if (f.numeric) {
      request[f.field] = flag_number(flags, f.flag);
    } else {
      request[f.field] = *flags.get(f.flag);
    }
  }
}

}  // namespace softtune::cli
