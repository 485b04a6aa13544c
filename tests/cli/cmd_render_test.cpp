// `softtune render` (cmd_render.cpp): writes the frames and the filmstrip as PNGs, names the motion by its
// content hash whichever way it is asked, and refuses bad flags with a problem naming the field (exit 2).
#include "cli/commands.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "png_decode.h"

namespace softtune::codec {
namespace {

class RenderCommand : public ::testing::Test {
 protected:
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("softtune_render_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                               "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void TearDown() override { std::filesystem::remove_all(dir); }
  int run(std::vector<std::string> args, std::string* out = nullptr, std::string* err = nullptr) {
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    const int code = cli::run_render(args);
    const std::string o = ::testing::internal::GetCapturedStdout(), e = ::testing::internal::GetCapturedStderr();
    if (out) *out = o;
    if (err) *err = e;
    return code;
  }
};

TEST_F(RenderCommand, WritesFramesAndFilmstrip) {
  std::string out;
  ASSERT_EQ(run({"--preset", "oscillator", "--frames", "5", "--size", "320x180", "--out", dir.string(),
                 "--response-frames", "20", "--mode", "exact"},
                &out),
            0);
  const auto doc = nlohmann::json::parse(out);
  ASSERT_EQ(doc["frames"].size(), 5u);
  EXPECT_EQ(doc["frames"][4], (dir / "frame_0004.png").string());
  // The oscillator runs on the core integrators: no Box2D stage, then rendering.
  EXPECT_EQ(doc["stages"], (nlohmann::json{"core_integrator", "render", "png_encode"}));
  EXPECT_EQ(doc["id"].get<std::string>().size(), 64u);
  for (const std::string name : {"frame_0000.png", "frame_0004.png", "filmstrip.png"}) {
    std::ifstream in(dir / name, std::ios::binary);
    ASSERT_TRUE(in) << name;
    std::stringstream bytes;
    bytes << in.rdbuf();
    const auto d = render::test::decode_png(bytes.str());
    if (name != "filmstrip.png") {
      EXPECT_EQ(d.width, 320);
      EXPECT_EQ(d.height, 180);
    }
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_0005.png"));
  // frames.json beside them: each frame's file and simulated time, spread over the oscillator's 3 s run
  // (180 steps at 60 fps: frames at steps 0, 45, 90, 135, 180).
  std::ifstream manifest_file(dir / "frames.json");
  ASSERT_TRUE(manifest_file);
  const auto manifest = nlohmann::json::parse(manifest_file);
  EXPECT_EQ(doc["manifest"], (dir / "frames.json").string());
  ASSERT_EQ(manifest["frames"].size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(manifest["frames"][k]["file"], "frame_000" + std::to_string(k) + ".png");
    EXPECT_NEAR(manifest["frames"][k]["time_s"].get<double>(), 45.0 * k / 60.0, 1e-12);
  }
  EXPECT_DOUBLE_EQ(manifest["run_end_s"].get<double>(), 3.0);
}

TEST_F(RenderCommand, AClipOverItsCapIsRefusedBeforeAnyFrameRenders) {
  // 121 frames of 1280x720 is one frame over the clip cap: a 422 naming frames, and no file written.
  std::string err;
  EXPECT_EQ(run({"--preset", "vehicle", "--frames", "121", "--size", "1280x720", "--out", dir.string(), "--animation", "webp"},
                nullptr, &err),
            2);
  EXPECT_NE(err.find("\"frames\""), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_0000.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "filmstrip.png"));
}

TEST_F(RenderCommand, AnimationFlagWritesTheClip) {
  std::string out, err;
  ASSERT_EQ(run({"--preset", "oscillator", "--frames", "3", "--size", "64x36", "--out", dir.string(), "--animation",
                 "gif"}, &out), 0);
  const auto doc = nlohmann::json::parse(out);
  EXPECT_EQ(doc["animation"], (dir / "animation.gif").string());
  std::ifstream in(dir / "animation.gif", std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  EXPECT_EQ(bytes.str().compare(0, 6, "GIF89a"), 0);
  EXPECT_EQ(run({"--preset", "oscillator", "--out", dir.string(), "--animation", "mp4"}, nullptr, &err), 2);
  EXPECT_NE(err.find("--animation"), std::string::npos);
}

TEST_F(RenderCommand, SameMotionSameIdWhicheverWayItIsAsked) {
  // 30 frames per period on a 60 Hz basis is 2 Hz: the same physics, so the same content hash.
  std::string a, b, c;
  ASSERT_EQ(run({"--preset", "oscillator", "--frames", "2", "--size", "64x36", "--out", dir.string(),
                 "--response-frames", "30"}, &a), 0);
  const std::filesystem::path request = dir / "request.json";
  std::ofstream(request) << R"({"frequency_hz": 2, "oscillation": "some", "effective_mass": 1})";
  ASSERT_EQ(run({"--preset", "oscillator", "--frames", "2", "--size", "64x36", "--out", dir.string(),
                 "--request", request.string()}, &b), 0);
  ASSERT_EQ(run({"--preset", "oscillator", "--frames", "2", "--size", "64x36", "--out", dir.string(),
                 "--response-frames", "31"}, &c), 0);
  EXPECT_EQ(nlohmann::json::parse(a)["id"], nlohmann::json::parse(b)["id"]);
  EXPECT_NE(nlohmann::json::parse(a)["id"], nlohmann::json::parse(c)["id"]);
  std::string err;
  EXPECT_EQ(run({"--preset", "oscillator", "--out", dir.string(), "--request", request.string(), "--mass", "2"},
                nullptr, &err), 2);
  EXPECT_NE(err.find("--request"), std::string::npos);
}

TEST_F(RenderCommand, RefusesWithAProblemNamingTheField) {
  std::string err;
  EXPECT_EQ(run({"--preset", "nosuch", "--out", dir.string()}, nullptr, &err), 2);
  EXPECT_NE(err.find("\"preset\""), std::string::npos);
  EXPECT_NE(err.find("nosuch"), std::string::npos);
  EXPECT_EQ(run({"--preset", "buddhas", "--out", dir.string(), "--mass", "2"}, nullptr, &err), 2);
  EXPECT_NE(err.find("--preset"), std::string::npos);
  EXPECT_EQ(run({"--preset", "oscillator", "--frames", "601", "--out", dir.string()}, nullptr, &err), 2);
  EXPECT_NE(err.find("\"frames\""), std::string::npos);
  EXPECT_EQ(run({"--preset", "oscillator", "--size", "3840x2160", "--out", dir.string()}, nullptr, &err), 2);
  EXPECT_NE(err.find("\"size\""), std::string::npos);
  EXPECT_EQ(run({"--preset", "oscillator", "--mass", "-1", "--out", dir.string()}, nullptr, &err), 2);
  EXPECT_NE(err.find("effective_mass"), std::string::npos);
  EXPECT_EQ(run({"--preset", "oscillator"}, nullptr, &err), 2);
  EXPECT_NE(err.find("--out"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_0000.png"));
}

}  // namespace
// `softtune render --engine` (issue 32): the frames come from that engine's run, named in the answer; an unknown
// engine is refused naming `engine` before anything renders.
TEST_F(RenderCommand, TheEngineFlagRendersThatEnginesRun) {
  std::string out, err;
  ASSERT_EQ(run({"--preset", "vehicle_per_spring", "--engine", "ode", "--frames", "3", "--size", "320x180", "--out", dir.string()},
                &out, &err),
            0) << err;
  const auto doc = nlohmann::json::parse(out);
  EXPECT_EQ(doc["engine"]["name"], "ode");
  ASSERT_EQ(doc["frames"].size(), 3u);
  const auto& stages = doc["stages"];
  EXPECT_NE(std::find(stages.begin(), stages.end(), "engine_step"), stages.end()) << stages;
  EXPECT_EQ(std::find(stages.begin(), stages.end(), "box2d_step"), stages.end()) << stages;
  std::ifstream in(dir / "frame_0002.png", std::ios::binary);
  ASSERT_TRUE(in);
  std::stringstream bytes;
  bytes << in.rdbuf();
  EXPECT_EQ(render::test::decode_png(bytes.str()).width, 320);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(run({"--preset", "vehicle_per_spring", "--engine", "havok", "--out", dir.string()}, nullptr, &err), 2);
  EXPECT_NE(err.find("\"engine\""), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_0000.png"));
}

}  // namespace softtune::codec
