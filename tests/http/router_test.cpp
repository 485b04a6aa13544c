#include "http/router.h"

#include <gtest/gtest.h>

using softtune::http::is_rest_pattern;
using softtune::http::match_route;

TEST(Router, LiteralPatternsMatchExactly) {
  EXPECT_TRUE(match_route("/api/v1/health", "/api/v1/health"));
  EXPECT_FALSE(match_route("/api/v1/health", "/api/v1/health/"));
  EXPECT_FALSE(match_route("/api/v1/health", "/api/v1/healthz"));
  EXPECT_FALSE(match_route("/api/v1/health", "/api/v1"));
  EXPECT_TRUE(match_route("/", "/"));
}

TEST(Router, CapturesNamedSegments) {
  auto m = match_route("/api/v1/presets/{name}", "/api/v1/presets/bridge");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->at("name"), "bridge");
  EXPECT_FALSE(match_route("/api/v1/presets/{name}", "/api/v1/presets/"));
  EXPECT_FALSE(match_route("/api/v1/presets/{name}", "/api/v1/presets/a/b"));
}

TEST(Router, CapturesWithALiteralSuffix) {
  auto m = match_route("/api/v1/preview/{id}/{n}.png", "/api/v1/preview/ab12/7.png");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->at("id"), "ab12");
  EXPECT_EQ(m->at("n"), "7");
  EXPECT_FALSE(match_route("/api/v1/preview/{id}/{n}.png", "/api/v1/preview/ab12/7.jpg"));
  EXPECT_FALSE(match_route("/api/v1/preview/{id}/{n}.png", "/api/v1/preview/ab12/.png"));
}

TEST(Router, RestPatternTakesTheRemainder) {
  EXPECT_TRUE(is_rest_pattern("/{path...}"));
  EXPECT_FALSE(is_rest_pattern("/api/{name}"));
  auto m = match_route("/{path...}", "/css/site.css");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->at("path"), "css/site.css");
  EXPECT_EQ(match_route("/{path...}", "/")->at("path"), "");
  EXPECT_FALSE(match_route("/{path...}", "relative"));
}
