// `softtune identify`: what a recorded trajectory did and what to type instead (contract: docs/identify.md).
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/identify_app.h"
#include "cli/cli_io.h"
#include "cli/tune_flags.h"
#include "codec/csv_recording.h"
#include "codec/problem.h"

namespace softtune::cli {
namespace {

constexpr const char* kIdentifyHelp = R"(softtune identify: what an engine did in a recorded trajectory, and what to type instead.

  softtune identify --csv FILE [options] [tune flags]   FILE (- for stdin): a header row, then time in
                                                         seconds and one column per probe
  softtune identify --request FILE                      the whole request as JSON (- for stdin)

  --engine NAME              the engine it was recorded in (a modelled one, e.g. box2d_v2_4, adds its exact)
  --typed-frequency HZ --typed-damping Z    what was typed, if not the request's values
  --typed-k K --typed-c C                   or the stiffness and damping typed
  --previous-csv FILE --previous-frequency HZ --previous-damping Z
                             an earlier recording and what was typed for it (the correction then iterates)
  --no-negative-damping      the engine refuses a negative damping: the correction never types one
 tune flags (the request the engine was tuned with; needed for the error and the correction):
)";
constexpr const char* kIdentifyHelpTail = R"(
Prints one JSON object: frequency, damping ratio, equilibrium, poles, residual, verdicts, and with a
request the error against it and the correction. Bad input: exit code 2.
)";

std::string read_text(const std::string& path, const std::string& flag) {
  std::stringstream buffer;
  if (path == "-") {
    buffer << std::cin.rdbuf();
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw codec::invalid_field("--" + flag, "cannot read file \"" + path + "\"");
    in.seekg(0, std::ios::end);
    if (static_cast<std::size_t>(in.tellg()) > codec::kCsvMaxBytes) throw codec::invalid_field("--" + flag, "must be at most 8 MiB");
    in.seekg(0);
    buffer << in.rdbuf();
  }
  std::string text = buffer.str();
  if (text.size() > codec::kCsvMaxBytes) throw codec::invalid_field("--" + flag, "must be at most 8 MiB");
  return text;
}

constexpr const char* kOwnFlags[] = {"csv", "engine", "typed-frequency", "typed-damping", "typed-k", "typed-c",
                                     "previous-csv", "previous-frequency", "previous-damping"};

nlohmann::json typed_from(const Flags& flags, const char* f, const char* z, const char* k, const char* c) {
  nlohmann::json typed = nlohmann::json::object();
  if (flags.has(f)) typed["frequency_hz"] = flag_number(flags, f);
  if (flags.has(z)) typed["damping_ratio"] = flag_number(flags, z);
  if (k && flags.has(k)) typed["k"] = flag_number(flags, k);
  if (c && flags.has(c)) typed["c"] = flag_number(flags, c);
  return typed;
}

}  // namespace

int run_identify(const Args& args) {
  return guarded([&] {
    std::vector<std::string> with_value = tune_flag_names();
    with_value.emplace_back("request");
    for (const char* f : kOwnFlags) with_value.emplace_back(f);
    const Flags flags = parse_flags(args, with_value, {"help", "no-negative-damping"});
    if (flags.has("help")) {
      std::cout << kIdentifyHelp << kTuneFlagsHelp << kIdentifyHelpTail;
      return kExitOk;
    }
    print_json(app::run_identify(request_from(flags, [&] {
      if (!flags.has("csv")) throw codec::invalid_field("--csv", "is required (or --request FILE): the recording");
      if (flags.get("csv") == "-" && flags.get("previous-csv") == "-") {
        throw codec::invalid_field("--previous-csv", "cannot also read stdin");
      }
      Flags tune_only = flags;
      for (const char* f : kOwnFlags) tune_only.values.erase(f);
      tune_only.values.erase("no-negative-damping");
      nlohmann::json request = {{"csv", read_text(*flags.get("csv"), "csv")}};
      const nlohmann::json tune = tune_fields_from_flags(tune_only);
      if (!tune.empty()) request["request"] = tune;
      if (auto e = flags.get("engine")) request["engine"] = *e;
      if (flags.has("no-negative-damping")) request["negative_damping"] = false;
      const nlohmann::json typed = typed_from(flags, "typed-frequency", "typed-damping", "typed-k", "typed-c");
      if (!typed.empty()) request["typed"] = typed;
      if (auto p = flags.get("previous-csv")) {
        request["previous"] = nlohmann::json::array(
            {{{"csv", read_text(*p, "previous-csv")},
              {"typed", typed_from(flags, "previous-frequency", "previous-damping", nullptr, nullptr)}}});
      }
      return request;
    })));
    return kExitOk;
  });
}

}  // namespace softtune::cli
