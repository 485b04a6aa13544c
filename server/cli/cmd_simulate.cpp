// `softtune simulate`: run a preset or a full scene and print stages, per-probe response and series.
#include <iostream>

#include "cli/cli_io.h"
#include "cli/engine_flags.h"
#include "app/preset_store.h"
#include "codec/problem.h"
#include "app/simulate_app.h"
#include "codec/scene_codec.h"

namespace softtune::cli {
namespace {

constexpr const char* kSimulateHelp = R"(softtune simulate: run a scene and measure the response it achieved.

  softtune simulate --preset NAME     a preset from the presets directory
  softtune simulate --request FILE    a full scene (JSON, - for stdin), or {"preset": NAME, ...}
    --presets DIR        presets directory (default: $SOFTTUNE_PRESETS, else ./presets)
    --mass-model M       effective (default) | box2d_reduced: the mass k, c are computed with
    --frames             also record per-frame snapshots (bodies and joints in world coordinates)
    --frame-stride N     record every N-th frame (default 1)
    --engine NAME        the engine the scene runs in (default box2d_v2_4; GET /api/v1/scene-engines lists them)
    --engine-settings name=value,...   that engine's own step settings (GET /api/v1/scene-engines)

Prints one JSON object: stages, joints (m_eff, k, c), probes (requested, measured, error, series).
Bad input: exit code 2 and a problem JSON on stderr naming the field.
)";

}  // namespace

int run_simulate(const Args& args) {
  return guarded([&] {
    const Flags flags = parse_flags(args, with_engine_flags({"preset", "request", "presets", "mass-model", "frame-stride"}), {"frames", "help"});
    if (flags.has("help")) {
      std::cout << kSimulateHelp;
      return kExitOk;
    }
    if (!flags.positional.empty()) throw codec::invalid_field(flags.positional.front(), "is not an argument of simulate (see --help)");
    nlohmann::json request = scene_request_from(flags);
    if (flags.has("frames")) request["frames"] = true;
    if (flags.has("frame-stride")) request["frame_stride"] = flag_number(flags, "frame-stride");
    print_json(app::run_simulate(request, app::resolve_presets_dir(flags.get("presets"))));
    return kExitOk;
  });
}

}  // namespace softtune::cli
