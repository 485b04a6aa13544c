// `softtune check [DIR]`: the automated preset test. One line per preset; exit code 1 when any fails.
#include <cstdio>
#include <iostream>

#include "cli/cli_io.h"
#include "app/preset_store.h"
#include "codec/problem.h"
#include "app/simulate_app.h"
#include "codec/scene_codec.h"

namespace softtune::cli {
namespace {

constexpr const char* kHelp = R"(softtune check [DIR]: run every preset's expectations.

  DIR        presets directory (default: $SOFTTUNE_PRESETS, else ./presets)
  --json     print the full results as JSON instead of one line per preset

Prints "NAME PASS|FAIL metric=value[min,max] ..." per preset (a failed expectation is marked "!").
Exit code 0 when every preset passes, 1 when any fails or cannot be loaded.
)";

std::string figure(const nlohmann::json& e) {
  auto number = [](const nlohmann::json& v) {
    if (v.is_null()) return std::string("null");
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", v.get<double>());
    return std::string(buffer);
  };
  std::string out = e["passed"].get<bool>() ? "" : "!";
  const std::string probe = e["probe"], metric = e["metric"], model = e["mass_model"];
  if (!probe.empty()) out.append(probe).append(".");
  out.append(metric);
  if (model != "effective") out.append("(").append(model).append(")");
  if (metric == "finite" || metric == "in_world") return out.append(e["value"] == 1.0 ? "=yes" : "=no");
  out.append("=").append(number(e["value"])).append("[");
  if (!e["min"].is_null()) out.append(number(e["min"]));
  out.append(",");
  if (!e["max"].is_null()) out.append(number(e["max"]));
  return out.append("]");
}

}  // namespace

int run_check(const Args& args) {
  return guarded([&] {
    const Flags flags = parse_flags(args, {}, {"json", "help"});
    if (flags.has("help")) {
      std::cout << kHelp;
      return kExitOk;
    }
    if (flags.positional.size() > 1) throw codec::invalid_field(flags.positional[1], "check takes at most one directory");
    const std::string dir = app::resolve_presets_dir(flags.positional.empty() ? std::nullopt : std::optional(flags.positional[0]));
    const std::vector<std::string> names = app::list_presets(dir);
    if (names.empty()) throw codec::Problem(404, "Not found", "presets", "no presets in \"" + dir + "\"");
    bool all = true;
    nlohmann::json report = nlohmann::json::array();
    for (const std::string& name : names) {
      nlohmann::json result;
      try {
        result = app::check_preset(app::load_preset(dir, name));
      } catch (const codec::Problem& p) {
        result = {{"name", name}, {"passed", false}, {"problem", codec::problem_json(p)}};
      }
      all = all && result["passed"].get<bool>();
      if (flags.has("json")) {
        report.push_back(result);
        continue;
      }
      std::string line = name;
      line.append(result["passed"].get<bool>() ? " PASS" : " FAIL");
      if (result.contains("problem")) {
        line.append(" ").append(result["problem"]["detail"].get<std::string>());
      } else {
        for (const auto& e : result["expectations"]) line.append(" ").append(figure(e));
      }
      std::cout << line << '\n';
    }
    if (flags.has("json")) print_json(report);
    return all ? kExitOk : kExitFailed;
  });
}

}  // namespace softtune::cli
