#include "app/check_request.h"

#include <algorithm>
#include <set>

#include "app/check_cost.h"
#include "app/check_junit.h"
#include "app/preset_store.h"
#include "app/request_cost.h"
#include "app/simulate_app.h"
#include "codec/list_reader.h"
#include "codec/problem.h"
#include "softtune/scene/limits.h"
#include "softtune/validation.h"

namespace softtune::app {

using namespace softtune::codec;  // the codec is this layer's JSON vocabulary
using nlohmann::json;

namespace {

std::optional<int> whole_number(const std::string& s) {
  if (s.empty() || s.size() > 6 || s.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  return std::stoi(s);
}

}  // namespace

Shard parse_shard(const std::string& text, const std::string& field) {
  const auto slash = text.find('/');
  const std::string rule = "must be I/N: this runner's shard I of N, 1 <= I <= N <= " + std::to_string(kMaxShards) + ", got \"" + text + "\"";
  if (slash == std::string::npos) throw invalid_field(field, rule);
  const auto i = whole_number(text.substr(0, slash)), n = whole_number(text.substr(slash + 1));
  if (!i || !n || *i < 1 || *n < 1 || *i > *n || *n > kMaxShards) throw invalid_field(field, rule);
  return {*i, *n};
}

void read_check_options(ObjectReader& r, CheckOptions& options) {
  if (auto v = read_number_list(r, "fps", scene::limits::kMaxRates, softtune::limits::kMinFps, scene::limits::kMaxSceneFps, "Hz")) options.fps = *v;
  if (auto v = read_integer_list(r, "substeps", scene::limits::kMaxRates, 1, scene::limits::kMaxSceneSubsteps)) options.substeps = *v;
  if (auto s = r.string("shard")) options.shard = parse_shard(*s, r.field("shard"));
  options.engine = read_request_engine(r);
}

CheckPlan plan_check_request(const json& request, const std::string& presets_dir) {
  ObjectReader r = read_object(request, "");
  CheckPlan plan;
  CheckOptions& options = plan.options;
  read_check_options(r, options);
  if (auto f = r.choice("format", {"json", "junit"})) plan.junit = *f == 1;

  std::vector<CheckInput>& inputs = plan.inputs;
  std::set<std::string> names;
  if (const json* list = r.raw("presets")) {
    if (!list->is_array() || list->empty() || list->size() > kMaxCheckPresets) {
      throw invalid_field("presets", "must be an array of 1 to " + std::to_string(kMaxCheckPresets) + " preset names");
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string field = "presets." + std::to_string(i);
      if (!(*list)[i].is_string()) throw invalid_field(field, "must be a preset name (see GET /api/v1/presets)");
      const std::string name = (*list)[i];
      if (!names.insert(name).second) throw invalid_field(field, "names \"" + name + "\" twice");
      try {
        inputs.push_back({name, load_preset(presets_dir, name), std::nullopt});
      } catch (const Problem& p) {
        throw Problem(p.status, p.title, field, p.detail);  // a name the caller typed: bad input, not a failed case
      }
    }
  }
  if (const json* list = r.raw("scenes")) {
    if (!list->is_array() || list->empty() || list->size() > kMaxCheckScenes) {
      throw invalid_field("scenes", "must be an array of 1 to " + std::to_string(kMaxCheckScenes) + " scenes");
    }
    const json schema = load_schema(presets_dir);
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string field = "scenes." + std::to_string(i);
      const json& doc = (*list)[i];
      if (!doc.is_object()) throw invalid_field(field, "must be a JSON object (a scene, as in presets/*.json)");
      try {
        validate_preset(doc, schema, field);
      } catch (const Problem& p) {
        // The schema names the field as a dotted path within the scene ("world.fps"): put it under the scene's.
        std::string inner = p.field;
        std::replace(inner.begin(), inner.end(), '/', '.');
        if (!inner.empty() && inner.front() == '.') inner.erase(0, 1);
        throw Problem(p.status, p.title, inner.empty() ? field : field + "." + inner, p.detail);
      }
      const std::string name = doc.at("name");
      if (!names.insert(name).second) throw invalid_field(field + ".name", "\"" + name + "\" is the name of another preset or scene");
      inputs.push_back({name, doc, std::nullopt});
    }
  }
  if (!r.has("presets") && !r.has("scenes")) {
    for (const std::string& name : list_presets(presets_dir)) {
      CheckInput in{name, json(), std::nullopt};
      try {
        in.document = load_preset(presets_dir, name);
      } catch (const Problem& p) {
        in.problem = problem_json(p);
      }
      inputs.push_back(std::move(in));
    }
  }
  if (const json* b = r.raw("baseline")) plan.baseline = decode_baseline(*b, "baseline");
  r.finish();
  plan.work = check_work(inputs, options);
  return plan;
}

CheckAnswer run_check_plan(const CheckPlan& plan, JobProgress* progress) {
  CheckOptions options = plan.options;
  if (plan.baseline) options.baseline = &*plan.baseline;
  options.progress = progress;
  const CheckReport report = run_checks(plan.inputs, options);
  if (progress && progress->cancelled()) throw JobCancelled{};
  CheckAnswer answer;
  answer.junit = plan.junit;
  if (answer.junit) {
    answer.xml = junit_xml(report);
  } else {
    answer.json = check_report_json(report);
  }
  return answer;
}

CheckAnswer run_check_request(const json& request, const std::string& presets_dir) {
  const CheckPlan plan = plan_check_request(request, presets_dir);
  require_check_budget(plan.work, kMaxCheckWork, kCheckCostFields, job_route_hint(kCheckJobsRoute));
  return run_check_plan(plan, nullptr);
}

CheckPlan plan_check_job(const json& request, const std::string& presets_dir) {
  CheckPlan plan = plan_check_request(request, presets_dir);
  // A job's result is the JSON report; JUnit XML is the synchronous route's.
  if (plan.junit) throw invalid_field("format", "a check job answers the JSON report: ask \"format\": \"json\" (or leave it out), or POST /api/v1/check for JUnit XML");
  require_check_budget(plan.work, kMaxCheckJobWork, kCheckCostFields);
  return plan;
}

}  // namespace softtune::app
