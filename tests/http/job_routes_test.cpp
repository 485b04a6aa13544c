// The job routes (server/http/job_routes.cpp) through the real transport: a job's result is the synchronous
// route's answer for the same body, the 202 and the status conform to the OpenAPI document, a cancel stops a
// running sweep, the queue bound is a 503 with Retry-After, the job budget a 422 naming the fields, and ids
// that are not of the job form are a 404 that does not echo them.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "../codec/stability_sweeps.h"
#include "app/job_runner.h"
#include "openapi_conformance.h"
#include "test_server.h"

using nlohmann::json;
using softtune::http::testing::conformance_error;
using softtune::http::testing::presets_config;
using softtune::http::testing::quick_options;
using softtune::http::testing::TestServer;

namespace {

using softtune::http::testing::kJson;

// GETs the status URL until the job has ended (20 s at most).
json wait_until_ended(TestServer& s, const std::string& url) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  for (;;) {
    auto r = s.client().Get(url.c_str());
    if (!r || r->status != 200) return json();
    json doc = json::parse(r->body);
    const std::string state = doc["state"];
    if (state == "done" || state == "failed" || state == "cancelled" || std::chrono::steady_clock::now() > give_up) return doc;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

bool app_form(const std::string& id) { return softtune::app::is_job_id(id); }

}  // namespace

TEST(JobRoutes, AStabilityJobsResultIsTheSynchronousAnswer) {
  TestServer s(quick_options(), presets_config());
  const std::string body = softtune::test::small_sweep().dump();
  auto r = s.client().Post("/api/v1/stability/jobs", body, kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 202) << r->body;
  const json queued = json::parse(r->body);
  EXPECT_EQ(conformance_error("/api/v1/stability/jobs", "post", 202, kJson, queued), "");
  const std::string url = queued["status_url"];
  EXPECT_EQ(r->get_header_value("Location"), url);
  EXPECT_EQ(url, "/api/v1/jobs/" + queued["id"].get<std::string>());
  const json done = wait_until_ended(s, url);
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_EQ(conformance_error("/api/v1/jobs/{id}", "get", 200, kJson, done), "");
  auto sync = s.client().Post("/api/v1/stability", body, kJson);
  ASSERT_TRUE(sync);
  EXPECT_EQ(done["result"], json::parse(sync->body));
  EXPECT_EQ(done["progress"]["done"], done["progress"]["total"]);
}

TEST(JobRoutes, ACheckJobsResultIsTheSynchronousReport) {
  TestServer s(quick_options(), presets_config());
  const std::string body = R"({"presets": ["mouse", "chain"], "fps": [30, 60]})";
  auto r = s.client().Post("/api/v1/check/jobs", body, kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 202) << r->body;
  const json done = wait_until_ended(s, json::parse(r->body)["status_url"]);
  ASSERT_EQ(done["state"], "done") << done.dump();
  auto sync = s.client().Post("/api/v1/check", body, kJson);
  ASSERT_TRUE(sync);
  EXPECT_EQ(done["result"], json::parse(sync->body));
  EXPECT_EQ(done["progress"]["total"], 4);
  auto junit = s.client().Post("/api/v1/check/jobs", R"({"presets": ["mouse"], "format": "junit"})", kJson);
  ASSERT_TRUE(junit);
  EXPECT_EQ(junit->status, 422);
  EXPECT_EQ(json::parse(junit->body)["field"], "format");
}

TEST(JobRoutes, DeleteStopsARunningSweepAndTheQueueIsBounded) {
  TestServer s(quick_options(), presets_config());
  // The default grid at 20000 steps: 19950 cases, about 10 s in all; none of them runs to its end here.
  const std::string body = R"({"observe_steps": 20000})";
  std::vector<std::string> urls;
  for (std::size_t i = 0; i < softtune::app::kMaxQueuedJobs; ++i) {
    auto r = s.client().Post("/api/v1/stability/jobs", body, kJson);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 202) << r->body;
    urls.push_back(json::parse(r->body)["status_url"]);
  }
  auto full = s.client().Post("/api/v1/stability/jobs", body, kJson);
  ASSERT_TRUE(full);
  EXPECT_EQ(full->status, 503);
  EXPECT_EQ(full->get_header_value("Retry-After"), "5");
  EXPECT_EQ(conformance_error("/api/v1/stability/jobs", "post", 503, "application/problem+json", json::parse(full->body)), "");

