// Strict JSON reading (json_reader.cpp): malformed, too deep or duplicated input is a 400 naming where it
// broke; typed fields refuse the wrong type, a non-integer, a wrong-length array, a choice not offered and an
// unknown field, each a 422 naming the dotted path.
#include "codec/json_reader.h"

#include <gtest/gtest.h>

#include <string>

#include "codec/problem.h"

using nlohmann::json;
using namespace softtune::codec;

namespace {

// The Problem `f` throws, or a failure when it throws none.
template <typename F>
Problem problem_from(F f) {
  try {
    f();
  } catch (const Problem& p) {
    return p;
  }
  ADD_FAILURE() << "no problem thrown";
  return Problem(0, "", "", "");
}

}  // namespace

TEST(JsonReader, RefusesMalformedDeepAndDuplicated) {
  EXPECT_THROW(parse_json("{\"a\": 1,"), Problem);
  EXPECT_THROW(parse_json("{\"fps\": 60, \"fps\": 30}"), Problem);
  std::string deep(100, '[');
  deep += std::string(100, ']');
  try {
    parse_json(deep);
    FAIL();
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 400);
  }
  EXPECT_NO_THROW(parse_json(std::string(20, '[') + std::string(20, ']')));
  // Huge exponents overflow a double: well-formed JSON, a value out of range (422) naming the field.
  try {
    parse_json(R"({"oscillation": "some", "response_frames": 1e999, "effective_mass": 1})");
    FAIL();
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "response_frames");
  }
}

TEST(JsonReader, ADuplicatedKeyIsNamedByItsPath) {
  const Problem top = problem_from([] { parse_json(R"({"fps": 60, "fps": 30})"); });
  EXPECT_EQ(top.status, 400);
  EXPECT_EQ(top.field, "fps");
  EXPECT_NE(top.detail.find("duplicated key \"fps\""), std::string::npos) << top.detail;
  const Problem nested = problem_from([] { parse_json(R"({"constraint": {"axis": [0, 1], "axis": [1, 0]}})"); });
  EXPECT_EQ(nested.field, "constraint.axis");
  // The same key in two different objects is no duplicate.
  EXPECT_NO_THROW(parse_json(R"({"body_a": {"mass": 1}, "body_b": {"mass": 2}})"));
  // A number too large for a double inside an array is named with its index.
  EXPECT_EQ(problem_from([] { parse_json(R"({"anchor_a": [0, 1e400]})"); }).field, "anchor_a.1");
}

TEST(ObjectReader, TypedFieldsRefuseTheWrongKindNamingThePath) {
  const json doc = json::parse(R"({"n": 3.0, "half": 2.5, "s": "x", "v": [1, 2], "mode": "exact",
                                   "inner": {"mass": "heavy"}, "extra": 1})");
  ObjectReader r(doc, "body");
  EXPECT_EQ(r.integer("n"), 3);  // 3.0 is an integer in JSON's number model
  const Problem half = problem_from([&] { r.integer("half"); });
  EXPECT_EQ(half.status, 422);
  EXPECT_EQ(half.field, "body.half");
  EXPECT_EQ(half.detail, "must be an integer");
  EXPECT_EQ(problem_from([&] { r.number("s"); }).detail, "must be a number");
  EXPECT_EQ(problem_from([&] { r.string("n"); }).detail, "must be a string");
  EXPECT_EQ(*r.numbers("v", 2), (std::vector<double>{1, 2}));
  EXPECT_EQ(problem_from([&] { r.numbers("v", 3); }).detail, "must be an array of 3 finite numbers");
  EXPECT_EQ(r.choice("mode", {"standard", "exact"}), 1u);
  EXPECT_EQ(problem_from([&] { r.choice("mode", {"free", "some"}); }).detail, "must be one of \"free\", \"some\"");
  std::optional<ObjectReader> inner = r.object("inner");
  ASSERT_TRUE(inner);
  EXPECT_EQ(problem_from([&] { inner->number("mass"); }).field, "body.inner.mass");
  EXPECT_FALSE(r.number("absent"));  // absent is no error: the caller applies its default
  // "extra" was never read: finish() refuses it by name.
  const Problem unknown = problem_from([&] { r.finish(); });
  EXPECT_EQ(unknown.field, "body.extra");
  EXPECT_EQ(unknown.detail, "is not a known field");
  EXPECT_EQ(problem_from([] { read_object(json::array(), "constraint"); }).field, "constraint");
}
