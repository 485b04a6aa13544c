#pragma once
// The repository's presets/ folder, for the tests that load presets. SOFTTUNE_PRESETS_DIR comes from the
// test's target (its CMakeLists.txt).

#include <string>

namespace softtune::test_support {

inline const std::string kPresets = SOFTTUNE_PRESETS_DIR;

}  // namespace softtune::test_support
