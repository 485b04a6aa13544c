// `softtune modes`: the modes of a preset or scene about its rest state (app/modes_app.h).
#include <iostream>

#include "app/modes_app.h"
#include "app/preset_store.h"
#include "cli/cli_io.h"
#include "cli/engine_flags.h"
#include "codec/problem.h"

namespace softtune::cli {
namespace {

constexpr const char* kModesHelp = R"(softtune modes: the modes of a scene about its rest state.

  softtune modes --preset NAME     a preset from the presets directory
  softtune modes --request FILE    a full scene (JSON, - for stdin), or {"preset": NAME, ...}
    --presets DIR        presets directory (default: $SOFTTUNE_PRESETS, else ./presets)
    --mass-model M       effective (default) | box2d_reduced: the mass the joints' k, c are computed with
    --at S               linearise at S seconds instead of when the scene settles
    --engine NAME        the scene's engine (default box2d_v2_4; the modes are linearised in Box2D 2.4's step:
                         another engine is refused until its step can be linearised)
    --engine-settings name=value,...   that engine's own step settings

Prints one JSON object: stages, at_s, settled, h, modes (name, frequency and damping ratio continuous and at the
scene's step, shape components). Bad input: exit code 2 and a problem JSON on stderr naming the field.
)";

}  // namespace

int run_modes(const Args& args) {
  return guarded([&] {
    const Flags flags = parse_flags(args, with_engine_flags({"preset", "request", "presets", "mass-model", "at"}), {"help"});
    if (flags.has("help")) {
      std::cout << kModesHelp;
      return kExitOk;
    }
    if (!flags.positional.empty()) throw codec::invalid_field(flags.positional.front(), "is not an argument of modes (see --help)");
    nlohmann::json request = scene_request_from(flags);
    if (flags.has("at")) request["at_s"] = flag_number(flags, "at");
    print_json(app::run_modes(request, app::resolve_presets_dir(flags.get("presets"))));
    return kExitOk;
  });
}

}  // namespace softtune::cli
