// SHA-256 (the digests of an export's upload files and of a sweep's inputs)
// against FIPS 180-2's examples, also fed in uneven pieces.
#include "dream/formats/sha256.h"

#include <gtest/gtest.h>

#include <string>

namespace dream::formats {
namespace {

TEST(Sha256Test, KnownDigests) {
  // FIPS 180-2's examples, and a million 'a's added in uneven pieces.
  EXPECT_EQ(Sha256::Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(Sha256::Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(Sha256::Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  Sha256 million;
  const std::string piece(999, 'a');
  for (int i = 0; i < 1001; ++i) million.Add(piece);
  million.Add(std::string(1000000 - 999 * 1001, 'a'));
  EXPECT_EQ(million.HexDigest(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

}  // namespace
}  // namespace dream::formats
