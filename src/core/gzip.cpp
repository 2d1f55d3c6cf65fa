#include "core/gzip.h"

#include <zlib.h>

#include <algorithm>
#include <climits>

#include <fmt/core.h>

namespace eyetrace {

bool is_gzip(std::string_view data) {
  return data.size() >= 2 && (unsigned char)data[0] == 0x1f && (unsigned char)data[1] == 0x8b;
}

namespace {

// Inflates one member starting at data[*offset]; appends to *out and advances *offset past it.
bool inflate_member(std::string_view data, size_t* offset, std::string* out, size_t max_bytes, std::string* error) {
  z_stream z{};
  // 16 + MAX_WBITS: a gzip header and trailer (CRC-32 and length, both checked by zlib).
  if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) {
    *error = "zlib cannot start";
    return false;
  }
  char buffer[1 << 16];
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    if (z.avail_in == 0) {
      const size_t left = data.size() - *offset;
      if (left == 0) break;
      // avail_in is 32 bits: feed a multi-gigabyte file in chunks.
      const size_t chunk = std::min<size_t>(left, UINT_MAX / 2);
      z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + *offset));
      z.avail_in = uInt(chunk);
      *offset += chunk;
    }
    z.next_out = reinterpret_cast<Bytef*>(buffer);
    z.avail_out = sizeof buffer;
    rc = inflate(&z, Z_NO_FLUSH);
    if (rc == Z_BUF_ERROR) break;  // no input left to go on with: reported below as truncated
    if (rc != Z_OK && rc != Z_STREAM_END) {
      *error = fmt::format("corrupt gzip data ({})", z.msg ? z.msg : "zlib error");
      inflateEnd(&z);
      return false;
    }
    const size_t produced = sizeof buffer - z.avail_out;
    if (out->size() + produced > max_bytes) {
      *error = fmt::format("it decompresses to more than {} bytes", max_bytes);
      inflateEnd(&z);
      return false;
    }
    out->append(buffer, produced);
  }
  *offset -= z.avail_in;  // input after this member's trailer, not consumed
  inflateEnd(&z);
  if (rc != Z_STREAM_END) {
    *error = "the gzip stream ends early (the file is truncated)";
    return false;
  }
  return true;
}

}  // namespace

std::optional<std::string> gunzip(std::string_view data, std::string* error, size_t max_bytes) {
  std::string out;
  size_t offset = 0;
  do {
    if (!is_gzip(data.substr(offset))) {
      *error = offset == 0 ? "not gzip data" : "bytes after the end of the gzip data that are not gzip";
      return std::nullopt;
    }
    if (!inflate_member(data, &offset, &out, max_bytes, error)) return std::nullopt;
  } while (offset < data.size());
  return out;
}

}  // namespace eyetrace
