// libFuzzer entry point for softtune::fuzz::request_decode (fuzz/harnesses.h).
#include "harnesses.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  softtune::fuzz::request_decode({reinterpret_cast<const char*>(data), size});
  return 0;
}
