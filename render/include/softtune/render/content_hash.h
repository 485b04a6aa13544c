#pragma once
// Content hashes that name preview results: SHA-256 (FIPS 180-4, computed by OpenSSL's libcrypto), so
// two different requests never share a cache entry or an ETag in practice.

#include <string>
#include <string_view>

namespace softtune::render {

/// SHA-256 of `bytes` as 64 lower-case hex digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace softtune::render
