// POST /api/v1/preview and its frame routes, against a real in-process server.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "openapi_conformance.h"
#include "softtune/render/renderer.h"
#include "test_server.h"

using nlohmann::json;
using softtune::http::testing::presets_config;
using softtune::http::testing::TestServer;

namespace {

json post_preview(httplib::Client& c, const json& body, int& status) {
  auto r = c.Post("/api/v1/preview", body.dump(), "application/json");
  status = r ? r->status : 0;
  return r ? json::parse(r->body) : json();
}

// Whether a shared object whose file name contains `name` is mapped into this process.
bool mapped(const std::string& name) {
  std::ifstream maps("/proc/self/maps");
  for (std::string line; std::getline(maps, line);) {
    if (line.find(name) != std::string::npos) return true;
  }
  return false;
}

// PNG files start with these eight bytes.
bool is_png(const std::string& bytes) { return bytes.rfind("\x89PNG\r\n\x1a\n", 0) == 0; }

}  // namespace

TEST(PreviewRoutes, NoContextUntilFramesAreAskedFor) {
  const int before = softtune::render::gl_contexts_created();
  TestServer server;
  auto c = server.client();
  ASSERT_EQ(c.Get("/api/v1/health")->status, 200);
  ASSERT_EQ(c.Post("/api/v1/tune", R"({"response_frames": 12, "oscillation": "some", "effective_mass": 1})",
                   "application/json")->status, 200);
  EXPECT_EQ(c.Get("/api/v1/preview/abc/0.png")->status, 404);
  EXPECT_EQ(softtune::render::gl_contexts_created(), before);
}

// Mesa and LLVM (about 50 MB of RSS as soon as they are mapped) never enter the server: the first
// preview starts raster processes that hold the GL contexts.
TEST(PreviewRoutes, MesaStaysOutOfTheServerProcess) {
  const int started = softtune::render::raster_processes_started();
  TestServer server;
  auto c = server.client();
  ASSERT_EQ(c.Post("/api/v1/tune", R"({"response_frames": 12, "oscillation": "some", "effective_mass": 1})",
                   "application/json")->status, 200);
  EXPECT_EQ(softtune::render::raster_processes_started(), started);
  int status = 0;
  const json answer = post_preview(c, {{"response_frames", 12}, {"oscillation", "some"}, {"effective_mass", 1},
                                       {"frames", 2}, {"size", "32x18"}}, status);
  ASSERT_EQ(status, 200) << answer.dump();
  EXPECT_GT(softtune::render::raster_processes_started(), started);
  EXPECT_GE(softtune::render::gl_contexts_created(), 1);
  EXPECT_FALSE(mapped("libOSMesa"));
  EXPECT_FALSE(mapped("libLLVM"));
}

TEST(PreviewRoutes, OscillatorFramesAreServedWithCachingHeaders) {
  TestServer server;
  auto c = server.client();
  int status = 0;
  const json body = {{"response_frames", 20}, {"oscillation", "free"}, {"effective_mass", 1}, {"mode", "exact"},
                     {"frames", 4}, {"size", "64x36"}};
  const json answer = post_preview(c, body, status);
  ASSERT_EQ(status, 200) << answer.dump();
  EXPECT_EQ(softtune::http::testing::conformance_error("/api/v1/preview", "post", 200, "application/json", answer), "");
  EXPECT_EQ(answer["status"], "done");
  ASSERT_EQ(answer["frames"].size(), 4u);
  EXPECT_EQ(answer["stages"], (json{"core_integrator", "render", "png_encode"}));  // no Box2D for the oscillator

  auto frame = c.Get(answer["frames"][3].get<std::string>().c_str());
  ASSERT_EQ(frame->status, 200);
  EXPECT_EQ(frame->get_header_value("Content-Type"), "image/png");
  EXPECT_TRUE(is_png(frame->body));
  const std::string etag = frame->get_header_value("ETag");
  EXPECT_NE(etag.find(answer["id"].get<std::string>()), std::string::npos);
  auto again = c.Get(answer["frames"][3].get<std::string>().c_str(), {{"If-None-Match", etag}});
  EXPECT_EQ(again->status, 304);
  EXPECT_TRUE(is_png(c.Get(answer["filmstrip"].get<std::string>().c_str())->body));

  // The same request again is a cache hit with the same id; nothing runs.
  const json repeat = post_preview(c, body, status);
  EXPECT_EQ(repeat["id"], answer["id"]);
  EXPECT_TRUE(repeat["cached"].get<bool>());
  EXPECT_EQ(repeat["stages"], json::array());

  // Progress of a known id; a frame past the end and an unknown id are 404.
  EXPECT_EQ(json::parse(c.Get(answer["progress_url"].get<std::string>().c_str())->body)["status"], "done");
  EXPECT_EQ(c.Get(("/api/v1/preview/" + answer["id"].get<std::string>() + "/4.png").c_str())->status, 404);
  EXPECT_EQ(c.Get("/api/v1/preview/nosuchid/0.png")->status, 404);
}

