#include "softtune/render/content_hash.h"

#include <openssl/evp.h>

#include <array>
#include <stdexcept>

namespace softtune::render {

// OpenSSL's EVP interface (libcrypto), one shot: EVP_Digest initialises, hashes and finalises a
// context of its own, so concurrent callers share nothing.
std::string sha256_hex(std::string_view bytes) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest.data(), &length, EVP_sha256(), nullptr) != 1 || length != 32) {
    throw std::runtime_error("SHA-256 (OpenSSL EVP_Digest) failed");
  }
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out(2 * length, '0');
  for (unsigned int i = 0; i < length; ++i) {
    out[2 * i] = kHex[digest[i] >> 4];
    out[2 * i + 1] = kHex[digest[i] & 0xF];
  }
  return out;
}

}  // namespace softtune::render
