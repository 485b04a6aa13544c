#pragma once
// What every CLI command shares: flags, reading a request (file or stdin), printing JSON, and turning
// a Problem into exit code 2 with problem JSON on stderr.

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "app/answer.h"
#include "cli/commands.h"

namespace softtune::cli {

inline constexpr int kExitOk = 0, kExitFailed = 1, kExitBadInput = 2;

/// Parsed `--name value` pairs and bare `--switch`es; positional arguments in order.
struct Flags {
  std::map<std::string, std::string> values;
  std::vector<std::string> positional;
  bool has(const std::string& name) const { return values.contains(name); }
  std::optional<std::string> get(const std::string& name) const;
};

/// Parses args; `switches` take no value. Unknown flags are refused (Problem naming the flag).
Flags parse_flags(const Args& args, const std::vector<std::string>& with_value,
                  const std::vector<std::string>& switches);

/// A flag's value as a number (Problem naming the flag when it is not one).
double flag_number(const Flags& f, const std::string& name);

/// Reads the JSON document in FILE, or stdin for "-".
nlohmann::json read_request_file(const std::string& path);

/// The request of a command: the JSON in `--request FILE` (which takes no other flag), else the one
/// `from_flags` builds from the flags.
nlohmann::json request_from(const Flags& flags, const std::function<nlohmann::json()>& from_flags);

/// The scene request of `simulate` and `modes`: {"preset": NAME} from `--preset NAME`, or the JSON object in
/// `--request FILE` (exactly one of the two), with `--mass-model M` as its mass_model and `--engine`,
/// `--engine-settings` as its engine (cli/engine_flags.h).
nlohmann::json scene_request_from(const Flags& flags);

/// Prints a JSON document on stdout.
void print_json(const nlohmann::json& doc);

/// Prints a use case's answer: JSON as print_json does, CSV and SVG text as they are.
void print_answer(const app::Answer& answer);

/// Runs `body`; a Problem goes to stderr as problem JSON with exit code 2, any other exception as a
/// problem with status 500 and exit code 1.
int guarded(const std::function<int()>& body);

}  // namespace softtune::cli
