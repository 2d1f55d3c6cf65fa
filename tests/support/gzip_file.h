// Writes a gzip-compressed file with zlib's own gzip writer, independent of eyetrace's reader.
#pragma once
#include <gtest/gtest.h>
#include <zlib.h>

#include <string>

namespace eyetrace::test {

inline void write_gzip_file(const std::string& path, const std::string& bytes) {
  gzFile f = gzopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  ASSERT_EQ(gzwrite(f, bytes.data(), unsigned(bytes.size())), int(bytes.size()));
  ASSERT_EQ(gzclose(f), Z_OK);
}

}  // namespace eyetrace::test
