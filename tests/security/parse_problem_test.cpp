// Regressions found by the bad-input matrix: a parse error quoting invalid UTF-8 made the problem
// itself unserializable (the route answered 500 instead of 400), and parse errors inside nested
// objects named only the last key ("anchor_a" for "constraint.anchor_a").
#include <gtest/gtest.h>

#include <string>

#include "codec/json_reader.h"
#include "codec/problem.h"

namespace softtune::codec {
namespace {

Problem parse_problem(const std::string& text) {
  try {
    parse_json(text);
  } catch (const Problem& p) {
    return p;
  }
  ADD_FAILURE() << "parsed: " << text;
  return Problem(0, "", "", "");
}

TEST(ParseProblem, InvalidUtf8IsA400WhoseProblemStillSerializes) {
  for (const std::string text : {"{\"oscillation\": \"\xff\xfe\xc3\x28\"}", "{\"\xc0\xaf\": 1}", "\xff"}) {
    const Problem p = parse_problem(text);
    EXPECT_EQ(p.status, 400);
    std::string dumped;
    EXPECT_NO_THROW(dumped = problem_json(p).dump()) << p.detail;
    EXPECT_NE(dumped.find("Malformed JSON"), std::string::npos);
  }
}

TEST(ParseProblem, AProblemQuotingInvalidBytesKeepsTheRestOfItsText) {
  const Problem p(404, "Unknown preset", "preset", "no preset \"a\xff" "b\"");
  EXPECT_EQ(p.detail, "no preset \"a\xEF\xBF\xBD" "b\"");  // U+FFFD in place of the bad byte
  EXPECT_NO_THROW((void)problem_json(p).dump());
}

TEST(ParseProblem, OverflowingNumbersNameTheirWholePath) {
  EXPECT_EQ(parse_problem(R"({"response_frames": 1e999})").field, "response_frames");
  EXPECT_EQ(parse_problem(R"({"constraint": {"anchor_a": [1, -1e999]}})").field, "constraint.anchor_a.1");
  EXPECT_EQ(parse_problem(R"({"constraint": {"body_b": {"mass": 1e400}}})").field, "constraint.body_b.mass");
  EXPECT_EQ(parse_problem(R"({"a": [[1, 2], {"b": [0, 0, 1e999]}]})").field, "a.1.b.2");
}

TEST(ParseProblem, DuplicatedKeysNameTheirWholePath) {
  EXPECT_EQ(parse_problem(R"({"fps": 60, "fps": 30})").field, "fps");
  EXPECT_EQ(parse_problem(R"({"constraint": {"body_b": {"mass": 1, "mass": 2}}})").field, "constraint.body_b.mass");
  EXPECT_EQ(parse_problem(R"({"oscillators": [{"id": "a"}, {"id": "b", "id": "c"}]})").field, "oscillators.1.id");
}

}  // namespace
}  // namespace softtune::codec
