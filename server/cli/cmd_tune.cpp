// `softtune tune`: designer request in, solver numbers out (contract: docs/api.md, "softtune tune").
#include <iostream>

#include "cli/cli_io.h"
#include "cli/tune_flags.h"
#include "app/tune_app.h"
#include "codec/tune_codec.h"

namespace softtune::cli {
namespace {

constexpr const char* kTuneHelp = R"(softtune tune: turn a designer's request into solver numbers.

  softtune tune --request FILE      read the request JSON from FILE (- for stdin)
  softtune tune [flags]             or build it from flags:
)";
constexpr const char* kTuneHelpTail = R"(
Prints one JSON object. Bad input: exit code 2 and a problem JSON on stderr naming the field.
)";

}  // namespace

int run_tune(const Args& args) {
  return guarded([&] {
    std::vector<std::string> with_value = tune_flag_names();
    with_value.emplace_back("request");
    const Flags flags = parse_flags(args, with_value, {"help"});
    if (flags.has("help")) {
      std::cout << kTuneHelp << kTuneFlagsHelp << kTuneHelpTail;
      return kExitOk;
    }
    print_json(app::run_tune(request_from(flags, [&] { return tune_fields_from_flags(flags); })));
    return kExitOk;
  });
}

}  // namespace softtune::cli
