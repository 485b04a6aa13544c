#pragma once
// Text and attribute values in XML (the plots' SVG, MuJoCo's MJCF): &, <, > and " as entities, the rest as is.

#include <string>
#include <string_view>

namespace softtune::support {

inline std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace softtune::support
