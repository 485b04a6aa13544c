#pragma once
// The tune request's flags (--frames, --oscillation, --mass, ...), for commands that take a tune request
// plus fields of their own (accuracy).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cli_io.h"

namespace softtune::cli {

/// Names of the tune flags, all taking a value.
std::vector<std::string> tune_flag_names();

/// The request fields of the tune flags present in `flags` (numbers as JSON numbers).
nlohmann::json tune_fields_from_flags(const Flags& flags);

/// Help lines for the tune flags.
inline constexpr const char* kTuneFlagsHelp = R"(    --frames N          response_frames: one oscillation period lasts N frames
    --basis-fps B       basis_fps for --frames (default 60)
    --frequency F       frequency_hz, instead of --frames
    --oscillation L     free | some | none
    --damping-ratio Z   damping_ratio, instead of --oscillation
    --mass M            effective_mass in kg
    --fps F             step rate (default 60)
    --substeps N        substeps per frame (default 1)
    --mode M            standard | exact (default standard)
)";

}  // namespace softtune::cli
