#include "codec/json_schema.h"

#include <gtest/gtest.h>

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
