#pragma once
// A small stability sweep (48 cases and a 2 x 2 chain) that the stability codec and use-case tests share.

#include <nlohmann/json.hpp>

namespace softtune::test {

inline nlohmann::json small_sweep() {
  return {{"methods", {"explicit_euler", "soft"}},
          {"frequency_ratios", {0.01, 0.3, 2.0}},
          {"stiffnesses", {1e12}},
          {"damping_ratios", {0.0, 1.0}},
          {"masses", {1e-6, 1.0}},
          {"steps", {1e-3, 0.1}},
          {"chain", {{"mass_ratios", {1, 1000}}, {"iterations", {1, 4}}, {"frequency_ratios", {0.01, 0.1, 1.0}}}}};
}

}  // namespace softtune::test
