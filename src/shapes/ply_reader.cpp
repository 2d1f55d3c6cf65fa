// Strict PLY reading (see ply_reader.h): the header is parsed whole, its counts are checked
// against the data that follows, then each element is read with bounds-checked reads.
#include "shapes/ply_reader.h"

#include <bit>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>

#include <fmt/format.h>

#include "core/gzip.h"

namespace eyetrace {

namespace {

enum class Format { Ascii, LittleEndian, BigEndian };

struct Scalar {
  int size = 0;     // bytes in a binary file
  char kind = 'f';  // 'i' signed integer, 'u' unsigned integer, 'f' floating point
};

struct Property {
  std::string name;
  Scalar value;
  bool is_list = false;
  Scalar count;  // a list's length
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  size_t data_start = 0;
};

bool parse_scalar(const std::string& type, Scalar* s) {
  static const struct {
    const char* name;
    const char* alias;
    Scalar scalar;
  } kTypes[] = {{"char", "int8", {1, 'i'}},     {"uchar", "uint8", {1, 'u'}},   {"short", "int16", {2, 'i'}},
                {"ushort", "uint16", {2, 'u'}}, {"int", "int32", {4, 'i'}},     {"uint", "uint32", {4, 'u'}},
                {"float", "float32", {4, 'f'}}, {"double", "float64", {8, 'f'}}};
  for (const auto& t : kTypes)
    if (type == t.name || type == t.alias) {
      *s = t.scalar;
      return true;
    }
  return false;
}

std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

void add_property(const std::vector<std::string>& w, int line, Header& h) {
  if (h.elements.empty()) throw PlyError(fmt::format("header line {}: a property before any element", line));
  Property p;
  bool ok = w.size() == 3 && parse_scalar(w[1], &p.value);
  if (w.size() == 5 && w[1] == "list") {
    p.is_list = true;
    ok = parse_scalar(w[2], &p.count) && p.count.kind != 'f' && parse_scalar(w[3], &p.value);
  }
  if (!ok) throw PlyError(fmt::format("header line {}: malformed property declaration", line));
  p.name = w.back();
  h.elements.back().properties.push_back(p);
}

void add_element(const std::vector<std::string>& w, int line, Header& h) {
  Element e;
  if (w.size() == 3) e.name = w[1];
  const char* end = w.size() == 3 ? w[2].data() + w[2].size() : nullptr;
  if (!end || std::from_chars(w[2].data(), end, e.count).ptr != end)
    throw PlyError(fmt::format("header line {}: element needs a name and a count (a whole number >= 0)", line));
  h.elements.push_back(e);
}

Header parse_header(const std::string& bytes) {
  Header h;
  size_t pos = 0;
  bool have_format = false;
  for (int line = 1;; ++line) {
    size_t eol = bytes.find('\n', pos);
    if (eol == std::string::npos) throw PlyError("the header has no end_header line");
    std::vector<std::string> w = words_of(bytes.substr(pos, eol - pos));
    pos = eol + 1;
    if (line == 1) {
      if (w.size() != 1 || w[0] != "ply") throw PlyError("not a PLY file (the first line is not \"ply\")");
      continue;
    }
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") break;
    if (w[0] == "format") {
      if (w.size() != 3 || (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
        throw PlyError(fmt::format("header line {}: unsupported format", line));
      h.format = w[1] == "ascii"                  ? Format::Ascii
                 : w[1] == "binary_little_endian" ? Format::LittleEndian
                                                  : Format::BigEndian;
      have_format = true;
    } else if (w[0] == "element") {
      add_element(w, line, h);
    } else if (w[0] == "property") {
      add_property(w, line, h);
    } else {
      throw PlyError(fmt::format("header line {}: unknown keyword \"{}\"", line, w[0]));
    }
  }
  if (!have_format) throw PlyError("the header has no format line");
  h.data_start = pos;
  return h;
}

// The fewest bytes the declared elements can occupy: a header that asks for more than the file
// holds lies about its size, and is refused before anything is allocated.
void check_declared_size(const Header& h, size_t available) {
  for (const Element& e : h.elements) {
    double per_element = 0;  // bytes; lists count as empty
    for (const Property& p : e.properties)
      per_element += h.format == Format::Ascii ? 2.0 : double(p.is_list ? p.count.size : p.value.size);
    // An ascii value is at least a character and a separator (the file's last may lack one).
    double needed = double(e.count) * per_element - (h.format == Format::Ascii ? 1.0 : 0.0);
    if (needed > double(available))
      throw PlyError(
          fmt::format("the header declares {} {} element(s), which need at least {:.0f} bytes, but the "
                      "file holds only {} bytes of data (is the file truncated?)",
                      e.count, e.name, needed, available));
  }
}

// Bounds-checked reading of one value at a time, ascii or binary.
class DataReader {
 public:
  DataReader(const std::string& bytes, const Header& h) : bytes_(bytes), pos_(h.data_start), format_(h.format) {}

  bool read(const Scalar& s, double* v) { return format_ == Format::Ascii ? read_text(v) : read_binary(s, v); }
  size_t remaining() const { return bytes_.size() - pos_; }
  bool binary() const { return format_ != Format::Ascii; }

 private:
  bool read_text(double* v) {
    while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
    size_t start = pos_;
    while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
    if (pos_ == start) return false;
    const char* end = bytes_.data() + pos_;
    auto [ptr, ec] = std::from_chars(bytes_.data() + start, end, *v);
    if (ec == std::errc::result_out_of_range && ptr == end)  // under- or overflow: strtod tells which
      *v = std::strtod(bytes_.substr(start, pos_ - start).c_str(), nullptr);
    else if (ec != std::errc() || ptr != end)
      throw PlyError(fmt::format("\"{}\" is not a number", bytes_.substr(start, std::min<size_t>(pos_ - start, 40))));
    return true;
  }

  bool read_binary(const Scalar& s, double* v) {
    if (remaining() < size_t(s.size)) return false;
    unsigned char b[8];
    std::memcpy(b, bytes_.data() + pos_, s.size);
    pos_ += s.size;
    bool file_little = format_ == Format::LittleEndian;
    if (file_little != (std::endian::native == std::endian::little))
      for (int i = 0; i < s.size / 2; ++i) std::swap(b[i], b[s.size - 1 - i]);
    *v = decode(s, b);
    return true;
  }

  static double decode(const Scalar& s, const unsigned char* b) {
    auto as = [b](auto x) {
      std::memcpy(&x, b, sizeof x);
      return double(x);
    };
    switch (s.size * 4 + (s.kind == 'i' ? 0 : s.kind == 'u' ? 1 : 2)) {
      case 4: return as(int8_t());
      case 5: return as(uint8_t());
      case 8: return as(int16_t());
      case 9: return as(uint16_t());
      case 16: return as(int32_t());
      case 17: return as(uint32_t());
      case 18: return as(float());
      default: return as(double());
    }
  }

  const std::string& bytes_;
  size_t pos_;
  Format format_;
};

int find(const Element& e, std::initializer_list<const char*> names) {
  for (size_t i = 0; i < e.properties.size(); ++i)
    for (const char* n : names)
      if (e.properties[i].name == n && !e.properties[i].is_list) return int(i);
  return -1;
}

[[noreturn]] void truncated(const Element& e, uint64_t i) {
  throw PlyError(fmt::format("the file ends in {} {} of the {} its header declares", e.name, i, e.count));
}

// Reads one element's values; a list's items go to `list` when it is `list_property`.
void read_element(DataReader& r, const Element& e, uint64_t i, std::vector<double>& values, int list_property,
                  std::vector<double>& list) {
  list.clear();
  for (size_t k = 0; k < e.properties.size(); ++k) {
    const Property& p = e.properties[k];
    if (!p.is_list) {
      if (!r.read(p.value, &values[k])) truncated(e, i);
      continue;
    }
    double n = 0;
    if (!r.read(p.count, &n)) truncated(e, i);
    if (!(n >= 0 && n == std::floor(n) && n <= double(INT_MAX)))
      throw PlyError(fmt::format("{} {}: list length {} is not a count", e.name, i, n));
    if (r.binary() && double(n) * p.value.size > double(r.remaining())) truncated(e, i);
    for (int64_t j = 0; j < int64_t(n); ++j) {
      double v = 0;
      if (!r.read(p.value, &v)) truncated(e, i);
      if (int(k) == list_property) list.push_back(v);
    }
  }
}

void read_vertices(DataReader& r, const Element& e, MeshData& mesh) {
  const int x = find(e, {"x"}), y = find(e, {"y"}), z = find(e, {"z"});
  if (x < 0 || y < 0 || z < 0) throw PlyError("the vertex element has no x, y and z properties");
  const int nx = find(e, {"nx"}), ny = find(e, {"ny"}), nz = find(e, {"nz"});
  const int u = find(e, {"u", "s", "texture_u", "texture_s"}), v = find(e, {"v", "t", "texture_v", "texture_t"});
  const bool normals = nx >= 0 && ny >= 0 && nz >= 0, uvs = u >= 0 && v >= 0;
  std::vector<double> values(e.properties.size()), unused;
  mesh.positions.reserve(e.count);  // bounded by the file's size (check_declared_size)
  for (uint64_t i = 0; i < e.count; ++i) {
    read_element(r, e, i, values, -1, unused);
    mesh.positions.emplace_back(float(values[x]), float(values[y]), float(values[z]));
    if (normals) mesh.normals.emplace_back(float(values[nx]), float(values[ny]), float(values[nz]));
    if (uvs) mesh.uvs.emplace_back(float(values[u]), float(values[v]));
  }
}

void read_faces(DataReader& r, const Element& e, MeshData& mesh) {
  int list = -1;
  for (size_t k = 0; k < e.properties.size(); ++k)
    if (e.properties[k].is_list && (e.properties[k].name == "vertex_indices" || e.properties[k].name == "vertex_index"))
      list = int(k);
  if (list < 0) throw PlyError("the face element has no vertex_indices list");
  std::vector<double> values(e.properties.size()), polygon;
  for (uint64_t i = 0; i < e.count; ++i) {
    read_element(r, e, i, values, list, polygon);
    for (double index : polygon)
      if (index != std::floor(index) || std::abs(index) > double(INT_MAX))
        throw PlyError(fmt::format("face {}: vertex index {} is not an integer", i, index));
    // Points and lines have no area; polygons become a fan of triangles.
    for (size_t k = 1; k + 1 < polygon.size(); ++k)
      mesh.indices.insert(mesh.indices.end(), {int(polygon[0]), int(polygon[k]), int(polygon[k + 1])});
  }
}

}  // namespace

MeshData parse_ply(const std::string& bytes) {
  Header h = parse_header(bytes);
  check_declared_size(h, bytes.size() - h.data_start);
  DataReader r(bytes, h);
  MeshData mesh;
  bool have_vertices = false;
  for (const Element& e : h.elements) {
    if (e.name == "vertex") {
      if (have_vertices) throw PlyError("the file has two vertex elements");
      read_vertices(r, e, mesh);
      have_vertices = true;
    } else if (e.name == "face") {
      read_faces(r, e, mesh);
    } else if (!e.properties.empty()) {  // an element of no properties occupies no bytes
      std::vector<double> values(e.properties.size()), unused;
      for (uint64_t i = 0; i < e.count; ++i) read_element(r, e, i, values, -1, unused);
    }
  }
  if (!have_vertices) throw PlyError("the file has no vertex element");
  return mesh;
}

MeshData read_ply_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw PlyError("cannot open it");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw PlyError("read error");
  // pbrt-v4 scenes ship large meshes as .ply.gz; the magic bytes decide, not the name.
  if (is_gzip(bytes)) {
    std::string error;
    std::optional<std::string> inflated = gunzip(bytes, &error);
    if (!inflated) throw PlyError("gzip-compressed file: " + error);
    return parse_ply(*inflated);
  }
  return parse_ply(bytes);
}

}  // namespace eyetrace