// Clips of a finished preview: made on first ask, cached, content-addressed like the PNGs.
TEST(PreviewRoutes, ClipsAreServedAsWebpAndGif) {
  TestServer server(softtune::http::testing::quick_options(), presets_config());
  auto c = server.client();
  int status = 0;
  const json answer = post_preview(c, {{"preset", "mouse"}, {"frames", 6}, {"size", "64x36"}}, status);
  ASSERT_EQ(status, 200) << answer.dump();
  EXPECT_EQ(softtune::http::testing::conformance_error("/api/v1/preview", "post", 200, "application/json", answer), "");
  const std::string webp_url = answer["animation"]["webp"], gif_url = answer["animation"]["gif"];
  EXPECT_EQ(webp_url, "/api/v1/preview/" + answer["id"].get<std::string>() + "/animation.webp");
  auto webp = c.Get(webp_url.c_str());
  ASSERT_EQ(webp->status, 200);
  EXPECT_EQ(webp->get_header_value("Content-Type"), "image/webp");
  EXPECT_EQ(webp->body.compare(0, 4, "RIFF"), 0);
  EXPECT_EQ(webp->body.compare(8, 4, "WEBP"), 0);
  const std::string etag = webp->get_header_value("ETag");
  EXPECT_EQ(c.Get(webp_url.c_str(), {{"If-None-Match", etag}})->status, 304);
  EXPECT_EQ(c.Get(webp_url.c_str())->body, webp->body);  // from the clip cache: the same bytes
  auto gif = c.Get(gif_url.c_str());
  ASSERT_EQ(gif->status, 200);
  EXPECT_EQ(gif->get_header_value("Content-Type"), "image/gif");
  EXPECT_EQ(gif->body.compare(0, 6, "GIF89a"), 0);
  EXPECT_EQ(c.Get("/api/v1/preview/nosuchid/animation.webp")->status, 404);
  EXPECT_EQ(c.Get("/api/v1/preview/nosuchid/animation.gif")->status, 404);
}

TEST(PreviewRoutes, SceneFramesRunTheBox2DScene) {
  unsetenv("SOFTTUNE_PRESETS");  // the presets come from the server's configuration alone
  TestServer server(softtune::http::testing::quick_options(), presets_config());
  auto c = server.client();
  int status = 0;
  const json answer = post_preview(c, {{"preset", "buddhas"}, {"frames", 3}, {"size", "64x36"}}, status);
  ASSERT_EQ(status, 200) << answer.dump();
  const json& stages = answer["stages"];
  EXPECT_NE(std::find(stages.begin(), stages.end(), "box2d_world"), stages.end());
  EXPECT_NE(std::find(stages.begin(), stages.end(), "render"), stages.end());
}

TEST(PreviewRoutes, BadInputNamesTheField) {
  TestServer server(softtune::http::testing::quick_options(), presets_config());
  auto c = server.client();
  int status = 0;
  EXPECT_EQ(post_preview(c, {{"preset", "buddhas"}, {"frames", 601}}, status)["field"], "frames");
  EXPECT_EQ(status, 422);
  EXPECT_EQ(post_preview(c, {{"preset", "buddhas"}, {"size", "4000x4000"}}, status)["field"], "size");
  EXPECT_EQ(post_preview(c, {{"preset", "nosuch"}}, status)["field"], "preset");
  EXPECT_EQ(status, 404);
  EXPECT_EQ(post_preview(c, json::object(), status)["field"], "preset");
  EXPECT_EQ(post_preview(c, {{"preset", "buddhas"}, {"effective_mass", 2}}, status)["field"], "preset");
  EXPECT_EQ(post_preview(c, {{"preset", "buddhas"}, {"wait", "yes"}}, status)["field"], "wait");
}
