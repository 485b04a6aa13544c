#include "codec/json_schema.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <regex>
#include <string_view>

namespace softtune::codec {
namespace {

using nlohmann::json;

bool has_type(const json& v, const std::string& type) {
  if (type == "object") return v.is_object();
  if (type == "array") return v.is_array();
  if (type == "string") return v.is_string();
  if (type == "boolean") return v.is_boolean();
  if (type == "null") return v.is_null();
  if (type == "number") return v.is_number();
  if (type == "integer") {
    if (v.is_number_integer()) return true;
    if (!v.is_number_float()) return false;
    const double d = v.get<double>();
    return std::isfinite(d) && d == std::floor(d);
  }
  return false;
}

std::string escape_pointer(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

class Validator {
 public:
  explicit Validator(const json& root) : root_(root) {}

  std::optional<SchemaError> check(const json& v, const json& s, const std::string& at, int depth) const {
    if (depth > 64) return SchemaError{at, "schema nesting too deep (a $ref cycle?)"};
    if (s.is_boolean()) {
      if (s.get<bool>()) return std::nullopt;
      return SchemaError{at, "no value is allowed here"};
    }
    if (!s.is_object()) return std::nullopt;
    if (auto it = s.find("$ref"); it != s.end()) {
      const std::string ref = it->get<std::string>();
      if (ref.rfind("#", 0) != 0) return SchemaError{at, "unsupported $ref " + ref};
      const json::json_pointer p(ref.substr(1));
      if (!root_.contains(p)) return SchemaError{at, "unresolved $ref " + ref};
      if (auto e = check(v, root_.at(p), at, depth + 1)) return e;
    }
    if (auto e = check_type(v, s, at)) return e;
    if (auto e = check_value(v, s, at)) return e;
    if (v.is_object()) {
      if (auto e = check_object(v, s, at, depth)) return e;
    }
    if (v.is_array()) {
      if (auto e = check_array(v, s, at, depth)) return e;
    }
    return check_combinators(v, s, at, depth);
  }

 private:
  std::optional<SchemaError> check_type(const json& v, const json& s, const std::string& at) const {
    auto it = s.find("type");
    if (it == s.end()) return std::nullopt;
    if (it->is_string()) {
      if (has_type(v, *it)) return std::nullopt;
      return SchemaError{at, "must be of type " + it->get<std::string>()};
    }
    std::string names;
    for (const auto& t : *it) {
      if (has_type(v, t)) return std::nullopt;
      names += (names.empty() ? "" : " or ") + t.get<std::string>();
    }
    return SchemaError{at, "must be of type " + names};
  }

  std::optional<SchemaError> check_value(const json& v, const json& s, const std::string& at) const {
    if (auto it = s.find("const"); it != s.end() && v != *it) return SchemaError{at, "must equal " + it->dump()};
    if (auto it = s.find("enum"); it != s.end()) {
      bool found = false;
      for (const auto& e : *it) found = found || e == v;
      if (!found) return SchemaError{at, "must be one of " + it->dump()};
    }
    if (v.is_number()) {
      const double d = v.get<double>();
      if (auto it = s.find("minimum"); it != s.end() && !(d >= it->get<double>()))
        return SchemaError{at, "must be >= " + it->dump()};
      if (auto it = s.find("maximum"); it != s.end() && !(d <= it->get<double>()))
        return SchemaError{at, "must be <= " + it->dump()};
      if (auto it = s.find("exclusiveMinimum"); it != s.end() && !(d > it->get<double>()))
        return SchemaError{at, "must be > " + it->dump()};
      if (auto it = s.find("exclusiveMaximum"); it != s.end() && !(d < it->get<double>()))
        return SchemaError{at, "must be < " + it->dump()};
    }
    if (v.is_string()) {
      const auto n = v.get_ref<const std::string&>().size();
      if (auto it = s.find("minLength"); it != s.end() && n < it->get<std::size_t>())
        return SchemaError{at, "must have at least " + it->dump() + " characters"};
      if (auto it = s.find("maxLength"); it != s.end() && n > it->get<std::size_t>())
        return SchemaError{at, "must have at most " + it->dump() + " characters"};
      // JSON Schema patterns are ECMA-262 regular expressions, unanchored: std::regex's default grammar.
      if (auto it = s.find("pattern"); it != s.end() &&
                                        !std::regex_search(v.get_ref<const std::string&>(), std::regex(it->get<std::string>())))
        return SchemaError{at, "must match the pattern " + it->dump()};
    }
    return std::nullopt;
  }

  std::optional<SchemaError> check_object(const json& v, const json& s, const std::string& at, int depth) const {
    if (auto it = s.find("required"); it != s.end()) {
      for (const auto& key : *it) {
        if (!v.contains(key.get<std::string>()))
          return SchemaError{at + "/" + escape_pointer(key), "is required"};
      }
    }
    const auto props = s.find("properties");
    const auto additional = s.find("additionalProperties");
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string child = at + "/" + escape_pointer(it.key());
      if (props != s.end() && props->contains(it.key())) {
        if (auto e = check(it.value(), props->at(it.key()), child, depth + 1)) return e;
      } else if (additional != s.end()) {
        if (additional->is_boolean() && !additional->get<bool>()) return SchemaError{child, "is not an allowed property"};
        if (auto e = check(it.value(), *additional, child, depth + 1)) return e;
      }
    }
    return std::nullopt;
  }

  std::optional<SchemaError> check_array(const json& v, const json& s, const std::string& at, int depth) const {
    if (auto it = s.find("minItems"); it != s.end() && v.size() < it->get<std::size_t>())
      return SchemaError{at, "must have at least " + it->dump() + " items"};
    if (auto it = s.find("maxItems"); it != s.end() && v.size() > it->get<std::size_t>())
      return SchemaError{at, "must have at most " + it->dump() + " items"};
    if (auto it = s.find("items"); it != s.end()) {
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (auto e = check(v[i], *it, at + "/" + std::to_string(i), depth + 1)) return e;
      }
    }
    return std::nullopt;
  }

