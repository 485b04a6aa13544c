// libFuzzer entry point for softtune::fuzz::preset_load (fuzz/harnesses.h).
#include "harnesses.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  softtune::fuzz::preset_load({reinterpret_cast<const char*>(data), size});
  return 0;
}
