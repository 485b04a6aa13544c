// `softtune check [DIR|FILE...]`: the automated preset test a studio's CI runs. Every preset at every rate it
// ships at, each figure against a baseline, as text, JSON or JUnit XML; the work split in shards and run on
// a thread pool. The logic is app/check_app.h's (POST /api/v1/check runs the same); this file reads flags and
// prints. docs/preset-ci.md.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "app/check_app.h"
#include "app/check_junit.h"
#include "app/check_request.h"
#include "app/preset_store.h"
#include "cli/cli_io.h"
#include "cli/engine_flags.h"
#include "codec/problem.h"

namespace softtune::cli {
namespace {

constexpr const char* kCheckHelp = R"HELP(softtune check [DIR|FILE...] [flags]: run every preset's expectations.

  DIR|FILE              presets directories (each validated against its schema.json) and preset files
                        (validated against the schema.json beside them, else the default directory's);
                        default: $SOFTTUNE_PRESETS, else ./presets
  --fps LIST            comma-separated frame rates, e.g. 30,60,120,144 (default: each preset's
                        "rates": {"fps"}, else its world.fps)
  --substeps LIST       comma-separated substep counts, e.g. 1,4 (default: "rates": {"substeps"}, else
                        world.substeps); every preset is checked at every fps x substeps pair
  --format F            text (default: one line per preset and rate) | json | junit (JUnit XML)
  --json                the same as --format json
  --baseline FILE       compare every measured figure with FILE; a figure beyond its tolerance fails
  --update-baseline     write the figures measured now into --baseline FILE (other cases kept)
  -j N                  check N cases at once (1..64, default 1); the output order does not change
  --shard I/N           check only shard I of N: every N-th preset by name, from the I-th
  --engine NAME         run every case in this engine (default box2d_v2_4)
  --engine-settings name=value,...   that engine's own step settings

Text lines: "NAME@FPSxSUBSTEPS PASS|FAIL metric=value[min,max] ..." (a failed expectation is marked "!",
a drifted figure "~figure=value(baseline B)"); a summary goes to stderr.
Exit code 0 when every case passes, 1 when an expectation fails, a figure drifts or a preset cannot be
loaded or run, 2 on bad input (an unknown flag, a bad list, a missing path or baseline file).
)HELP";

std::string number(const nlohmann::json& v) {
  if (v.is_null()) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", v.get<double>());
  return buffer;
}

std::string figure(const nlohmann::json& e) {
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

std::string text_line(const app::CaseResult& c) {
  std::string line = app::case_key(c.preset, c.rate) + (c.passed ? " PASS" : " FAIL");
  if (c.problem) return line + " " + (*c.problem)["detail"].get<std::string>();
  for (const auto& e : c.expectations) line.append(" ").append(figure(e));
  for (const app::Drift& d : c.drift) {
    line.append(" ~").append(d.figure).append("=").append(d.value ? number(*d.value) : "undefined");
    line.append("(baseline ").append(d.baseline ? number(*d.baseline) : "undefined").append(")");
  }
  return line;
}

// "30,60,120" -> [30, 60, 120] for the request the app reads (which checks each entry and names it).
nlohmann::json list_from_flag(const Flags& flags, const std::string& name) {
  nlohmann::json out = nlohmann::json::array();
  std::stringstream in(*flags.get(name));
  std::string item;
  while (std::getline(in, item, ',')) {
    Flags one;
    one.values[name] = item;
    const double v = flag_number(one, name);
    if (name == "substeps" && v == static_cast<long long>(v)) {
      out.push_back(static_cast<long long>(v));
    } else {
      out.push_back(v);
    }
  }
  return out;
}

// -j N and -jN are --jobs N.
Args with_long_jobs_flag(const Args& args) {
  Args out;
  for (const std::string& a : args) {
    if (a == "-j") {
      out.push_back("--jobs");
    } else if (a.size() > 2 && a.rfind("-j", 0) == 0 && a[2] != '-') {
      out.push_back("--jobs=" + a.substr(2));
    } else {
      out.push_back(a);
    }
  }
  return out;
}

}  // namespace

int run_check(const Args& args) {
  return guarded([&] {
    const Flags flags = parse_flags(with_long_jobs_flag(args), {"fps", "substeps", "format", "baseline", "jobs", "shard", "engine", "engine-settings"},
                                    {"json", "help", "update-baseline"});
    if (flags.has("help")) {
      std::cout << kCheckHelp;
      return kExitOk;
    }
    const std::string format = flags.has("json") ? "json" : flags.get("format").value_or("text");
    if (format != "text" && format != "json" && format != "junit") throw codec::invalid_field("--format", "must be text, json or junit");

    nlohmann::json request = nlohmann::json::object();
    for (const char* list : {"fps", "substeps"}) {
      if (flags.has(list)) request[list] = list_from_flag(flags, list);
    }
    if (auto shard = flags.get("shard")) request["shard"] = *shard;
    set_engine_from_flags(flags, request);
    app::CheckOptions options;
    try {
      codec::ObjectReader r(request, "");
      app::read_check_options(r, options);
    } catch (const codec::Problem& p) {
      throw codec::Problem(p.status, p.title, "--" + p.field, p.detail);  // the flag, not the request field
    }
    if (auto jobs = flags.get("jobs")) {
      const double n = flag_number(flags, "jobs");
      if (n != static_cast<int>(n) || n < 1 || n > app::kMaxCheckJobs) {
        throw codec::invalid_field("-j", "must be an integer in [1, " + std::to_string(app::kMaxCheckJobs) + "]");
      }
      options.jobs = static_cast<int>(n);
    }

    const bool update = flags.has("update-baseline");
    const auto baseline_file = flags.get("baseline");
    if (update && !baseline_file) throw codec::invalid_field("--update-baseline", "needs --baseline FILE (the file to write)");
    app::Baseline baseline;
    if (baseline_file && (!update || std::filesystem::exists(*baseline_file))) baseline = app::read_baseline_file(*baseline_file);
    if (baseline_file && !update) options.baseline = &baseline;

    const std::string default_dir = app::resolve_presets_dir();
    const std::vector<std::string> paths = flags.positional.empty() ? std::vector<std::string>{default_dir} : flags.positional;
    const app::CheckReport report = app::run_checks(app::presets_from_paths(paths, default_dir), options);
    if (update) app::write_baseline_file(*baseline_file, app::updated_baseline(report, baseline));

    if (format == "json") {
      print_json(app::check_report_json(report));
    } else if (format == "junit") {
      std::cout << app::junit_xml(report);
    } else {
      for (const app::CaseResult& c : report.cases) std::cout << text_line(c) << '\n';
    }
    std::size_t failed = 0;
    for (const app::CaseResult& c : report.cases) failed += c.passed ? 0 : 1;
    std::cerr << "softtune check: " << report.cases.size() << " cases, " << failed << " failed (shard " << report.shard.index << "/"
              << report.shard.count << " of " << report.presets_total << " presets)" << (update ? ", baseline written" : "") << '\n';
    return report.passed ? kExitOk : kExitFailed;
  });
}

}  // namespace softtune::cli
