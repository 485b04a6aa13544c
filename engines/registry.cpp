// The real engines linked in process, in the order answers list them. Each engine room adds one line.
#include <array>

#include "softtune/engines/verify.h"

namespace softtune::engines {

std::span<const RealEngine* const> real_engines() {
  static constexpr std::array<const RealEngine*, 0> kEngines = {};
  return kEngines;
}

}  // namespace softtune::engines
