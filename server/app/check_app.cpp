#include "app/check_app.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <cstdio>
#include <filesystem>
#include <set>
#include <thread>

#include "app/check_cost.h"
#include "app/preset_store.h"
#include "codec/json_writer.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "softtune/support/run_limit.h"

namespace softtune::app {

using namespace softtune::codec;  // the codec is this layer's JSON vocabulary
using nlohmann::json;

namespace {

namespace fs = std::filesystem;

std::string short_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

// A decoded input: the scene, or the problem that refused it.
struct Prepared {
  const CheckInput* input = nullptr;
  std::optional<scene::Scene> scene;
  std::optional<json> problem;
};

struct Job {
  std::size_t prepared = 0;
  std::optional<CheckRate> rate;  ///< empty: the input could not be decoded
};

CaseResult run_case(const Prepared& p, const Job& job, const CheckOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  CaseResult c;
  c.preset = p.input->name;
  c.rate = job.rate.value_or(CheckRate{0.0, 0});
  try {
    if (p.problem) {
      c.problem = p.problem;
    } else {
      scene::RunOptions engine;
      engine.backend = options.engine.backend;
      engine.engine_settings = options.engine.settings;
      const scene::CheckResult check = scene::check_scene(at_rate(*p.scene, c.rate), engine);
      for (const scene::SceneResult& run : check.runs) {
        if (run.error) throw_field_error(*run.error);
      }
      c.expectations = expectations_json(check);
      c.figures = measured_figures(check);
      c.passed = check.passed;
      if (options.baseline) {
        const std::string key = case_key(c.preset, c.rate);
        c.in_baseline = options.baseline->cases.contains(key);
        c.drift = compare_with_baseline(*options.baseline, key, c.figures);
        c.passed = c.passed && c.drift.empty();
      }
    }
  } catch (const Problem& e) {
    c.problem = problem_json(e);
  } catch (const support::RunStopped&) {
    throw;  // the whole request stops (run_check)
  } catch (const std::exception& e) {
    // A worker thread must never let an exception escape; this case fails, the others still run.
    c.problem = problem_json(Problem(500, "Internal error", "", e.what()));
  }
  if (c.problem) c.passed = false;
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

// "drag.frequency_error", "hanger_1.frequency_error(box2d_reduced)"; appended piece by piece (GCC 12 warns
// -Wrestrict, wrongly, on the chained operator+ of these temporaries).
std::string figure_label(const json& e) {
  const std::string& probe = e["probe"].get_ref<const std::string&>();
  const std::string& model = e["mass_model"].get_ref<const std::string&>();
  std::string out = probe;
  if (!probe.empty()) out.append(".");
  out.append(e["metric"].get_ref<const std::string&>());
  if (model != "effective") out.append("(").append(model).append(")");
  return out;
}

}  // namespace

std::string case_key(const std::string& preset, const CheckRate& rate) {
  if (rate.substeps == 0) return preset;  // a preset that could not be read has no rate
  return preset + "@" + short_number(rate.fps) + "x" + std::to_string(rate.substeps);
}

std::vector<CheckRate> check_rates(const scene::Scene& scene, const CheckOptions& options) {
  const std::vector<double> fps = !options.fps.empty() ? options.fps
                                  : !scene.rates.fps.empty() ? scene.rates.fps
                                                             : std::vector<double>{scene.world.fps};
  const std::vector<int> substeps = !options.substeps.empty() ? options.substeps
                                    : !scene.rates.substeps.empty() ? scene.rates.substeps
                                                                    : std::vector<int>{scene.world.substeps};
  std::vector<CheckRate> out;
  for (double f : fps) {
    for (int s : substeps) {
      const CheckRate r{f, s};
      const bool seen = std::any_of(out.begin(), out.end(), [&](const CheckRate& o) { return o.fps == f && o.substeps == s; });
      if (!seen) out.push_back(r);
    }
  }
  return out;
}

scene::Scene at_rate(scene::Scene scene, const CheckRate& rate) {
  scene.world.fps = rate.fps;
  scene.world.substeps = rate.substeps;
  return scene;
}

std::vector<CheckInput> shard_inputs(std::vector<CheckInput> inputs, const Shard& shard) {
  std::stable_sort(inputs.begin(), inputs.end(), [](const CheckInput& a, const CheckInput& b) { return a.name < b.name; });
  std::vector<CheckInput> out;
  for (std::size_t i = static_cast<std::size_t>(shard.index - 1); i < inputs.size(); i += static_cast<std::size_t>(shard.count)) {
    out.push_back(std::move(inputs[i]));
  }
  return out;
}

std::vector<CheckInput> presets_from_paths(const std::vector<std::string>& paths, const std::string& fallback_schema_dir) {
  std::vector<CheckInput> out;
  std::set<std::string> names;
  auto add = [&](const std::string& name, const std::string& path, const auto& load) {
    if (!names.insert(name).second) throw invalid_field(path, "preset \"" + name + "\" is given twice");
    CheckInput in{name, json(), std::nullopt};
    try {
      in.document = load();
    } catch (const Problem& p) {
      in.problem = problem_json(p);  // an unreadable preset fails its case, the others still run
    }
    out.push_back(std::move(in));
  };
  for (const std::string& path : paths) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      const std::vector<std::string> found = list_presets(path);
      if (found.empty()) throw Problem(404, "Not found", path, "no presets in \"" + path + "\"");
      for (const std::string& name : found) add(name, path, [&] { return load_preset(path, name); });
      continue;
    }
    const fs::path file(path);
    if (!fs::is_regular_file(file, ec) || file.extension() != ".json") {
      throw Problem(404, "Not found", path, "\"" + path + "\" is neither a presets directory nor a preset file (NAME.json)");
    }
    // A preset file is validated against the schema.json beside it, else the default directory's.
    const fs::path dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    const std::string schema_dir = fs::is_regular_file(dir / "schema.json", ec) ? dir.string() : fallback_schema_dir;
    add(file.stem().string(), path, [&] { return load_preset_file(file.string(), schema_dir); });
  }
  return out;
}

