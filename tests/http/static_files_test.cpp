#include "http/static_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "codec/problem.h"

namespace fs = std::filesystem;
using softtune::http::content_type_for;
using softtune::http::resolve_static_path;
using softtune::http::serve_static;

namespace {

// A web root with a page, a sub-folder, a hidden file, and a symlink pointing outside the root.
class StaticFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    base_ = fs::temp_directory_path() / ("softtune_static_" + std::to_string(::getpid()));
    fs::remove_all(base_);
    root_ = base_ / "web";
    fs::create_directories(root_ / "css");
    write(root_ / "index.html", "<p>page</p>");
    write(root_ / "css" / "site.css", "p{}");
    write(root_ / ".secret", "hidden");
    write(base_ / "outside.txt", "outside");
    fs::create_symlink(base_ / "outside.txt", root_ / "escape.txt");
  }
  void TearDown() override { fs::remove_all(base_); }
  static void write(const fs::path& p, const std::string& s) { std::ofstream(p) << s; }

  int status_of(std::string_view path) const {
    try {
      resolve_static_path(root_, path);
      return 200;
    } catch (const softtune::codec::Problem& p) {
      EXPECT_EQ(p.field, "path");
      return p.status;
    }
  }

  fs::path base_, root_;
};

}  // namespace

TEST_F(StaticFiles, ServesFilesAndIndexes) {
  EXPECT_EQ(resolve_static_path(root_, "/"), fs::canonical(root_ / "index.html"));
  EXPECT_EQ(resolve_static_path(root_, "/css/site.css"), fs::canonical(root_ / "css" / "site.css"));
  const auto page = serve_static(root_, "/index.html");
  EXPECT_EQ(page.status, 200);
  EXPECT_EQ(page.body, "<p>page</p>");
  EXPECT_EQ(page.content_type, "text/html; charset=utf-8");
}

TEST_F(StaticFiles, RefusesPathTricks) {
  // The transport hands over percent-decoded paths: %2e%2e is "..", ..%2f is "../", %00 is a NUL byte.
  EXPECT_EQ(status_of("/../outside.txt"), 400);
  EXPECT_EQ(status_of("/css/../../outside.txt"), 400);
  EXPECT_EQ(status_of(std::string("/index.html\0.png", 16)), 400);
  EXPECT_EQ(status_of("/..\\outside.txt"), 400);
  EXPECT_EQ(status_of("/.secret"), 400);
  EXPECT_EQ(status_of("/css//site.css"), 400);
  EXPECT_EQ(status_of("/index html"), 400);
  EXPECT_EQ(status_of("relative.html"), 400);
}

TEST_F(StaticFiles, SymlinksOutOfTheRootAndMissingFilesAreNotFound) {
  EXPECT_EQ(status_of("/escape.txt"), 404);
  EXPECT_EQ(status_of("/missing.html"), 404);
  EXPECT_EQ(status_of("/css"), 404);  // a folder without index.html
  EXPECT_EQ(status_of("/index.html/x"), 404);
}

TEST(StaticContentTypes, ByExtension) {
  EXPECT_EQ(content_type_for("app.js"), "text/javascript; charset=utf-8");
  EXPECT_EQ(content_type_for("site.css"), "text/css; charset=utf-8");
  EXPECT_EQ(content_type_for("plot.svg"), "image/svg+xml");
  EXPECT_EQ(content_type_for("frame.png"), "image/png");
  EXPECT_EQ(content_type_for("data.json"), "application/json");
  EXPECT_EQ(content_type_for("archive.tar.gz"), "application/octet-stream");
  EXPECT_EQ(content_type_for("README"), "application/octet-stream");
}

// The validators against their definitions: FNV-1a 64's published vectors ("" is the offset basis, "a"
// is 0xaf63dc4c8601ec8c) and RFC 9110 5.6.7's own example date.
TEST(StaticValidators, EtagIsTheFnv1aHashAndDatesAreImfFixdate) {
  EXPECT_EQ(softtune::http::static_etag(""), "\"cbf29ce484222325\"");
  EXPECT_EQ(softtune::http::static_etag("a"), "\"af63dc4c8601ec8c\"");
  EXPECT_EQ(softtune::http::http_date(784111777), "Sun, 06 Nov 1994 08:49:37 GMT");
}
