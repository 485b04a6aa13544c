// `softtune verify`: a tuning run in the real engines linked in process (contract: docs/engines.md).
#include <iostream>

#include "app/verify_app.h"
#include "cli/cli_io.h"
#include "cli/tune_flags.h"

namespace softtune::cli {
namespace {

constexpr const char* kVerifyHelp = R"(softtune verify: run a tuning in the real engines and measure what they do.

  softtune verify --request FILE    read the request JSON from FILE (- for stdin): the tune fields plus
                                    "engines": ["box2d_v2_4", ...], "duration_s", "body", "x0"
  softtune verify --engines a,b [--duration S] [--body point|rotating_plank] [tune flags]:
)";
constexpr const char* kVerifyHelpTail = R"(
Prints one JSON object: per engine what to type, what its model predicts, what the engine measured, and
the same for the exact parameters. Without --engines no engine runs. Bad input: exit code 2.
)";

nlohmann::json split_names(const std::string& list) {
  nlohmann::json out = nlohmann::json::array();
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = list.find(',', start);
    const std::string name = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!name.empty()) out.push_back(name);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

int run_verify(const Args& args) {
  return guarded([&] {
    std::vector<std::string> with_value = tune_flag_names();
    for (const char* f : {"request", "engines", "duration", "body"}) with_value.emplace_back(f);
    const Flags flags = parse_flags(args, with_value, {"help"});
    if (flags.has("help")) {
      std::cout << kVerifyHelp << kTuneFlagsHelp << kVerifyHelpTail;
      return kExitOk;
    }
    print_json(app::run_verify(request_from(flags, [&] {
      Flags tune_only = flags;
      for (const char* f : {"engines", "duration", "body"}) tune_only.values.erase(f);
      nlohmann::json request = tune_fields_from_flags(tune_only);
      if (auto e = flags.get("engines")) request["engines"] = split_names(*e);
      if (auto d = flags.get("duration")) request["duration_s"] = flag_number(flags, "duration");
      if (auto b = flags.get("body")) request["body"] = *b;
      return request;
    })));
    return kExitOk;
  });
}

}  // namespace softtune::cli
