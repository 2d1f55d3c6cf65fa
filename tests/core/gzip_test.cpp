// gunzip against bytes made by GNU gzip (`printf 'hello\n' | gzip -n`), and its refusals:
// a truncated stream, corrupt data, bytes after the end, and output beyond the limit.
#include "core/gzip.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <string>

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// `printf 'hello\n' | gzip -n | xxd -i` (GNU gzip 1.12): header, deflate data, CRC-32 and length.
const unsigned char kHelloGz[] = {0x1f, 0x8b, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x03, 0xcb, 0x48, 0xcd,
                                  0xc9, 0xc9, 0xe7, 0x02, 0x00, 0x20, 0x30, 0x3a, 0x36, 0x06, 0x00, 0x00, 0x00};

std::string hello_gz() { return std::string(reinterpret_cast<const char*>(kHelloGz), sizeof kHelloGz); }

TEST(Gzip, InflatesWhatGnuGzipWrote) {
  std::string error;
  ASSERT_TRUE(is_gzip(hello_gz()));
  auto out = gunzip(hello_gz(), &error);
  ASSERT_TRUE(out) << error;
  EXPECT_EQ(*out, "hello\n");
}

// `cat a.gz b.gz` is one stream to gunzip: the members' contents concatenated.
TEST(Gzip, ConcatenatedMembersAreOneStream) {
  std::string error;
  auto out = gunzip(hello_gz() + hello_gz(), &error);
  ASSERT_TRUE(out) << error;
  EXPECT_EQ(*out, "hello\nhello\n");
}

TEST(Gzip, EveryTruncationIsAnError) {
  const std::string gz = hello_gz();
  for (size_t n = 0; n < gz.size(); ++n) {
    std::string error;
    EXPECT_FALSE(gunzip(gz.substr(0, n), &error)) << n;
    EXPECT_FALSE(error.empty()) << n;
  }
  std::string error;
  EXPECT_FALSE(gunzip(gz.substr(0, gz.size() - 8), &error));  // the whole trailer gone
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
}

// A changed byte of the data or of the trailer (CRC-32, length) is found. (Byte 17 is the
// deflate data's last: its upper bits only pad the stream to a whole byte, so they are skipped.)
TEST(Gzip, CorruptDataIsAnError) {
  for (size_t i = 10; i < sizeof kHelloGz; ++i) {
    if (i == 17) continue;
    std::string gz = hello_gz();
    gz[i] = char(gz[i] ^ 0x40);
    std::string error;
    EXPECT_FALSE(gunzip(gz, &error)) << "byte " << i;
    EXPECT_FALSE(error.empty());
  }
}

TEST(Gzip, TrailingBytesAndPlainTextAreErrors) {
  std::string error;
  EXPECT_FALSE(gunzip(hello_gz() + "x", &error));
  EXPECT_NE(error.find("after the end"), std::string::npos) << error;
  EXPECT_FALSE(is_gzip("Shape \"sphere\""));
  EXPECT_FALSE(gunzip("Shape \"sphere\"", &error));
}

TEST(Gzip, OutputBeyondTheLimitIsRefused) {
  std::string error;
  EXPECT_FALSE(gunzip(hello_gz(), &error, 5));
  EXPECT_NE(error.find("more than 5 bytes"), std::string::npos) << error;
  EXPECT_TRUE(gunzip(hello_gz(), &error, 6));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
