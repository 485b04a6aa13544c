// limits_table: writes or checks the limits table of a Markdown page (docs/limits-and-security.md), the
// lines between `<!-- limits:begin -->` and `<!-- limits:end -->`, from the limits registry.
//   limits_table --write FILE   replaces the table (cmake --build build --target limits_doc)
//   limits_table --check FILE   exit 1, naming the first line that differs, when the page has drifted
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "http/limits_registry.h"

namespace {

constexpr std::string_view kBegin = "<!-- limits:begin -->\n";
constexpr std::string_view kEnd = "<!-- limits:end -->";

int fail(const std::string& message) {
  std::cerr << "limits_table: " << message << "\n";
  return 2;
}

// The first differing line of two texts, for a message a person can act on.
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream x(a), y(b);
  std::string lx, ly;
  for (int line = 1;; ++line) {
    const bool more_x = static_cast<bool>(std::getline(x, lx));
    const bool more_y = static_cast<bool>(std::getline(y, ly));
    if (!more_x && !more_y) return "no line differs";
    if (!more_x || !more_y || lx != ly) {
      return "table line " + std::to_string(line) + ":\n  page:     " + (more_x ? lx : "(none)") +
             "\n  registry: " + (more_y ? ly : "(none)");
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 || (std::string(argv[1]) != "--write" && std::string(argv[1]) != "--check")) {
    return fail("usage: limits_table --write|--check FILE");
  }
  const std::string mode = argv[1], path = argv[2];
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot read " + path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string page = buffer.str();
  const auto begin = page.find(kBegin);
  const auto end = page.find(kEnd);
  if (begin == std::string::npos || end == std::string::npos || end < begin) {
    return fail(path + " has no `<!-- limits:begin -->` ... `<!-- limits:end -->` block");
  }
  const auto from = begin + kBegin.size();
  const std::string written = page.substr(from, end - from);
  const std::string wanted = softtune::http::limits_table_markdown();
  if (mode == "--check") {
    if (written == wanted) return 0;
    std::cerr << "limits_table: " << path << " has drifted from the limits registry (server/http/limits_registry.cpp); "
              << "run `cmake --build build --target limits_doc`. First difference, " << first_difference(written, wanted)
              << "\n";
    return 1;
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << page.substr(0, from) << wanted << page.substr(end);
  return out ? 0 : fail("cannot write " + path);
}
