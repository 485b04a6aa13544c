#pragma once
// Strict JSON reading at the edge: parse with a depth limit and duplicate-key check, then read typed
// fields by name. Every failure is a Problem naming the field and the rule; unknown fields are refused
// (a misspelt "damping_ration" must not silently fall back to a default).

#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace softtune::codec {

inline constexpr int kMaxJsonDepth = 32;

/// The dotted path of a JSON pointer: "/world/fps" -> "world.fps", "/bodies/0/mass" -> "bodies.0.mass"
/// (RFC 6901 escapes ~1 and ~0 undone). Every problem names its field this way.
std::string dotted_path(std::string_view pointer);

/// Parses `text` as one JSON document; 400 when malformed, too deep or holding a duplicated key.
nlohmann::json parse_json(std::string_view text);

/// Reads the fields of one JSON object; `path` is its dotted prefix ("constraint.body_a").
class ObjectReader {
 public:
  ObjectReader(const nlohmann::json& object, std::string path);

  bool has(std::string_view key) const;
  std::optional<double> number(std::string_view key);
  std::optional<long long> integer(std::string_view key);
  std::optional<std::string> string(std::string_view key);
  const nlohmann::json* raw(std::string_view key);   ///< any type; nullptr when absent
  /// A number array of exactly `n` entries.
  std::optional<std::vector<double>> numbers(std::string_view key, std::size_t n);
  std::optional<ObjectReader> object(std::string_view key);
  /// One of `choices` (e.g. "free"|"some"|"none"); returns its index.
  std::optional<std::size_t> choice(std::string_view key, const std::vector<std::string_view>& choices);

  std::string field(std::string_view key) const;  ///< dotted path of a key
  /// Refuses any key not read so far (422 naming it).
  void finish() const;

 private:
  const nlohmann::json& json_;
  std::string path_;
  std::set<std::string, std::less<>> read_;
};

/// An ObjectReader for `doc`, which must be an object (422 otherwise).
ObjectReader read_object(const nlohmann::json& doc, std::string path);

}  // namespace softtune::codec
