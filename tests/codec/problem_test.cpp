// Request problems (problem.cpp) as RFC 9457 problem details: a 422 for a field, a 400 for the body, the
// type derived from the title, and text that stays valid UTF-8 so the problem itself always serializes.
#include "codec/problem.h"

#include <gtest/gtest.h>

using nlohmann::json;
using namespace softtune::codec;

TEST(Problem, InvalidFieldIsA422NamingFieldAndRule) {
  const Problem p = invalid_field("constraint.body_b.mass", "must be > 0");
  EXPECT_EQ(p.status, 422);
  EXPECT_EQ(p.title, "Invalid field");
  EXPECT_EQ(p.field, "constraint.body_b.mass");
  EXPECT_EQ(p.detail, "must be > 0");
  EXPECT_STREQ(p.what(), "constraint.body_b.mass: must be > 0");
}

TEST(Problem, MalformedJsonIsA400AboutTheBody) {
  const Problem p = malformed_json("unexpected end of input");
  EXPECT_EQ(p.status, 400);
  EXPECT_EQ(p.field, "");
  EXPECT_STREQ(p.what(), "unexpected end of input");
}

TEST(Problem, JsonHasTheFiveMembersAndATypeFromTheTitle) {
  const json j = problem_json(invalid_field("fps", "must be in [1, 10000]"));
  EXPECT_EQ(j.size(), 5u);
  EXPECT_EQ(j["type"], "/problems/invalid-field");
  EXPECT_EQ(j["title"], "Invalid field");
  EXPECT_EQ(j["status"], 422);
  EXPECT_EQ(j["field"], "fps");
  EXPECT_EQ(j["detail"], "must be in [1, 10000]");
  EXPECT_EQ(problem_json(Problem(413, "Payload Too Large", "", "over 1 MiB"))["type"], "/problems/payload-too-large");
}

TEST(Problem, BytesThatAreNotUtf8BecomeTheReplacementCharacter) {
  const Problem p(400, "Malformed JSON", "na\xffme", "bad \xc3\x28 byte");
  EXPECT_EQ(p.field, "na\xef\xbf\xbdme");  // U+FFFD
  EXPECT_EQ(p.detail.find('\xff'), std::string::npos);
  EXPECT_NO_THROW(problem_json(p).dump());
  // Valid UTF-8 passes unchanged.
  EXPECT_EQ(Problem(422, "Invalid field", "gr\xc3\xb6\xc3\x9f" "e", "x").field, "gr\xc3\xb6\xc3\x9f" "e");
}
