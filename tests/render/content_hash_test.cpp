#include "softtune/render/content_hash.h"

#include <gtest/gtest.h>

#include <string>

namespace softtune::render {
namespace {

// FIPS 180-4 / NIST CSRC example vectors.
TEST(Sha256, MatchesNistVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // 56 bytes: the padding needs a second block.
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, BlockBoundaryLengthsDiffer) {
  // 55, 56, 63, 64, 65 bytes straddle the one/two padding-block cases; all must be distinct digests.
  std::string last;
  for (int n : {55, 56, 63, 64, 65}) {
    const std::string h = sha256_hex(std::string(n, 'x'));
    EXPECT_EQ(h.size(), 64u);
    EXPECT_NE(h, last);
    last = h;
  }
}

}  // namespace
}  // namespace softtune::render
