// gzip-compressed data (RFC 1952), as pbrt-v4 scenes ship their large included files
// (`Include "geometry.pbrt.gz"`): recognised by its magic bytes and inflated with zlib.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace eyetrace {

// True when `data` starts with gzip's magic bytes 1f 8b.
bool is_gzip(std::string_view data);

// The decompressed bytes of every gzip member in `data` (concatenated members are one stream,
// as gunzip reads them), or nullopt with *error saying what is wrong: corrupt data, a stream
// that ends early (a truncated file), bytes after the last member that are not gzip, or an
// output beyond `max_bytes` (a guard against decompression bombs).
std::optional<std::string> gunzip(std::string_view data, std::string* error, size_t max_bytes = size_t(1) << 40);

}  // namespace eyetrace
