#include "materials/tensor_file.h"

#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

namespace eyetrace {

static_assert(std::endian::native == std::endian::little, "tensor files are little-endian; add byte swapping");

namespace {

size_t type_size(TensorField::Type t) {
  switch (t) {
    case TensorField::UInt8:
    case TensorField::Int8: return 1;
    case TensorField::UInt16:
    case TensorField::Int16:
    case TensorField::Float16: return 2;
    case TensorField::UInt32:
    case TensorField::Int32:
    case TensorField::Float32: return 4;
    case TensorField::UInt64:
    case TensorField::Int64:
    case TensorField::Float64: return 8;
    default: return 0;
  }
}

// Reads the header sequentially; every read names what it was reading when the bytes end.
class Cursor {
 public:
  explicit Cursor(std::string_view bytes) : bytes_(bytes) {}
  template <typename T>
  T read(const std::string& what) {
    T v;
    std::memcpy(&v, take(sizeof(T), what), sizeof(T));
    return v;
  }
  std::string read_string(size_t n, const std::string& what) { return std::string(take(n, what), n); }
  size_t position() const { return pos_; }

 private:
  const char* take(size_t n, const std::string& what) {
    if (n > bytes_.size() - pos_)
      throw TensorFileError(
          fmt::format("truncated: {} needs {} bytes at offset {}, the file has {}", what, n, pos_, bytes_.size()));
    const char* p = bytes_.data() + pos_;
    pos_ += n;
    return p;
  }
  std::string_view bytes_;
  size_t pos_ = 0;
};

TensorField read_field(Cursor& in, std::string_view bytes, const std::string& name) {
  const std::string where = fmt::format("field \"{}\"", name);
  const auto rank = in.read<uint16_t>(where + "'s rank");
  TensorField f;
  const auto dtype = in.read<uint8_t>(where + "'s type");
  if (dtype == TensorField::Invalid || dtype > TensorField::Float64)
    throw TensorFileError(fmt::format("{} has unknown element type {}", where, unsigned(dtype)));
  f.dtype = TensorField::Type(dtype);
  const auto offset = in.read<uint64_t>(where + "'s data offset");
  // The element count, kept below the file size at each step so it cannot overflow.
  uint64_t count = 1;
  for (uint16_t d = 0; d < rank; ++d) {
    const auto n = in.read<uint64_t>(fmt::format("{}'s size {}", where, d));
    f.shape.push_back(n);
    if (n != 0 && count > bytes.size() / n)
      count = bytes.size() + 1;  // saturate: too large anyway
    else
      count *= n;
  }
  const uint64_t size = count * type_size(f.dtype);
  if (offset > bytes.size() || count > bytes.size() || size > bytes.size() - offset)
    throw TensorFileError(fmt::format("truncated: {} ({}) needs {} bytes at offset {}, the file has {}", where,
                                      f.describe(), count > bytes.size() ? std::string("more") : std::to_string(size),
                                      offset, bytes.size()));
  f.bytes.assign(bytes.data() + offset, bytes.data() + offset + size);
  return f;
}

}  // namespace

const char* tensor_type_name(TensorField::Type t) {
  static const char* names[] = {"invalid", "uint8",  "int8",  "uint16",  "int16",   "uint32",
                                "int32",   "uint64", "int64", "float16", "float32", "float64"};
  return t <= TensorField::Float64 ? names[t] : "invalid";
}

std::vector<float> TensorField::floats() const {
  std::vector<float> v(bytes.size() / sizeof(float));
  if (!v.empty()) std::memcpy(v.data(), bytes.data(), v.size() * sizeof(float));
  return v;
}

std::string TensorField::describe() const {
  std::string dims;
  for (size_t i = 0; i < shape.size(); ++i) dims += (i ? ", " : "") + std::to_string(shape[i]);
  return fmt::format("{} [{}]", tensor_type_name(dtype), dims);
}

TensorFile parse_tensor_file(std::string_view bytes) {
  Cursor in(bytes);
  const std::string magic = in.read_string(12, "the header \"tensor_file\"");
  if (std::memcmp(magic.data(), "tensor_file", 12) != 0)
    throw TensorFileError("not a tensor file: it does not start with \"tensor_file\"");
  const auto major = in.read<uint8_t>("the version"), minor = in.read<uint8_t>("the version");
  if (major != 1 || minor != 0)
    throw TensorFileError(
        fmt::format("tensor file version {}.{}; only 1.0 is known", unsigned(major), unsigned(minor)));
  const auto n_fields = in.read<uint32_t>("the field count");
  TensorFile file;
  for (uint32_t i = 0; i < n_fields; ++i) {
    const auto length = in.read<uint16_t>(fmt::format("field {}'s name length", i));
    const std::string name = in.read_string(length, fmt::format("field {}'s name", i));
    if (file.fields.count(name)) throw TensorFileError(fmt::format("field \"{}\" appears twice", name));
    file.fields.emplace(name, read_field(in, bytes, name));
  }
  return file;
}

TensorFile read_tensor_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TensorFileError("cannot open the file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw TensorFileError("read error");
  return parse_tensor_file(bytes);
}

}  // namespace eyetrace