  // The first is running: cancel it once it has done some cases; the queued ones are cancelled at once.
  for (;;) {
    auto r = s.client().Get(urls[0].c_str());
    ASSERT_TRUE(r);
    if (json::parse(r->body)["progress"]["done"].get<int>() >= 10) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  for (const std::string& url : urls) {
    auto d = s.client().Delete(url.c_str());
    ASSERT_TRUE(d);
    EXPECT_EQ(d->status, 200) << d->body;
  }
  const json first = wait_until_ended(s, urls[0]);
  EXPECT_EQ(first["state"], "cancelled");
  EXPECT_LT(first["progress"]["done"].get<int>(), first["progress"]["total"].get<int>() / 10);
  EXPECT_EQ(wait_until_ended(s, urls.back())["state"], "cancelled");
  auto again = s.client().Post("/api/v1/stability/jobs", R"({"observe_steps": 1000, "chain": false, "steps": [0.01]})", kJson);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 202) << again->body;
}

TEST(JobRoutes, BadBodiesAndTheJobBudgetAreRefusedBeforeQueueing) {
  TestServer s(quick_options(), presets_config());
  // 32 masses x the default grid at 100000 steps: far over 60 s; the fields that drive it are named.
  json big = {{"observe_steps", 100000}, {"masses", json::array()}};
  for (int i = 0; i < 32; ++i) big["masses"].push_back(1.0 + i);
  auto r = s.client().Post("/api/v1/stability/jobs", big.dump(), kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 422) << r->body;
  const json p = json::parse(r->body);
  EXPECT_EQ(p["budget_cpu_seconds"], 60.0);
  EXPECT_NE(std::find(p["fields"].begin(), p["fields"].end(), "observe_steps"), p["fields"].end()) << p.dump();
  EXPECT_EQ(conformance_error("/api/v1/stability/jobs", "post", 422, "application/problem+json", p), "");
  // The synchronous route's refusal of a job-sized request points to the job route.
  auto sync = s.client().Post("/api/v1/stability", R"({"observe_steps": 20000})", kJson);
  ASSERT_TRUE(sync);
  EXPECT_EQ(sync->status, 422);
  EXPECT_NE(json::parse(sync->body)["detail"].get<std::string>().find("POST /api/v1/stability/jobs"), std::string::npos);

  auto bad = s.client().Post("/api/v1/stability/jobs", R"({"methods": ["soft", "rk4"]})", kJson);
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 422);
  EXPECT_EQ(json::parse(bad->body)["field"], "methods.1");
  auto check = s.client().Post("/api/v1/check/jobs", R"({"presets": ["mouse", "no_such_preset"]})", kJson);
  ASSERT_TRUE(check);
  EXPECT_EQ(json::parse(check->body)["field"], "presets.1");
}

TEST(JobRoutes, IdsNotOfTheJobFormAre404sThatDoNotEchoThem) {
  TestServer s(quick_options(), presets_config());
  const std::string long_id(5000, 'a');
  for (const std::string& id : {long_id, std::string("j0123456789ABCDEF"), std::string("0123456789abcdef0"), std::string("j0123456789abcdef")}) {
    for (const char* method : {"GET", "DELETE"}) {
      auto r = std::string(method) == "GET" ? s.client().Get(("/api/v1/jobs/" + id).c_str()) : s.client().Delete(("/api/v1/jobs/" + id).c_str());
      ASSERT_TRUE(r);
      EXPECT_EQ(r->status, 404) << method << " " << id.substr(0, 20);
      if (app_form(id)) continue;  // well-formed but unknown: its 404 may name it
      EXPECT_EQ(r->body.find(id.substr(1, 12)), std::string::npos) << r->body;
      EXPECT_LT(r->body.size(), 400u);
    }
  }
}