  std::optional<SchemaError> check_combinators(const json& v, const json& s, const std::string& at, int depth) const {
    if (auto it = s.find("allOf"); it != s.end()) {
      for (const auto& sub : *it) {
        if (auto e = check(v, sub, at, depth + 1)) return e;
      }
    }
    if (auto it = s.find("anyOf"); it != s.end()) {
      for (const auto& sub : *it) {
        if (!check(v, sub, at, depth + 1)) return std::nullopt;
      }
      return closest_mismatch(v, *it, at, depth);
    }
    if (auto it = s.find("oneOf"); it != s.end()) {
      int matches = 0;
      for (const auto& sub : *it) matches += check(v, sub, at, depth + 1) ? 0 : 1;
      if (matches == 1) return std::nullopt;
      if (matches == 0) return closest_mismatch(v, *it, at, depth);
      return SchemaError{at, "must match exactly one allowed form; " + std::to_string(matches) + " matched"};
    }
    return std::nullopt;
  }

  // Why `v` matches none of `forms`, said about the form the author meant. When every form fixes a
  // "type" member to a constant (box, circle, polygon), that member picks the form, and an unknown one
  // is the error; otherwise the form that got furthest (the deepest mismatch) is the one reported.
  std::optional<SchemaError> closest_mismatch(const json& v, const json& forms, const std::string& at, int depth) const {
    if (v.is_object() && v.contains("type") && v["type"].is_string()) {
      std::string names;
      const json* chosen = nullptr;
      for (const auto& form : forms) {
        const json* tag = form.is_object() ? tag_of(form) : nullptr;
        if (!tag) {
          names.clear();
          break;
        }
        names += (names.empty() ? "" : ", ") + tag->dump();
        if (*tag == v["type"]) chosen = &form;
      }
      if (!names.empty()) {
        if (!chosen) return SchemaError{at + "/type", "must be one of " + names};
        return check(v, *chosen, at, depth + 1);
      }
    }
    std::optional<SchemaError> deepest;
    for (const auto& form : forms) {
      auto e = check(v, form, at, depth + 1);
      if (e && (!deepest || e->pointer.size() > deepest->pointer.size())) deepest = e;
    }
    if (!deepest) return SchemaError{at, "matches none of the allowed forms"};
    return SchemaError{deepest->pointer, "matches none of the allowed forms; closest: " + deepest->rule};
  }

  static const json* tag_of(const json& form) {
    const auto props = form.find("properties");
    if (props == form.end() || !props->is_object()) return nullptr;
    const auto type = props->find("type");
    if (type == props->end() || !type->is_object()) return nullptr;
    const auto tag = type->find("const");
    return tag == type->end() ? nullptr : &*tag;
  }

  const json& root_;
};

// Keywords the validator checks, and those that only annotate (JSON Schema 2020-12, OpenAPI 3.1).
constexpr std::array<std::string_view, 22> kChecked = {
    "type", "enum", "const", "properties", "required", "additionalProperties", "items", "minItems", "maxItems",
    "minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum", "minLength", "maxLength", "pattern", "$ref", "oneOf",
    "anyOf", "allOf", "$defs", "$schema"};
constexpr std::array<std::string_view, 11> kAnnotations = {
    "description", "title", "examples", "example", "default", "$comment", "format", "$id", "deprecated",
    "readOnly", "writeOnly"};

void collect_unsupported(const json& s, const std::string& at, std::vector<std::string>& out) {
  if (!s.is_object()) return;
  for (auto it = s.begin(); it != s.end(); ++it) {
    const std::string& key = it.key();
    const bool known = std::find(kChecked.begin(), kChecked.end(), key) != kChecked.end() ||
                       std::find(kAnnotations.begin(), kAnnotations.end(), key) != kAnnotations.end() ||
                       key.rfind("x-", 0) == 0;
    if (!known) out.push_back(at + "/" + escape_pointer(key));
  }
  for (const char* map : {"properties", "$defs"}) {
    if (auto it = s.find(map); it != s.end() && it->is_object()) {
      for (auto sub = it->begin(); sub != it->end(); ++sub) {
        collect_unsupported(sub.value(), at + "/" + map + "/" + escape_pointer(sub.key()), out);
      }
    }
  }
  for (const char* one : {"items", "additionalProperties"}) {
    if (auto it = s.find(one); it != s.end()) collect_unsupported(*it, at + "/" + one, out);
  }
  for (const char* list : {"oneOf", "anyOf", "allOf"}) {
    if (auto it = s.find(list); it != s.end() && it->is_array()) {
      for (std::size_t i = 0; i < it->size(); ++i) collect_unsupported((*it)[i], at + "/" + list + "/" + std::to_string(i), out);
    }
  }
}

}  // namespace

std::vector<std::string> unsupported_keywords(const json& schema) {
  std::vector<std::string> out;
  collect_unsupported(schema, "", out);
  return out;
}

std::optional<SchemaError> validate_json_schema(const json& instance, const json& schema) {
  return validate_json_schema(instance, schema, schema);
}

std::optional<SchemaError> validate_json_schema(const json& instance, const json& schema, const json& root) {
  return Validator(root).check(instance, schema, "", 0);
}

}  // namespace softtune::codec
