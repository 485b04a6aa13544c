// `softtune stability`: the extreme-case sweep (contract: docs/accuracy-and-stability.md).
#include <iostream>

#include "app/preset_stability_app.h"
#include "app/preset_store.h"
#include "app/stability_app.h"
#include "cli/cli_io.h"
#include "cli/engine_flags.h"
#include "codec/problem.h"
#include "codec/stability_codec.h"

namespace softtune::cli {
namespace {

constexpr const char* kStabilityHelp = R"(softtune stability: predicted (step matrix) against observed (simulation) stability.

  softtune stability                 the default sweep (>= 10,000 cases) and the sequential-impulse chain
  softtune stability --preset NAME   each tuned joint's highest stable frequency in Box2D 2.4 (a table;
                                     --format json for the JSON), found on the real solver's motion
    --presets DIR       presets directory (default: $SOFTTUNE_PRESETS, else ./presets)
    --engine NAME       the scene engine (default box2d_v2_4; the search bisects Box2D 2.4's twin runs, so
                        another engine is refused naming engine)
  softtune stability --request FILE  a custom sweep (- for stdin): methods, frequency_ratios, stiffnesses,
                                     damping_ratios, masses, steps, max_stiffness, observe_steps,
                                     include_cases, chain
    --summary           counts, step limits and chain limits only (no per-case list)
    --format F          json (default) | svg (stability maps and each solver's chain limits)

Exit code 0 when every observation matches its prediction, 1 otherwise; bad input: 2.
)";

}  // namespace

int run_stability(const Args& args) {
  return guarded([&] {
    const Flags flags = parse_flags(args, with_engine_flags({"request", "format", "preset", "presets"}), {"help", "summary"});
    if (flags.has("help")) {
      std::cout << kStabilityHelp;
      return kExitOk;
    }
    const app::Format format =
        app::format_named(flags.get("format").value_or("json"), {app::Format::json, app::Format::svg}, "--format");
    nlohmann::json doc;
    if (auto file = flags.get("request")) doc = read_request_file(*file);
    if (auto name = flags.get("preset")) {
      if (!doc.is_null()) throw codec::invalid_field("--preset", "runs alone: drop --request");
      doc = {{"preset", *name}};
      set_engine_from_flags(flags, doc);
    }
    codec::StabilityRequest q = codec::decode_stability_request(doc);
    if (flags.has("summary") || format == app::Format::svg) q.include_cases = false;
    if (q.preset) {
      const nlohmann::json out = app::stability_answer(q, format, app::resolve_presets_dir(flags.get("presets"))).json;
      if (flags.get("format")) {
        print_json(out);
      } else {
        std::cout << app::preset_limits_table(out);
      }
      return out.at("summary").at("passed").get<bool>() ? kExitOk : kExitFailed;
    }
    // The CLI holds no server thread: it runs what a job may (the job budget, 60 s), in process.
    app::require_stability_job_budget(q);
    app::JobProgress progress;
    const nlohmann::json out = app::run_stability_job(q, progress);
    if (format == app::Format::svg) {
      std::cout << app::stability_svg(out);
    } else if (flags.has("summary")) {
      print_json({{"summary", out.at("summary")}, {"step_limits", out.at("step_limits")},
                  {"chain", out.contains("chain") ? out.at("chain") : nlohmann::json()}, {"stages", out.at("stages")}});
    } else {
      print_json(out);
    }
    return out.at("summary").at("passed").get<bool>() ? kExitOk : kExitFailed;
  });
}

}  // namespace softtune::cli
