// The JSON Schema subset: each keyword accepts what it should, refuses what it should, and names the JSON
// pointer of the offending place.
#include "codec/json_schema.h"

#include <gtest/gtest.h>

namespace softtune::codec {
namespace {

using nlohmann::json;

std::optional<SchemaError> check(const json& instance, const json& schema) { return validate_json_schema(instance, schema); }

TEST(JsonSchema, TypeEnumConstAndNumberBounds) {
  EXPECT_FALSE(check(3, {{"type", "integer"}}));
  EXPECT_FALSE(check(3.0, {{"type", "integer"}}));
  EXPECT_EQ(check(3.5, {{"type", "integer"}})->rule, "must be of type integer");
  EXPECT_FALSE(check("x", {{"type", json::array({"number", "string"})}}));
  EXPECT_TRUE(check(true, {{"type", json::array({"number", "string"})}}));
  EXPECT_FALSE(check("some", {{"enum", {"free", "some", "none"}}}));
  EXPECT_EQ(check("lots", {{"enum", {"free", "some"}}})->rule, "must be one of \"free\", \"some\"");
  EXPECT_EQ(check("circle", {{"const", "box"}})->rule, "must be exactly \"box\"");
  EXPECT_FALSE(check(1, {{"minimum", 1}}));
  EXPECT_TRUE(check(0.99, {{"minimum", 1}}));
  EXPECT_TRUE(check(0, {{"exclusiveMinimum", 0}}));
  EXPECT_FALSE(check(1e-9, {{"exclusiveMinimum", 0}}));
  EXPECT_EQ(check(11, {{"maximum", 10}})->rule, "must be <= 10");
  EXPECT_TRUE(check(10, {{"exclusiveMaximum", 10}}));
  EXPECT_TRUE(check("", {{"minLength", 1}}));
}

TEST(JsonSchema, ObjectsArraysAndPointers) {
  const json schema = {
      {"type", "object"},
      {"required", {"world"}},
      {"additionalProperties", false},
      {"properties", {{"world", {{"type", "object"}, {"properties", {{"fps", {{"type", "number"}, {"minimum", 1}}}}}}},
                      {"a/b", {{"type", "array"}, {"minItems", 1}, {"maxItems", 2}, {"items", {{"type", "number"}}}}}}}};
  EXPECT_FALSE(check({{"world", {{"fps", 60}}}}, schema));
  EXPECT_EQ(check(json::object(), schema)->pointer, "/world");
  EXPECT_EQ(check(json::object(), schema)->rule, "is required");
  auto e = check({{"world", {{"fps", 0}}}}, schema);
  EXPECT_EQ(e->pointer, "/world/fps");
  EXPECT_EQ(e->rule, "must be >= 1");
  e = check({{"world", json::object()}, {"extra", 1}}, schema);
  EXPECT_EQ(e->pointer, "/extra");
  EXPECT_EQ(e->rule, "is not a known field");
  e = check({{"world", json::object()}, {"a/b", {1, "x"}}}, schema);
  EXPECT_EQ(e->pointer, "/a~1b/1");  // RFC 6901 escaping
  EXPECT_EQ(check({{"world", json::object()}, {"a/b", json::array()}}, schema)->rule, "must have at least 1 items");
  EXPECT_EQ(check({{"world", json::object()}, {"a/b", {1, 2, 3}}}, schema)->rule, "must have at most 2 items");
}

TEST(JsonSchema, RefsAndOneOf) {
  const json schema = {
      {"$defs", {{"box", {{"type", "object"}, {"required", {"type", "width"}}, {"additionalProperties", false},
                          {"properties", {{"type", {{"const", "box"}}}, {"width", {{"type", "number"}, {"minimum", 0.001}}}}}}},
                 {"circle", {{"type", "object"}, {"required", {"type", "radius"}}, {"additionalProperties", false},
                             {"properties", {{"type", {{"const", "circle"}}}, {"radius", {{"type", "number"}}}}}}},
                 {"shape", {{"oneOf", {{{"$ref", "#/$defs/box"}}, {{"$ref", "#/$defs/circle"}}}}}}}},
      {"type", "array"},
      {"items", {{"$ref", "#/$defs/shape"}}}};
  EXPECT_FALSE(check(json::parse(R"([{"type":"box","width":1},{"type":"circle","radius":2}])"), schema));
  // The branch that got deepest names the field: the box's width.
  const auto e = check(json::parse(R"([{"type":"box","width":0}])"), schema);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->pointer, "/0/width");
  EXPECT_EQ(e->rule, "must be >= 0.001");
  // A circle with a bad radius is reported against the circle alternative, not as "width is required".
  const auto c = check(json::parse(R"([{"type":"circle","radius":"big"}])"), schema);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->pointer, "/0/radius");
  EXPECT_EQ(c->rule, "must be of type number");
  EXPECT_EQ(check(json::parse(R"([{"type":"circle"}])"), schema)->pointer, "/0/radius");
  // Matching two alternatives is refused too.
  const json both = {{"oneOf", {{{"type", "number"}}, {{"minimum", 0}}}}};
  EXPECT_EQ(check(5, both)->rule, "must match exactly one of the oneOf alternatives (2 match)");
  EXPECT_FALSE(check("x", both));
}

TEST(JsonSchema, RefusesWhatItCannotCheck) {
  EXPECT_THROW(check(1, {{"pattern", "^a"}}), std::invalid_argument);
  EXPECT_THROW(check(1, {{"$ref", "#/$defs/missing"}}), std::invalid_argument);
  EXPECT_THROW(check(1, {{"$ref", "other.json"}}), std::invalid_argument);
}

}  // namespace
}  // namespace softtune::codec
