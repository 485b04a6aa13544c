// softtune: one binary, one subcommand per job. The table below is the whole CLI surface.
#include <cstring>
#include <iostream>

#include "cli/commands.h"
#include "softtune/version.h"

namespace {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const softtune::cli::Args&);
};

constexpr Command kCommands[] = {
    {"tune", "designer request -> k, c, gamma, beta, ERP/CFM, engine export, stability", softtune::cli::run_tune},
    {"serve", "the REST API and the page on http://127.0.0.1:8080/", softtune::cli::run_serve},
    {"accuracy", "work-precision report: error against CPU time per method, and a recommendation", softtune::cli::run_accuracy},
    {"stability", "extreme-case sweep: predicted against observed stability, mass-ratio chain", softtune::cli::run_stability},
    {"simulate", "run a scene or preset in Box2D / the core integrators, measure the achieved response", softtune::cli::run_simulate},
    {"modes", "the modes of a scene or preset about its rest state: frequency, damping, shape", softtune::cli::run_modes},
    {"check", "run every preset's expectations (the automated preset test)", softtune::cli::run_check},
    {"render", "preview frames of a preset -> DIR/frame_0000.png ... and filmstrip.png", softtune::cli::run_render},
    {"verify", "run a tuning in the real engines linked in process: measured against predicted", softtune::cli::run_verify},
    {"identify", "a recorded trajectory (CSV) -> frequency, damping, verdicts, and what to type instead", softtune::cli::run_identify},
};

int usage(std::ostream& out, int code) {
  out << "usage: softtune COMMAND [options]   (softtune COMMAND --help for each)\n"
         "       softtune --version\n\ncommands:\n";
  for (const Command& c : kCommands) out << "  " << c.name << std::string(12 - std::strlen(c.name), ' ') << c.summary << '\n';
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage(std::cerr, 2);
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") return usage(std::cout, 0);
  if (name == "--version" || name == "-V") {
    if (argc > 2) {
      std::cerr << "softtune: --version takes no arguments\n";
      return 2;
    }
    std::cout << "softtune " << softtune::kVersion << '\n';
    return 0;
  }
  for (const Command& c : kCommands) {
    if (name == c.name) return c.run(softtune::cli::Args(argv + 2, argv + argc));
  }
  std::cerr << "softtune: unknown command \"" << name << "\"\n";
  return usage(std::cerr, 2);
}
