#include "cli/cli_io.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "codec/json_reader.h"
#include "cli/engine_flags.h"
#include "codec/problem.h"

namespace softtune::cli {

std::optional<std::string> Flags::get(const std::string& name) const {
  auto it = values.find(name);
  return it == values.end() ? std::nullopt : std::optional<std::string>(it->second);
}

Flags parse_flags(const Args& args, const std::vector<std::string>& with_value,
                  const std::vector<std::string>& switches) {
  Flags f;
  auto known = [](const std::vector<std::string>& list, const std::string& s) {
    return std::find(list.begin(), list.end(), s) != list.end();
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() < 3 || a.rfind("--", 0) != 0) {
      f.positional.push_back(a);
      continue;
    }
    std::string name = a.substr(2), value;
    const auto eq = name.find('=');
    const bool inline_value = eq != std::string::npos;
    if (inline_value) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    if (known(switches, name)) {
      f.values[name] = "true";
    } else if (known(with_value, name)) {
      if (!inline_value) {
        if (i + 1 >= args.size()) throw codec::invalid_field("--" + name, "needs a value");
        value = args[++i];
      }
      f.values[name] = value;
    } else {
      throw codec::invalid_field("--" + name, "is not a flag of this command (see --help)");
    }
  }
  return f;
}

double flag_number(const Flags& f, const std::string& name) {
  const std::string s = *f.get(name);
  try {
    std::size_t used = 0;
    const double d = std::stod(s, &used);
    if (used == s.size() && std::isfinite(d)) return d;
  } catch (const std::exception&) {
  }
  throw codec::invalid_field("--" + name, "must be a finite number, got \"" + s + "\"");
}

nlohmann::json read_request_file(const std::string& path) {
  std::stringstream buffer;
  if (path == "-") {
    buffer << std::cin.rdbuf();
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw codec::invalid_field("--request", "cannot read file \"" + path + "\"");
    buffer << in.rdbuf();
  }
  return codec::parse_json(buffer.str());
}

nlohmann::json request_from(const Flags& flags, const std::function<nlohmann::json()>& from_flags) {
  const auto file = flags.get("request");
  if (!file) return from_flags();
  if (flags.values.size() > 1) throw codec::invalid_field("--request", "cannot be combined with other flags");
  return read_request_file(*file);
}

nlohmann::json scene_request_from(const Flags& flags) {
  if (flags.has("preset") == flags.has("request")) {
    throw codec::invalid_field("--preset", "give exactly one of --preset NAME and --request FILE");
  }
  nlohmann::json request;
  if (auto name = flags.get("preset")) {
    request = {{"preset", *name}};
  } else {
    request = read_request_file(*flags.get("request"));
    if (!request.is_object()) throw codec::invalid_field("--request", "must hold a JSON object");
  }
  if (auto m = flags.get("mass-model")) request["mass_model"] = *m;
  set_engine_from_flags(flags, request);
  return request;
}

void print_json(const nlohmann::json& doc) { std::cout << doc.dump(2) << '\n'; }

void print_answer(const app::Answer& answer) {
  if (answer.format == app::Format::json) {
    print_json(answer.json);
  } else {
    std::cout << answer.text;
  }
}

int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const codec::Problem& p) {
    std::cerr << codec::problem_json(p).dump(2) << '\n';
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << codec::problem_json(codec::Problem(500, "Internal error", "", e.what())).dump(2) << '\n';
    return kExitFailed;
  }
}

}  // namespace softtune::cli
