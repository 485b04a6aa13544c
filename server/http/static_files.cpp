#include "http/static_files.h"

#include <cstdint>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sys/stat.h>
#include <iterator>
#include <system_error>

#include "codec/problem.h"
#include "http/conditional.h"

namespace softtune::http {
namespace {

namespace fs = std::filesystem;

codec::Problem bad_path(const std::string& rule) { return codec::Problem(400, "Bad path", "path", rule); }

codec::Problem not_found(std::string_view path) {
  return codec::Problem(404, "Not found", "path", "no such file: \"" + std::string(path) + "\"");
}

bool plain_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
}

// True when `inner` is `root` or lies below it (both canonical).
bool inside(const fs::path& root, const fs::path& inner) {
  auto r = root.begin(), i = inner.begin();
  for (; r != root.end(); ++r, ++i) {
    if (i == inner.end() || *r != *i) return false;
  }
  return true;
}

}  // namespace

std::string content_type_for(std::string_view file_name) {
  struct Entry {
    std::string_view ext, type;
  };
  static constexpr Entry kTypes[] = {
      {".html", "text/html; charset=utf-8"}, {".htm", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"}, {".mjs", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"}, {".json", "application/json"}, {".svg", "image/svg+xml"},
      {".png", "image/png"}, {".ico", "image/x-icon"}, {".txt", "text/plain; charset=utf-8"},
      {".csv", "text/csv; charset=utf-8"}, {".wasm", "application/wasm"}, {".map", "application/json"},
      {".woff2", "font/woff2"},
  };
  const std::size_t dot = file_name.rfind('.');
  if (dot != std::string_view::npos) {
    const std::string_view ext = file_name.substr(dot);
    for (const Entry& e : kTypes) {
      if (e.ext == ext) return std::string(e.type);
    }
  }
  return "application/octet-stream";
}

fs::path resolve_static_path(const fs::path& web_root, std::string_view path) {
  if (path.empty() || path.front() != '/') throw bad_path("must start with /");
  fs::path relative;
  std::size_t start = 1;
  while (start <= path.size()) {
    std::size_t end = path.find('/', start);
    if (end == std::string_view::npos) end = path.size();
    const std::string_view segment = path.substr(start, end - start);
    start = end + 1;
    if (segment.empty()) {
      if (end == path.size()) break;  // a trailing slash names the directory
      throw bad_path("empty path segments (//) are not allowed");
    }
    for (char c : segment) {
      if (!plain_char(c)) throw bad_path("path segments may hold only letters, digits, '.', '_' and '-'");
    }
    if (segment.front() == '.') throw bad_path("path segments may not start with '.' (no .., no hidden files)");
    relative /= std::string(segment);
  }
  std::error_code ec;
  const fs::path root = fs::canonical(web_root, ec);
  if (ec) throw not_found(path);
  fs::path file = fs::weakly_canonical(root / relative, ec);
  if (ec || !inside(root, file)) throw not_found(path);
  if (fs::is_directory(file, ec)) file /= "index.html";
  file = fs::canonical(file, ec);
  if (ec || !inside(root, file) || !fs::is_regular_file(file, ec)) throw not_found(path);
  return file;
}

// FNV-1a, 64 bits (Fowler, Noll, Vo): offset basis 14695981039346656037, prime 1099511628211.
std::string static_etag(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  char buf[24];
  std::snprintf(buf, sizeof buf, "\"%016llx\"", static_cast<unsigned long long>(h));
  return buf;
}

std::string http_date(long long unix_seconds) {
  const std::time_t t = static_cast<std::time_t>(unix_seconds);
  std::tm tm{};
  ::gmtime_r(&t, &tm);
  static constexpr const char* kDays[] = {"Sun", "Mon", "Tue", "Wed", "Thu", "Fri", "Sat"};
  static constexpr const char* kMonths[] = {"Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                            "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
  char buf[40];
  std::snprintf(buf, sizeof buf, "%s, %02d %s %04d %02d:%02d:%02d GMT", kDays[tm.tm_wday], tm.tm_mday, kMonths[tm.tm_mon],
                tm.tm_year + 1900, tm.tm_hour, tm.tm_min, tm.tm_sec);
  return buf;
}

HttpResponse serve_static(const fs::path& web_root, std::string_view path, const std::optional<std::string>& tags) {
  const fs::path file = resolve_static_path(web_root, path);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw not_found(path);
  std::string bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>{});
  HttpResponse r;
  const std::string etag = static_etag(bytes);
  r.headers.emplace_back("ETag", etag);
  struct stat st {};
  if (::stat(file.c_str(), &st) == 0) r.headers.emplace_back("Last-Modified", http_date(st.st_mtime));
  r.headers.emplace_back("Cache-Control", "no-cache");
  r.headers.emplace_back("X-Content-Type-Options", "nosniff");
  if (tags && if_none_match(*tags, etag)) {
    r.status = 304;
    r.content_type.clear();
    return r;
  }
  r.content_type = content_type_for(file.filename().string());
  r.body = std::move(bytes);
  return r;
}

}  // namespace softtune::http
