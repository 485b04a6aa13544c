#include "codec/json_schema.h"

#include <gtest/gtest.h>

#include <fstream>
#include <vector>

using nlohmann::json;
using softtune::codec::validate_json_schema;

namespace {

const json kSchema = json::parse(R"({
  "$defs": {
    "positive": {"type": "number", "exclusiveMinimum": 0},
    "body": {"type": "object", "required": ["mass"], "additionalProperties": false,
             "properties": {"mass": {"$ref": "#/$defs/positive"}, "shape": {"enum": ["box", "circle"]}}}
  },
  "type": "object",
  "required": ["name", "bodies"],
  "properties": {
    "name": {"type": "string", "minLength": 1},
    "fps": {"type": "integer", "minimum": 1, "maximum": 1000},
    "bodies": {"type": "array", "minItems": 1, "maxItems": 3, "items": {"$ref": "#/$defs/body"}},
    "oscillation": {"oneOf": [{"type": "number", "minimum": 0}, {"enum": ["free", "some", "none"]}]}
  }
})");

std::string pointer_of(const json& instance) {
  auto e = validate_json_schema(instance, kSchema);
  return e ? e->pointer : "ok";
}

}  // namespace

TEST(JsonSchema, AcceptsAValidDocument) {
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "a", "fps": 60, "bodies": [{"mass": 2, "shape": "box"}],
                                       "oscillation": "some"})")), "ok");
}

TEST(JsonSchema, NamesTheOffendingLocation) {
  EXPECT_EQ(pointer_of(json::parse(R"({"bodies": [{"mass": 1}]})")), "/name");
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "a", "bodies": [{"mass": 1}, {"mass": 0}]})")), "/bodies/1/mass");
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "a", "bodies": [{"mass": 1, "colour": 3}]})")), "/bodies/0/colour");
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "a", "bodies": []})")), "/bodies");
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "a", "fps": 60.5, "bodies": [{"mass": 1}]})")), "/fps");
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "a", "fps": 0, "bodies": [{"mass": 1}]})")), "/fps");
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "", "bodies": [{"mass": 1}]})")), "/name");
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "a", "bodies": [{"mass": 1, "shape": "cone"}]})")), "/bodies/0/shape");
}

TEST(JsonSchema, OneOfNeedsExactlyOneMatch) {
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "a", "bodies": [{"mass": 1}], "oscillation": 0.5})")), "ok");
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "a", "bodies": [{"mass": 1}], "oscillation": "lots"})")), "/oscillation");
  EXPECT_EQ(pointer_of(json::parse(R"({"name": "a", "bodies": [{"mass": 1}], "oscillation": -1})")), "/oscillation");
}

TEST(JsonSchema, RuleSaysWhatWasExpected) {
  auto e = validate_json_schema(json::parse(R"({"name": "a", "bodies": [{"mass": -1}]})"), kSchema);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->rule, "must be > 0");
}

TEST(JsonSchema, RefCycleDoesNotRecurseForever) {
  const json cyclic = json::parse(R"({"$defs": {"a": {"$ref": "#/$defs/a"}}, "$ref": "#/$defs/a"})");
  auto e = validate_json_schema(json(1), cyclic);
  ASSERT_TRUE(e);
}

// A tagged oneOf (each form fixes "type"): the error is about the form the tag names, at its field.
TEST(JsonSchema, TaggedOneOfReportsTheNamedForm) {
  const json schema = json::parse(R"({"oneOf": [
      {"type": "object", "required": ["type", "width"], "additionalProperties": false,
       "properties": {"type": {"const": "box"}, "width": {"type": "number", "minimum": 0.001}}},
      {"type": "object", "required": ["type", "radius"], "additionalProperties": false,
       "properties": {"type": {"const": "circle"}, "radius": {"type": "number", "minimum": 0.001}}}]})");
  auto e = validate_json_schema(json{{"type", "circle"}, {"radius", -1}}, schema);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->pointer, "/radius");
  EXPECT_EQ(e->rule, "must be >= 0.001");
  e = validate_json_schema(json{{"type", "circle"}, {"width", 1}}, schema);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->pointer, "/radius");
  EXPECT_EQ(e->rule, "is required");
  e = validate_json_schema(json{{"type", "triangle"}}, schema);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->pointer, "/type");
  EXPECT_EQ(e->rule, R"(must be one of "box", "circle")");
}

TEST(JsonSchema, PatternIsAnUnanchoredEcmaRegex) {
  const json schema = json::parse(R"({"type": "string", "pattern": "^[a-z0-9_-]{1,64}$"})");
  EXPECT_FALSE(validate_json_schema("chain_2", schema));
  const auto e = validate_json_schema("../etc", schema);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->rule, R"(must match the pattern "^[a-z0-9_-]{1,64}$")");
  EXPECT_FALSE(validate_json_schema("xx-ab-yy", json::parse(R"({"pattern": "ab"})")));
}

// Without a tag, the form that matched furthest is the one reported.
TEST(JsonSchema, UntaggedOneOfReportsTheDeepestMismatch) {
  const json schema = json::parse(R"({"anyOf": [
      {"type": "array", "items": {"type": "number", "maximum": 10}},
      {"type": "string"}]})");
  const auto e = validate_json_schema(json{1, 2, 30}, schema);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->pointer, "/2");
  EXPECT_EQ(e->rule, "matches none of the allowed forms; closest: must be <= 10");
}

TEST(JsonSchema, ListsKeywordsItWouldNotCheck) {
  using softtune::codec::unsupported_keywords;
  EXPECT_TRUE(unsupported_keywords(kSchema).empty());
  const json typo = json::parse(R"({"type": "object", "description": "fine", "x-note": 1,
      "properties": {"mass": {"type": "number", "minimun": 0}},
      "oneOf": [{"patternProperties": {"^a": true}}]})");
  EXPECT_EQ(unsupported_keywords(typo),
            (std::vector<std::string>{"/properties/mass/minimun", "/oneOf/0/patternProperties"}));
}

// The schemas softtune ships are enforced in full: no keyword in them goes unchecked.
TEST(JsonSchema, ShippedSchemasUseOnlyCheckedKeywords) {
  std::ifstream presets(SOFTTUNE_SOURCE_DIR "/presets/schema.json");
  EXPECT_EQ(softtune::codec::unsupported_keywords(json::parse(presets)), std::vector<std::string>{});
  std::ifstream openapi(SOFTTUNE_SOURCE_DIR "/server/http/openapi.json");
  const json doc = json::parse(openapi);
  for (const auto& [name, schema] : doc["components"]["schemas"].items()) {
    EXPECT_EQ(softtune::codec::unsupported_keywords(schema), std::vector<std::string>{}) << name;
  }
}
