// The handlers' request and response types (http_types.cpp): header names compare case-insensitively
// (RFC 9110 5.1), query values by exact name, JSON and problem responses carry their media types, and
// "application/json" is recognised with parameters and in any case (RFC 9110 8.3.1).
#include "http/http_types.h"

#include <gtest/gtest.h>

#include "codec/problem.h"

using nlohmann::json;
using namespace softtune::http;

TEST(HttpTypes, HeaderNamesAreCaseInsensitive) {
  HttpRequest r;
  r.headers.emplace("Content-Type", "application/json");
  EXPECT_EQ(r.header("content-type"), "application/json");
  EXPECT_EQ(r.header("CONTENT-TYPE"), "application/json");
  EXPECT_FALSE(r.header("Content-Length"));
  CaseInsensitiveLess less;
  EXPECT_FALSE(less("Accept", "aCCEPT"));
  EXPECT_FALSE(less("aCCEPT", "Accept"));
  EXPECT_TRUE(less("Accept", "Host"));
}

TEST(HttpTypes, QueryValuesByExactName) {
  HttpRequest r;
  r.query.emplace("format", "svg");
  EXPECT_EQ(r.query_value("format"), "svg");
  EXPECT_FALSE(r.query_value("Format"));  // query names are case-sensitive
  EXPECT_FALSE(r.query_value("summary"));
}

TEST(HttpTypes, JsonAndProblemResponses) {
  const HttpResponse ok = json_response({{"status", "ok"}}, 201);
  EXPECT_EQ(ok.status, 201);
  EXPECT_EQ(ok.content_type, "application/json");
  EXPECT_EQ(json::parse(ok.body)["status"], "ok");
  const HttpResponse bad = problem_response(softtune::codec::invalid_field("fps", "must be > 0"));
  EXPECT_EQ(bad.status, 422);
  EXPECT_EQ(bad.content_type, "application/problem+json");
  EXPECT_EQ(json::parse(bad.body)["field"], "fps");
}

TEST(HttpTypes, JsonMediaTypeWithParametersAndAnyCase) {
  EXPECT_TRUE(is_json_media_type("application/json"));
  EXPECT_TRUE(is_json_media_type("application/json; charset=utf-8"));
  EXPECT_TRUE(is_json_media_type("Application/JSON"));
  EXPECT_TRUE(is_json_media_type(" application/json ;charset=utf-8"));
  EXPECT_FALSE(is_json_media_type("application/jsonx"));
  EXPECT_FALSE(is_json_media_type("text/json"));
  EXPECT_FALSE(is_json_media_type("application/problem+json"));
  EXPECT_FALSE(is_json_media_type(""));
}
