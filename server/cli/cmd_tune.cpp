// `softtune tune`: designer request in, solver numbers out (contract: README.md, "tune").
#include <iostream>

#include "cli/cli_io.h"
#include "cli/flag_fields.h"
#include "codec/problem.h"
#include "codec/tune_codec.h"

namespace softtune::cli {
namespace {

constexpr const char* kHelp = R"(softtune tune: turn a designer's request into solver numbers.

  softtune tune --request FILE      read the request JSON from FILE (- for stdin)
  softtune tune [flags]             or build it from flags:
    --frames N          response_frames: one oscillation period lasts N frames
    --basis-fps B       basis_fps for --frames (default 60)
    --frequency F       frequency_hz, instead of --frames
    --oscillation L     free | some | none
    --damping-ratio Z   damping_ratio, instead of --oscillation
    --mass M            effective_mass in kg
    --fps F             step rate (default 60)
    --substeps N        substeps per frame (default 1)
    --mode M            standard | exact (default standard)

Prints one JSON object. Bad input: exit code 2 and a problem JSON on stderr naming the field.
)";

constexpr FlagField kFlagFields[] = {
    {"frames", "response_frames", true}, {"basis-fps", "basis_fps", true}, {"frequency", "frequency_hz", true},
    {"oscillation", "oscillation", false}, {"damping-ratio", "damping_ratio", true}, {"mass", "effective_mass", true},
    {"fps", "fps", true}, {"substeps", "substeps", true}, {"mode", "mode", false},
};

}  // namespace

int run_tune(const Args& args) {
  return guarded([&] {
    std::vector<std::string> with_value = flag_names(kFlagFields);
    with_value.emplace_back("request");
    const Flags flags = parse_flags(args, with_value, {"help"});
    if (flags.has("help")) {
      std::cout << kHelp;
      return kExitOk;
    }
    nlohmann::json request;
    if (auto file = flags.get("request")) {
      if (flags.values.size() > 1) throw codec::invalid_field("--request", "cannot be combined with other flags");
      request = read_request_file(*file);
    } else {
      request = nlohmann::json::object();
      set_fields_from_flags(flags, kFlagFields, request);
    }
    print_json(codec::run_tune(request));
    return kExitOk;
  });
}

}  // namespace softtune::cli