CheckReport run_checks(const std::vector<CheckInput>& all_inputs, const CheckOptions& options) {
  CheckReport report;
  report.presets_total = all_inputs.size();
  report.shard = options.shard;
  if (options.engine.backend) report.engine = scene_engine_json(options.engine);
  const std::vector<CheckInput> inputs = shard_inputs(all_inputs, options.shard);

  std::vector<Prepared> prepared(inputs.size());
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    Prepared& p = prepared[i];
    p.input = &inputs[i];
    p.problem = inputs[i].problem;
    if (!p.problem) {
      try {
        p.scene = decode_scene(inputs[i].document);
      } catch (const Problem& e) {
        p.problem = problem_json(e);
      }
    }
    if (!p.scene) {
      jobs.push_back({i, std::nullopt});
      continue;
    }
    for (const CheckRate& r : check_rates(*p.scene, options)) jobs.push_back({i, r});
  }

  // A pool of `jobs` threads takes the cases largest first (their estimated work, check_cost.h), so the last
  // one to finish is a short one; each result lands in its own slot, so the report's order does not depend on
  // which thread finished first.
  std::vector<std::size_t> order(jobs.size());
  std::vector<double> cost(jobs.size(), 0.0);
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    order[k] = k;
    if (jobs[k].rate) cost[k] = case_work(*prepared[jobs[k].prepared].scene, *jobs[k].rate);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  report.cases.resize(jobs.size());
  std::atomic<std::size_t> next{0};
  if (options.progress) options.progress->set_total(jobs.size());
  // A run-time limit (softtune/support/run_limit.h) is the calling thread's: when it stops a case, the
  // other threads take no more cases, and it is rethrown once they are joined.
  std::exception_ptr stopped;
  auto work = [&] {
    try {
      for (std::size_t i = next++; i < jobs.size(); i = next++) {
        const std::size_t k = order[i];
        report.cases[k] = run_case(prepared[jobs[k].prepared], jobs[k], options);
        if (options.progress && !options.progress->advance()) next.store(jobs.size());
      }
    } catch (const support::RunStopped&) {
      stopped = std::current_exception();
      next.store(jobs.size());
    }
  };
  const int threads = std::clamp(options.jobs, 1, std::min<int>(kMaxCheckJobs, static_cast<int>(std::max<std::size_t>(1, jobs.size()))));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (stopped) std::rethrow_exception(stopped);

  for (const CaseResult& c : report.cases) report.passed = report.passed && c.passed;
  return report;
}

