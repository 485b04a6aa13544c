#pragma once
// The fields a cost blames: each candidate field with how many times the default's work it asks for;
// those above 1, the largest first. Shared by the contracts' cost functions (app/*_cost.cpp).

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace softtune::app {

class CostDrivers {
 public:
  /// `field` multiplies the work by `factor` against the default request (1: as the default).
  void add(std::string field, double factor) { candidates_.emplace_back(std::move(field), factor); }
  /// The fields whose factor is above 1, largest first; all of them, in order, when none is.
  std::vector<std::string> fields() const {
    std::vector<std::pair<std::string, double>> c = candidates_;
    std::stable_sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    std::vector<std::string> out;
    for (const auto& [field, factor] : c) {
      if (factor > 1.0) out.push_back(field);
    }
    if (out.empty()) {
      for (const auto& [field, factor] : candidates_) out.push_back(field);
    }
    return out;
  }

 private:
  std::vector<std::pair<std::string, double>> candidates_;
};

}  // namespace softtune::app
