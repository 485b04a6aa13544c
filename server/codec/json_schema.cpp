#include "codec/json_schema.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace softtune::codec {
namespace {

using nlohmann::json;

// RFC 6901: "~" -> "~0", "/" -> "~1".
std::string escape(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string number_text(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  return json(v).dump();
}

bool has_type(const json& v, const std::string& type) {
  if (type == "object") return v.is_object();
  if (type == "array") return v.is_array();
  if (type == "string") return v.is_string();
  if (type == "boolean") return v.is_boolean();
  if (type == "null") return v.is_null();
  if (type == "number") return v.is_number();
  if (type == "integer") {
    if (v.is_number_integer()) return true;
    return v.is_number_float() && std::isfinite(v.get<double>()) && v.get<double>() == std::floor(v.get<double>());
  }
  throw std::invalid_argument("schema: unknown type \"" + type + "\"");
}

// The rule text of a failed "const": oneOf uses it to recognise a discriminator ("type": "box") that says the
// instance was not meant for that alternative.
constexpr std::string_view kConstRule = "must be exactly ";

const std::set<std::string, std::less<>> kAnnotations = {"$schema", "$id", "$defs", "title", "description", "default", "examples", "$comment"};
const std::set<std::string, std::less<>> kKeywords = {"type", "properties", "required", "additionalProperties", "items", "enum", "const",
                                                      "minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum", "minItems", "maxItems",
                                                      "minLength", "maxLength", "$ref", "oneOf", "anyOf"};

class Validator {
 public:
  explicit Validator(const json& root) : root_(root) {}

  std::optional<SchemaError> check(const json& v, const json& s, const std::string& ptr, int depth = 0) const {
    if (depth > 64) throw std::invalid_argument("schema: $ref nesting deeper than 64");
    if (s.is_boolean()) {
      if (s.get<bool>()) return std::nullopt;
      return SchemaError{ptr, "is not allowed here"};
    }
    if (!s.is_object()) throw std::invalid_argument("schema: a schema must be an object or a boolean");
    for (auto it = s.begin(); it != s.end(); ++it) {
      if (!kKeywords.contains(it.key()) && !kAnnotations.contains(it.key()))
        throw std::invalid_argument("schema: unsupported keyword \"" + it.key() + "\"");
    }
    if (auto r = s.find("$ref"); r != s.end()) {
      if (auto e = check(v, resolve(r->get<std::string>()), ptr, depth + 1)) return e;
    }
    if (auto t = s.find("type"); t != s.end()) {
      bool ok = false;
      std::string names;
      for (const json& name : t->is_array() ? *t : json::array({*t})) {
        ok = ok || has_type(v, name.get<std::string>());
        names += (names.empty() ? "" : " or ") + name.get<std::string>();
      }
      if (!ok) return SchemaError{ptr, "must be of type " + names};
    }
    if (auto e = s.find("enum"); e != s.end()) {
      bool ok = false;
      std::string names;
      for (const json& option : *e) {
        ok = ok || option == v;
        names += (names.empty() ? "" : ", ") + option.dump();
      }
      if (!ok) return SchemaError{ptr, "must be one of " + names};
    }
    if (auto c = s.find("const"); c != s.end() && *c != v) return SchemaError{ptr, std::string(kConstRule) + c->dump()};
    if (v.is_number()) {
      if (auto e = check_number(v.get<double>(), s, ptr)) return e;
    }
    if (v.is_string()) {
      const auto length = static_cast<double>(v.get_ref<const std::string&>().size());
      if (auto m = s.find("minLength"); m != s.end() && length < m->get<double>())
        return SchemaError{ptr, "must have at least " + number_text(m->get<double>()) + " characters"};
      if (auto m = s.find("maxLength"); m != s.end() && length > m->get<double>())
        return SchemaError{ptr, "must have at most " + number_text(m->get<double>()) + " characters"};
    }
    if (v.is_array()) {
      if (auto e = check_array(v, s, ptr, depth)) return e;
    }
    if (v.is_object()) {
      if (auto e = check_object(v, s, ptr, depth)) return e;
    }
    if (auto one = s.find("oneOf"); one != s.end()) {
      if (auto e = check_one_of(v, *one, ptr, depth)) return e;
    }
    if (auto any = s.find("anyOf"); any != s.end()) {
      std::optional<SchemaError> best;
      for (const json& option : *any) {
        auto e = check(v, option, ptr, depth + 1);
        if (!e) return std::nullopt;
        if (!best) best = e;
      }
      return best;
    }
    return std::nullopt;
  }

 private:
  const json& resolve(const std::string& ref) const {
    const std::string prefix = "#/$defs/";
    if (ref.rfind(prefix, 0) != 0) throw std::invalid_argument("schema: only \"#/$defs/NAME\" references are supported: " + ref);
    const auto defs = root_.find("$defs");
    if (defs == root_.end() || !defs->contains(ref.substr(prefix.size())))
      throw std::invalid_argument("schema: unresolved reference " + ref);
    return (*defs)[ref.substr(prefix.size())];
  }

  static std::optional<SchemaError> check_number(double d, const json& s, const std::string& ptr) {
    if (auto m = s.find("minimum"); m != s.end() && !(d >= m->get<double>()))
      return SchemaError{ptr, "must be >= " + number_text(m->get<double>())};
    if (auto m = s.find("maximum"); m != s.end() && !(d <= m->get<double>()))
      return SchemaError{ptr, "must be <= " + number_text(m->get<double>())};
    if (auto m = s.find("exclusiveMinimum"); m != s.end() && !(d > m->get<double>()))
      return SchemaError{ptr, "must be > " + number_text(m->get<double>())};
    if (auto m = s.find("exclusiveMaximum"); m != s.end() && !(d < m->get<double>()))
      return SchemaError{ptr, "must be < " + number_text(m->get<double>())};
    return std::nullopt;
  }

  std::optional<SchemaError> check_array(const json& v, const json& s, const std::string& ptr, int depth) const {
    const auto n = static_cast<double>(v.size());
    if (auto m = s.find("minItems"); m != s.end() && n < m->get<double>())
      return SchemaError{ptr, "must have at least " + number_text(m->get<double>()) + " items"};
    if (auto m = s.find("maxItems"); m != s.end() && n > m->get<double>())
      return SchemaError{ptr, "must have at most " + number_text(m->get<double>()) + " items"};
    if (auto items = s.find("items"); items != s.end()) {
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (auto e = check(v[i], *items, ptr + "/" + std::to_string(i), depth + 1)) return e;
      }
    }
    return std::nullopt;
  }

  // Declared properties first (a wrong discriminator shows before anything else), then unknown fields, then
  // missing required ones.
  std::optional<SchemaError> check_object(const json& v, const json& s, const std::string& ptr, int depth) const {
    const auto props = s.find("properties");
    const auto additional = s.find("additionalProperties");
    for (auto it = v.begin(); it != v.end(); ++it) {
      if (props != s.end() && props->contains(it.key())) {
        if (auto e = check(it.value(), (*props)[it.key()], ptr + "/" + escape(it.key()), depth + 1)) return e;
      }
    }
    for (auto it = v.begin(); it != v.end(); ++it) {
      if ((props != s.end() && props->contains(it.key())) || additional == s.end()) continue;
      const std::string child = ptr + "/" + escape(it.key());
      if (additional->is_boolean() && !additional->get<bool>()) return SchemaError{child, "is not a known field"};
      if (auto e = check(it.value(), *additional, child, depth + 1)) return e;
    }
    if (auto req = s.find("required"); req != s.end()) {
      for (const json& name : *req) {
        if (!v.contains(name.get<std::string>()))
          return SchemaError{ptr + "/" + escape(name.get<std::string>()), "is required"};
      }
    }
    return std::nullopt;
  }

  // Exactly one branch must match. When none does, report the alternative the instance was most likely meant
  // for: one whose discriminator (a "const") matched, then the error deepest in the instance, then the first.
  std::optional<SchemaError> check_one_of(const json& v, const json& options, const std::string& ptr, int depth) const {
    int matched = 0;
    std::optional<SchemaError> best;
    auto score = [](const SchemaError& e) {
      const bool discriminator = e.rule.rfind(kConstRule, 0) == 0;
      const auto segments = std::count(e.pointer.begin(), e.pointer.end(), '/');
      return (discriminator ? 0 : 1000) + segments;
    };
    for (const json& option : options) {
      auto e = check(v, option, ptr, depth + 1);
      if (!e) {
        ++matched;
      } else if (!best || score(*e) > score(*best)) {
        best = e;
      }
    }
    if (matched == 1) return std::nullopt;
    if (matched > 1) return SchemaError{ptr, "must match exactly one of the oneOf alternatives (" + std::to_string(matched) + " match)"};
    return best;
  }

  const json& root_;
};

}  // namespace

std::optional<SchemaError> validate_json_schema(const json& instance, const json& schema) {
  return Validator(schema).check(instance, schema, "");
}

}  // namespace softtune::codec
