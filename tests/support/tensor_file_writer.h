// Writes a TensorFile back to the bytes of an RGL tensor file (the layout tools/make_measured_bsdf
// writes: header, field table, then the fields' data in order), so that tests can take a valid
// file apart, break one thing and see the reader name it.
#pragma once
#include <cstring>
#include <string>

#include "materials/tensor_file.h"

namespace eyetrace::test {

inline std::string serialize_tensor_file(const TensorFile& file) {
  auto put = [](std::string& out, const auto& v) { out.append(reinterpret_cast<const char*>(&v), sizeof(v)); };
  size_t header = 12 + 2 + 4;
  for (const auto& [name, f] : file.fields) header += 2 + name.size() + 2 + 1 + 8 + 8 * f.shape.size();
  std::string out("tensor_file\0", 12), data;
  out += char(1);
  out += char(0);
  put(out, uint32_t(file.fields.size()));
  for (const auto& [name, f] : file.fields) {
    put(out, uint16_t(name.size()));
    out += name;
    put(out, uint16_t(f.shape.size()));
    put(out, uint8_t(f.dtype));
    put(out, uint64_t(header + data.size()));
    for (uint64_t n : f.shape) put(out, n);
    data.append(reinterpret_cast<const char*>(f.bytes.data()), f.bytes.size());
  }
  return out + data;
}

// A float32 field of the given shape and values.
inline TensorField float_field(std::vector<uint64_t> shape, const std::vector<float>& values) {
  TensorField f;
  f.dtype = TensorField::Float32;
  f.shape = std::move(shape);
  f.bytes.resize(values.size() * sizeof(float));
  std::memcpy(f.bytes.data(), values.data(), f.bytes.size());
  return f;
}

}  // namespace eyetrace::test
