#include "codec/list_reader.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "codec/problem.h"

namespace softtune::codec {
namespace {

std::string list_rule(std::size_t max_entries, double lo, double hi, const char* unit, bool integers) {
  char b[192];
  std::snprintf(b, sizeof b, "must be an array of 1 to %zu %s in [%g, %g]%s%s", max_entries,
                integers ? "integers" : "finite numbers", lo, hi, *unit ? " " : "", unit);
  return b;
}

// The array at `key`, or nullptr when absent; a Problem when it is not a non-empty, short enough array.
const nlohmann::json* list_at(ObjectReader& r, std::string_view key, std::size_t max_entries, const std::string& rule) {
  const nlohmann::json* v = r.raw(key);
  if (!v) return nullptr;
  if (!v->is_array() || v->empty() || v->size() > max_entries) throw invalid_field(r.field(key), rule);
  return v;
}

// Reads every entry with `read` (which returns false when the entry breaks the rule).
template <typename T, typename Read>
std::optional<std::vector<T>> read_list(ObjectReader& r, std::string_view key, std::size_t max_entries,
                                        const std::string& rule, Read read) {
  const nlohmann::json* v = list_at(r, key, max_entries, rule);
  if (!v) return std::nullopt;
  std::vector<T> out;
  for (std::size_t i = 0; i < v->size(); ++i) {
    T value{};
    if (!read((*v)[i], value)) throw invalid_field(r.field(key) + "." + std::to_string(i), rule);
    out.push_back(value);
  }
  return out;
}

}  // namespace

std::optional<std::vector<double>> read_number_list(ObjectReader& r, std::string_view key, std::size_t max_entries,
                                                    double lo, double hi, const char* unit) {
  return read_list<double>(r, key, max_entries, list_rule(max_entries, lo, hi, unit, false),
                           [&](const nlohmann::json& e, double& out) {
                             if (!e.is_number()) return false;
                             out = e.get<double>();
                             return std::isfinite(out) && out >= lo && out <= hi;
                           });
}

std::optional<std::vector<int>> read_integer_list(ObjectReader& r, std::string_view key, std::size_t max_entries,
                                                  int lo, int hi) {
  return read_list<int>(r, key, max_entries, list_rule(max_entries, lo, hi, "", true),
                        [&](const nlohmann::json& e, int& out) {
                          if (!e.is_number_integer() || e.get<long long>() < lo || e.get<long long>() > hi) return false;
                          out = static_cast<int>(e.get<long long>());
                          return true;
                        });
}

}  // namespace softtune::codec
