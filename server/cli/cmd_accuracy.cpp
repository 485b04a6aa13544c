// `softtune accuracy`: the work-precision report (contract: docs/accuracy-and-stability.md).
#include <iostream>
#include <sstream>

#include "app/accuracy_app.h"
#include "cli/cli_io.h"
#include "cli/tune_flags.h"
#include "codec/problem.h"

namespace softtune::cli {
namespace {

constexpr const char* kAccuracyHelp = R"(softtune accuracy: error against run time for every method, and a recommendation.

  softtune accuracy --request FILE   read the request JSON from FILE (- for stdin): a tune request plus
                                     error_budget, step_rates, soft_substeps, duration_s, timing_repeats, box2d
  softtune accuracy [flags]          or build it from the tune flags:
)";
constexpr const char* kAccuracyHelpTail = R"(  report flags:
    --error-budget B    max position error as a fraction of the amplitude (default 0.05)
    --step-rates LIST   comma-separated fps values (default 30,60,120,240,480; the request's fps is added)
    --duration S        simulated seconds (minimum 3 periods; default 3 periods, or 8 frames of the
                        lowest step rate when longer)
    --no-box2d          leave out the Box2D 2.4 distance joint row
    --format F          json (default) | csv | svg

Bad input: exit code 2 and a problem JSON on stderr naming the field.
)";

nlohmann::json step_rates_from_flag(const std::string& text) {
  nlohmann::json out = nlohmann::json::array();
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    Flags one;
    one.values["step-rates"] = item;
    out.push_back(flag_number(one, "step-rates"));
  }
  return out;
}

}  // namespace

int run_accuracy(const Args& args) {
  return guarded([&] {
    std::vector<std::string> with_value = tune_flag_names();
    for (const char* f : {"request", "format", "error-budget", "step-rates", "duration"}) with_value.emplace_back(f);
    const Flags flags = parse_flags(args, with_value, {"help", "no-box2d"});
    if (flags.has("help")) {
      std::cout << kAccuracyHelp << kTuneFlagsHelp << kAccuracyHelpTail;
      return kExitOk;
    }
    const app::Format format = app::format_named(flags.get("format").value_or("json"),
                                                 {app::Format::json, app::Format::csv, app::Format::svg}, "--format");
    nlohmann::json request;
    if (auto file = flags.get("request")) {
      for (const auto& [name, value] : flags.values) {
        if (name != "request" && name != "format") {
          throw codec::invalid_field("--request", "cannot be combined with --" + name + " (only with --format)");
        }
      }
      request = read_request_file(*file);
    } else {
      request = tune_fields_from_flags(flags);
      if (flags.has("error-budget")) request["error_budget"] = flag_number(flags, "error-budget");
      if (flags.has("duration")) request["duration_s"] = flag_number(flags, "duration");
      if (auto rates = flags.get("step-rates")) request["step_rates"] = step_rates_from_flag(*rates);
      if (flags.has("no-box2d")) request["box2d"] = false;
    }
    print_answer(app::accuracy_answer(request, format));
    return kExitOk;
  });
}

}  // namespace softtune::cli
