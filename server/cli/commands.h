#pragma once
// Every `softtune` subcommand. Each lives in its own cmd_*.cpp; main.cpp holds the table.

#include <string>
#include <vector>

namespace softtune::cli {

using Args = std::vector<std::string>;

int run_tune(const Args& args);
int run_serve(const Args& args);
int run_accuracy(const Args& args);
int run_stability(const Args& args);
int run_simulate(const Args& args);
int run_modes(const Args& args);
int run_check(const Args& args);
int run_render(const Args& args);
int run_verify(const Args& args);
int run_identify(const Args& args);

}  // namespace softtune::cli
