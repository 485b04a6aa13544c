// libFuzzer entry point for softtune::fuzz::tune_request (fuzz/tune_harness.h).
#include "tune_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  softtune::fuzz::tune_request({reinterpret_cast<const char*>(data), size});
  return 0;
}
