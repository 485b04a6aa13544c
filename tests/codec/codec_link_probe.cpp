// A program on the codec library alone: a tune request decoded, tuned and encoded. Its link line is what
// codec.link_line reads, so a codec that pulls in Box2D, libpng or Mesa fails a test (issue 14).
#include <iostream>

#include "codec/tune_codec.h"

int main() {
  const nlohmann::json request = {{"frequency_hz", 5.0}, {"oscillation", "some"}, {"effective_mass", 1.0}};
  const softtune::TuneRequest q = softtune::codec::decode_tune_request(request);
  std::cout << softtune::codec::encode_tune_result(q, softtune::tune(q)).at("k") << "\n";
  return 0;
}
