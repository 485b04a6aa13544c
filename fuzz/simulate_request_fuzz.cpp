// libFuzzer entry point for softtune::fuzz::simulate_request (fuzz/harnesses.h).
#include "harnesses.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  softtune::fuzz::simulate_request({reinterpret_cast<const char*>(data), size});
  return 0;
}
