// What a use case answers (answer.cpp): each format's media type (RFC 8259 JSON, RFC 4180 CSV, SVG's
// image/svg+xml), and a format name taken only from the allowed ones, else a 422 naming the field and
// listing them.
#include "app/answer.h"

#include <gtest/gtest.h>

#include "codec/problem.h"

namespace softtune::app {
namespace {

TEST(Answer, MediaTypes) {
  Answer a;
  EXPECT_EQ(a.content_type(), "application/json");  // json by default
  a.format = Format::csv;
  EXPECT_EQ(a.content_type(), "text/csv");
  a.format = Format::svg;
  EXPECT_EQ(a.content_type(), "image/svg+xml");
}

TEST(Answer, FormatNamedFromTheAllowedOnes) {
  EXPECT_EQ(format_named("svg", {Format::json, Format::csv, Format::svg}, "format"), Format::svg);
  EXPECT_EQ(format_named("json", {Format::json, Format::svg}, "--format"), Format::json);
  try {
    format_named("csv", {Format::json, Format::svg}, "--format");  // known, but not allowed here
    FAIL();
  } catch (const codec::Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "--format");
    EXPECT_EQ(p.detail, "must be json or svg");
  }
  try {
    format_named("XML", {Format::json, Format::csv, Format::svg}, "format");
    FAIL();
  } catch (const codec::Problem& p) {
    EXPECT_EQ(p.detail, "must be json, csv or svg");
  }
}

}  // namespace
}  // namespace softtune::app
