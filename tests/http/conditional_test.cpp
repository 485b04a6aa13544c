#include "http/conditional.h"

#include <gtest/gtest.h>

using softtune::http::if_none_match;

// RFC 9110 13.1.2: "*" matches any representation; a list matches when any member does; the comparison
// is weak (W/ ignored on both sides).
TEST(Conditional, IfNoneMatchFollowsRfc9110) {
  const char* tag = "\"ID-0\"";
  EXPECT_TRUE(if_none_match("\"ID-0\"", tag));
  EXPECT_TRUE(if_none_match("*", tag));
  EXPECT_TRUE(if_none_match(" * ", tag));
  EXPECT_TRUE(if_none_match("W/\"ID-0\"", tag));
  EXPECT_TRUE(if_none_match("\"x\", \"ID-0\"", tag));
  EXPECT_TRUE(if_none_match("\"x\",W/\"ID-0\" ,", tag));
  EXPECT_TRUE(if_none_match("\"ID-0\"", "W/\"ID-0\""));
  EXPECT_FALSE(if_none_match("\"ID-1\"", tag));
  EXPECT_FALSE(if_none_match("\"x\", \"y\"", tag));
  EXPECT_FALSE(if_none_match("ID-0", tag));         // not a quoted tag
  EXPECT_FALSE(if_none_match("\"ID-0", tag));       // unterminated
  EXPECT_FALSE(if_none_match("", tag));
  EXPECT_FALSE(if_none_match("*, \"x\"", tag));     // "*" only alone
}