json expectations_json(const scene::CheckResult& check) {
  json out = json::array();
  for (const scene::ExpectationResult& e : check.results) {
    out.push_back({{"probe", e.expectation.probe},
                   {"metric", scene::metric_name(e.expectation.metric)},
                   {"mass_model", scene::mass_model_name(e.mass_model)},
                   {"value", number_or_null(e.value)},
                   {"min", number_or_null(e.expectation.min)},
                   {"max", number_or_null(e.expectation.max)},
                   {"passed", e.passed},
                   {"note", e.expectation.note}});
  }
  return out;
}

std::vector<std::string> failure_messages(const CaseResult& c) {
  std::vector<std::string> out;
  if (c.problem) {
    out.push_back((*c.problem)["detail"].get<std::string>());
    return out;
  }
  for (const json& e : c.expectations) {
    if (e["passed"].get<bool>()) continue;
    const std::string metric = e["metric"];
    std::string m = figure_label(e);
    if (metric == "finite" || metric == "in_world") {
      m += " = no";
    } else if (e["value"].is_null()) {
      m += " is undefined (no fit, or never settled)";
    } else {
      const double v = e["value"];
      m += " = " + short_number(v);
      if (!e["min"].is_null() && v < e["min"].get<double>()) m += ", below min " + short_number(e["min"]);
      if (!e["max"].is_null() && v > e["max"].get<double>()) m += ", above max " + short_number(e["max"]);
    }
    if (!e["note"].get<std::string>().empty()) m += " (" + e["note"].get<std::string>() + ")";
    out.push_back(std::move(m));
  }
  for (const Drift& d : c.drift) out.push_back("drift " + drift_message(d));
  return out;
}

json check_report_json(const CheckReport& report) {
  json cases = json::array();
  for (const CaseResult& c : report.cases) {
    json drift = json::array(), figures = json::object();
    for (const Drift& d : c.drift) {
      drift.push_back({{"figure", d.figure}, {"baseline", number_or_null(d.baseline)}, {"value", number_or_null(d.value)},
                       {"message", drift_message(d)}});
    }
    for (const Figure& f : c.figures) figures[f.name] = number_or_null(f.value);
    json entry = {{"preset", c.preset},
                  {"key", case_key(c.preset, c.rate)},
                  {"fps", c.rate.substeps == 0 ? json() : json(c.rate.fps)},
                  {"substeps", c.rate.substeps == 0 ? json() : json(c.rate.substeps)},
                  {"passed", c.passed},
                  {"expectations", c.expectations},
                  {"drift", std::move(drift)},
                  {"in_baseline", c.in_baseline},
                  {"figures", std::move(figures)},
                  {"failures", failure_messages(c)}};
    if (c.problem) entry["problem"] = *c.problem;
    cases.push_back(std::move(entry));
  }
  json out = {{"passed", report.passed},
              {"presets_total", report.presets_total},
              {"shard", {{"index", report.shard.index}, {"count", report.shard.count}}},
              {"cases", std::move(cases)}};
  if (!report.engine.is_null()) out["engine"] = report.engine;
  return out;
}

Baseline updated_baseline(const CheckReport& report, Baseline previous) {
  for (const CaseResult& c : report.cases) {
    if (c.problem) continue;  // nothing was measured
    auto& figures = previous.cases[case_key(c.preset, c.rate)];
    figures.clear();
    for (const Figure& f : c.figures) figures[f.name] = f.value;
  }
  return previous;
}

}  // namespace softtune::app
