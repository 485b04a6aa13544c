// libFuzzer harness: any byte string as a tune request body, through the same path as the CLI and the
// HTTP route (parse_json -> decode -> validate -> tune -> encode). Bad input must end as a Problem; the
// output must never hold a non-finite number.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "codec/json_reader.h"
#include "codec/problem.h"
#include "codec/tune_codec.h"

namespace {
bool all_finite(const nlohmann::json& j) {
  if (j.is_number()) return std::isfinite(j.get<double>());
  if (j.is_structured()) {
    for (const auto& e : j) {
      if (!all_finite(e)) return false;
    }
  }
  return true;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const nlohmann::json doc = softtune::codec::parse_json(std::string_view(reinterpret_cast<const char*>(data), size));
    const nlohmann::json out = softtune::codec::run_tune(doc);
    if (!all_finite(out)) std::abort();
    (void)out.dump();
  } catch (const softtune::codec::Problem&) {
  }
  return 0;
}
