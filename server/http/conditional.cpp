#include "http/conditional.h"

namespace softtune::http {
namespace {

std::string_view opaque(std::string_view tag) {
  if (tag.starts_with("W/")) tag.remove_prefix(2);
  return tag;
}

bool space(char c) { return c == ' ' || c == '\t'; }

}  // namespace

bool if_none_match(std::string_view header, std::string_view etag) {
  std::size_t i = 0;
  while (i < header.size() && space(header[i])) ++i;
  std::string_view rest = header.substr(i);
  while (!rest.empty() && space(rest.back())) rest.remove_suffix(1);
  if (rest == "*") return true;
  const std::string_view want = opaque(etag);
  // entity-tag = [ "W/" ] DQUOTE *etagc DQUOTE, in a comma-separated list (empty elements allowed).
  std::size_t p = 0;
  while (p < rest.size()) {
    while (p < rest.size() && (space(rest[p]) || rest[p] == ',')) ++p;
    if (p >= rest.size()) break;
    const std::size_t start = p;
    if (rest.substr(p, 2) == "W/") p += 2;
    if (p >= rest.size() || rest[p] != '"') return false;
    const std::size_t close = rest.find('"', p + 1);
    if (close == std::string_view::npos) return false;
    if (opaque(rest.substr(start, close + 1 - start)) == want) return true;
    p = close + 1;
  }
  return false;
}

}  // namespace softtune::http
