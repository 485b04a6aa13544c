#include "codec/json_reader.h"

#include <cmath>

#include "codec/problem.h"

namespace softtune::codec {

namespace {

// One open object or array while parsing, to name the field a parse error is about.
struct OpenValue {
  bool array = false;
  std::set<std::string> keys;  ///< keys seen (objects), to refuse duplicates
  std::string key;             ///< the key being read (objects)
  std::size_t index = 0;       ///< the element being read (arrays)
};

// The dotted path of the value being read: "constraint.anchor_a.1".
std::string open_path(const std::vector<OpenValue>& open) {
  std::string path;
  for (const OpenValue& v : open) {
    if (v.array) {
      path += (path.empty() ? "" : ".") + std::to_string(v.index);
    } else if (!v.key.empty()) {
      path += (path.empty() ? "" : ".") + v.key;
    }
  }
  return path;
}

}  // namespace

nlohmann::json parse_json(std::string_view text) {
  // nlohmann keeps the last of duplicated keys silently, and its errors do not say where: the open
  // objects and arrays are followed here to refuse duplicates and name the field of a failed value
  // (e.g. a number overflowing 1e308) by its whole path.
  std::vector<OpenValue> open;
  auto callback = [&open](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (depth > kMaxJsonDepth) {
      throw malformed_json("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }
    // A finished element of an array moves the array on to its next index.
    const auto element_done = [&open] {
      if (!open.empty() && open.back().array) ++open.back().index;
    };
    if (event == E::object_start || event == E::array_start) open.push_back({event == E::array_start, {}, {}, 0});
    if ((event == E::object_end || event == E::array_end) && !open.empty()) {
      open.pop_back();
      element_done();
    }
    if (event == E::value) element_done();
    if (event == E::key && !open.empty()) {
      const std::string& key = parsed.get_ref<const std::string&>();
      open.back().key = key;
      if (!open.back().keys.insert(key).second) {
        throw Problem(400, "Malformed JSON", open_path(open), "duplicated key \"" + key + "\"");
      }
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text.begin(), text.end(), callback);
  } catch (const nlohmann::json::out_of_range& e) {
    // Well-formed JSON whose value no double holds: a value out of range (422), like 1e308 * 10 would be.
    throw invalid_field(open_path(open), "must be a finite number: the value overflows a double (largest 1.8e308)");
  } catch (const nlohmann::json::exception& e) {
    throw malformed_json(e.what());
  }
}

std::string dotted_path(std::string_view pointer) {
  std::string out;
  for (std::size_t i = 0; i < pointer.size(); ++i) {
    const char c = pointer[i];
    if (c == '/') {
      if (i > 0) out += '.';
    } else if (c == '~' && i + 1 < pointer.size() && (pointer[i + 1] == '0' || pointer[i + 1] == '1')) {
      out += pointer[++i] == '0' ? '~' : '/';
    } else {
      out += c;
    }
  }
  return out;
}

ObjectReader::ObjectReader(const nlohmann::json& object, std::string path)
    : json_(object), path_(std::move(path)) {}

std::string ObjectReader::field(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

bool ObjectReader::has(std::string_view key) const { return json_.contains(key); }

const nlohmann::json* ObjectReader::raw(std::string_view key) {
  auto it = json_.find(key);
  if (it == json_.end()) return nullptr;
  read_.emplace(key);
  return &*it;
}

std::optional<double> ObjectReader::number(std::string_view key) {
  const nlohmann::json* v = raw(key);
  if (!v) return std::nullopt;
  if (!v->is_number()) throw invalid_field(field(key), "must be a number");
  const double d = v->get<double>();
  if (!std::isfinite(d)) throw invalid_field(field(key), "must be a finite number");
  return d;
}

std::optional<long long> ObjectReader::integer(std::string_view key) {
  const nlohmann::json* v = raw(key);
  if (!v) return std::nullopt;
  if (v->is_number_integer()) return v->get<long long>();
  if (v->is_number_float()) {
    const double d = v->get<double>();
    if (std::isfinite(d) && d == std::floor(d) && std::abs(d) < 9e15) return static_cast<long long>(d);
  }
  throw invalid_field(field(key), "must be an integer");
}

std::optional<std::string> ObjectReader::string(std::string_view key) {
  const nlohmann::json* v = raw(key);
  if (!v) return std::nullopt;
  if (!v->is_string()) throw invalid_field(field(key), "must be a string");
  return v->get<std::string>();
}

std::optional<std::vector<double>> ObjectReader::numbers(std::string_view key, std::size_t n) {
  const nlohmann::json* v = raw(key);
  if (!v) return std::nullopt;
  const std::string rule = "must be an array of " + std::to_string(n) + " finite numbers";
  if (!v->is_array() || v->size() != n) throw invalid_field(field(key), rule);
  std::vector<double> out;
  for (const auto& e : *v) {
    if (!e.is_number() || !std::isfinite(e.get<double>())) throw invalid_field(field(key), rule);
    out.push_back(e.get<double>());
  }
  return out;
}

std::optional<ObjectReader> ObjectReader::object(std::string_view key) {
  const nlohmann::json* v = raw(key);
  if (!v) return std::nullopt;
  if (!v->is_object()) throw invalid_field(field(key), "must be an object");
  return ObjectReader(*v, field(key));
}

std::optional<std::size_t> ObjectReader::choice(std::string_view key, const std::vector<std::string_view>& choices) {
  const std::optional<std::string> s = string(key);
  if (!s) return std::nullopt;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (*s == choices[i]) return i;
  }
  std::string rule = "must be one of";
  for (std::size_t i = 0; i < choices.size(); ++i) rule += (i ? ", \"" : " \"") + std::string(choices[i]) + "\"";
  throw invalid_field(field(key), rule);
}

void ObjectReader::finish() const {
  for (auto it = json_.begin(); it != json_.end(); ++it) {
    if (!read_.contains(it.key())) throw invalid_field(field(it.key()), "is not a known field");
  }
}

ObjectReader read_object(const nlohmann::json& doc, std::string path) {
  if (!doc.is_object()) throw invalid_field(path, "must be a JSON object");
  return ObjectReader(doc, std::move(path));
}

}  // namespace softtune::codec
