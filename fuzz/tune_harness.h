#pragma once
// The tune harness and what every harness shares (fuzz/harnesses.h has the rest). The tune harness needs
// the codec and core alone, so tune_request_fuzz links softtune_codec and nothing that pulls in Box2D,
// libpng or Mesa.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "codec/json_reader.h"
#include "codec/problem.h"
#include "codec/tune_codec.h"

namespace softtune::fuzz {

inline bool all_finite(const nlohmann::json& j) {
  if (j.is_number()) return std::isfinite(j.get<double>());
  if (j.is_structured()) {
    for (const auto& e : j) {
      if (!all_finite(e)) return false;
    }
  }
  return true;
}

/// Aborts when an answer holds a non-finite number; dumps it as a route would.
inline void check_answer(const nlohmann::json& out) {
  if (!all_finite(out)) std::abort();
  (void)out.dump();
}

inline const std::string& presets_dir() {
  static const std::string dir = SOFTTUNE_SOURCE_DIR "/presets";
  return dir;
}

/// Runs `f`; a Problem is the expected end of bad input.
template <typename F>
void expecting_problems(F&& f) {
  try {
    f();
  } catch (const codec::Problem&) {
  }
}

/// A tune request body: parse_json -> decode -> validate -> tune -> encode (the CLI's and the route's path).
inline void tune_request(std::string_view text) {
  expecting_problems([&] {
    const TuneRequest q = codec::decode_tune_request(codec::parse_json(text));
    check_answer(codec::encode_tune_result(q, tune(q)));
  });
}

}  // namespace softtune::fuzz
