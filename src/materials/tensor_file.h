// The "tensor file" of the RGL material database (rgl.epfl.ch/materials; Mitsuba's
// TensorFile, read by pbrt-v4's "measured" material): a 12-byte magic "tensor_file\0", a
// version (1, 0), a uint32 field count, then per field its name (uint16 length + bytes), rank
// (uint16), element type (uint8), the uint64 byte offset of its data and its shape (rank
// uint64s). All little-endian. Every size is checked against the bytes the file holds before
// anything is allocated, so a truncated or lying file is an error that says what is wrong,
// never a crash or a runaway allocation.
#pragma once
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace eyetrace {

// What is wrong with a tensor file, without its path (the caller names the file).
class TensorFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct TensorField {
  // The element types, numbered as in the file.
  enum Type : uint8_t { Invalid, UInt8, Int8, UInt16, Int16, UInt32, Int32, UInt64, Int64, Float16, Float32, Float64 };
  Type dtype = Invalid;
  std::vector<uint64_t> shape;
  std::vector<uint8_t> bytes;  // the elements as stored

  // Float32 elements as floats (the caller has checked dtype).
  std::vector<float> floats() const;
  std::string describe() const;  // "float32 [1, 8, 24, 24]"
};

struct TensorFile {
  std::map<std::string, TensorField> fields;
  const TensorField* find(const std::string& name) const {
    auto it = fields.find(name);
    return it == fields.end() ? nullptr : &it->second;
  }
};

TensorFile parse_tensor_file(std::string_view bytes);
TensorFile read_tensor_file(const std::string& path);  // also TensorFileError when unreadable

const char* tensor_type_name(TensorField::Type t);

}  // namespace eyetrace
