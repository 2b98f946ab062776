// SHA-256 against the test vectors of FIPS 180-4 (NIST's examples) and across block boundaries.
#include "io/sha256.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

std::string digest_of(const std::string& text) {
  return rbcsim::io::sha256_hex(std::as_bytes(std::span(text.data(), text.size())));
}

TEST(Sha256, NistTestVectors) {
  EXPECT_EQ(digest_of(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(digest_of("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(digest_of("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(digest_of(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

// Fed in pieces of any size, the digest is that of the whole (55/56/64 bytes: the padding cases).
TEST(Sha256, PiecesGiveTheDigestOfTheWhole) {
  for (const std::size_t length : {55u, 56u, 63u, 64u, 65u, 200u}) {
    const std::string text(length, 'x');
    rbcsim::io::Sha256 hash;
    for (std::size_t start = 0; start < length; start += 7) {
      const auto piece = text.substr(start, 7);
      hash.update(std::as_bytes(std::span(piece.data(), piece.size())));
    }
    EXPECT_EQ(hash.hex_digest(), digest_of(text)) << length;
  }
}

}  // namespace
