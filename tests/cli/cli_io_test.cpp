// What the CLI commands share (cli_io.cpp): `--name value`, `--name=value` and switches; unknown flags and
// missing values refused naming the flag; numbers parsed whole and finite; the request from a file (strict
// JSON) alone or from the flags; a Problem is exit 2 with problem JSON on stderr, anything else exit 1 and 500.
#include "cli/cli_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "codec/problem.h"

namespace softtune::cli {
namespace {

using nlohmann::json;

// The field of the Problem `f` throws, or "(none)".
template <typename F>
std::string refused_field(F f) {
  try {
    f();
  } catch (const codec::Problem& p) {
    return p.field;
  }
  return "(none)";
}

TEST(CliIo, ParsesValuesInlineValuesSwitchesAndPositionals) {
  const Flags f = parse_flags({"presets", "--fps", "60", "--mode=exact", "--summary", "more"}, {"fps", "mode"}, {"summary"});
  EXPECT_EQ(f.get("fps"), "60");
  EXPECT_EQ(f.get("mode"), "exact");
  EXPECT_EQ(f.get("summary"), "true");
  EXPECT_FALSE(f.has("mass"));
  EXPECT_EQ(f.positional, (std::vector<std::string>{"presets", "more"}));
  EXPECT_EQ(refused_field([] { parse_flags({"--frobnicate", "3"}, {"fps"}, {}); }), "--frobnicate");
  EXPECT_EQ(refused_field([] { parse_flags({"--fps"}, {"fps"}, {}); }), "--fps");  // needs a value
}

TEST(CliIo, NumbersAreWholeAndFinite) {
  const Flags f = parse_flags({"--a", "1e3", "--b", "12abc", "--c", "inf", "--d", "nan", "--e", "-0.5"}, {"a", "b", "c", "d", "e"}, {});
  EXPECT_DOUBLE_EQ(flag_number(f, "a"), 1000.0);
  EXPECT_DOUBLE_EQ(flag_number(f, "e"), -0.5);
  for (const char* name : {"b", "c", "d"}) EXPECT_EQ(refused_field([&] { flag_number(f, name); }), std::string("--") + name);
}

TEST(CliIo, RequestFromAFileAloneOrFromTheFlags) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "softtune_cli_io_request.json";
  std::ofstream(file) << R"({"response_frames": 12})";
  const Flags with_file = parse_flags({"--request", file.string()}, {"request", "mass"}, {});
  EXPECT_EQ(request_from(with_file, [] { return json{{"from", "flags"}}; }), (json{{"response_frames", 12}}));
  const Flags no_file = parse_flags({"--mass", "2"}, {"request", "mass"}, {});
  EXPECT_EQ(request_from(no_file, [] { return json{{"from", "flags"}}; }), (json{{"from", "flags"}}));
  const Flags both = parse_flags({"--request", file.string(), "--mass", "2"}, {"request", "mass"}, {});
  EXPECT_EQ(refused_field([&] { request_from(both, [] { return json(); }); }), "--request");
  EXPECT_EQ(refused_field([] { read_request_file("/nonexistent/softtune.json"); }), "--request");
  std::ofstream(file) << R"({"fps": 60, "fps": 30})";  // strict JSON: a duplicated key is refused
  try {
    read_request_file(file.string());
    ADD_FAILURE() << "duplicated key accepted";
  } catch (const codec::Problem& p) {
    EXPECT_EQ(p.status, 400);
    EXPECT_EQ(p.field, "fps");
  }
  std::filesystem::remove(file);
}

TEST(CliIo, GuardedTurnsProblemsIntoExitCodes) {
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(guarded([] { return kExitOk; }), 0);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(guarded([]() -> int { throw codec::invalid_field("--mass", "must be > 0"); }), 2);
  const json problem = json::parse(::testing::internal::GetCapturedStderr());
  EXPECT_EQ(problem["status"], 422);
  EXPECT_EQ(problem["field"], "--mass");
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(guarded([]() -> int { throw std::runtime_error("disk full"); }), 1);
  const json internal = json::parse(::testing::internal::GetCapturedStderr());
  EXPECT_EQ(internal["status"], 500);
  EXPECT_EQ(internal["detail"], "disk full");
}

}  // namespace
}  // namespace softtune::cli
