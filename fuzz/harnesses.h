#pragma once
// The body of every libFuzzer harness, shared with tests/security/fuzz_regressions_test.cpp, which
// replays the seeds (fuzz/seeds/<harness>/) and every crash found (fuzz/regressions/<harness>/) in the plain build.
// Each takes any byte string; bad input must end as a Problem, and an answer must never hold a
// non-finite number (abort: libFuzzer records a crash, the test run fails).
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "tune_harness.h"

#include "app/accuracy_app.h"
#include "codec/accuracy_codec.h"
#include "codec/json_reader.h"
#include "app/preset_store.h"
#include "app/preview_service.h"
#include "codec/problem.h"
#include "app/simulate_app.h"
#include "codec/scene_codec.h"
#include "codec/stability_codec.h"

namespace softtune::fuzz {

/// Any body through every JSON route's decoder: tune, accuracy, stability, the preview plan.
inline void request_decode(std::string_view text) {
  nlohmann::json doc;
  try {
    doc = codec::parse_json(text);
  } catch (const codec::Problem&) {
    return;
  }
  expecting_problems([&] { (void)codec::decode_tune_request(doc); });
  expecting_problems([&] { (void)codec::decode_accuracy_request(doc); });
  expecting_problems([&] { (void)codec::decode_stability_request(doc); });
  expecting_problems([&] { (void)app::plan_preview(doc, presets_dir()); });
}

/// A simulate request ({"preset"}, {"scene"} or a bare scene): schema -> decode_scene -> run -> encode.
inline void simulate_request(std::string_view text) {
  expecting_problems([&] { check_answer(app::run_simulate(codec::parse_json(text), presets_dir())); });
}

/// An accuracy request: decode -> work-precision report -> encode.
inline void accuracy_request(std::string_view text) {
  expecting_problems([&] { check_answer(app::run_accuracy(codec::parse_json(text))); });
}

/// A preset file as load_preset reads it (strict parse, the directory's schema), then decoded to a scene.
inline void preset_load(std::string_view text) {
  static const nlohmann::json schema = app::load_schema(presets_dir());
  expecting_problems([&] {
    const nlohmann::json preset = codec::parse_json(text);
    app::validate_preset(preset, schema, "fuzz.json");
    (void)codec::decode_scene(preset);
  });
}

}  // namespace softtune::fuzz
