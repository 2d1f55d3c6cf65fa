// Build-time data embedded into the library (tools/rgb2spec_opt, tools/pmj02bn_tables): a host
// tool writes its data as a binary file and a C++ file whose assembler text pulls labelled slices
// of that binary into .rodata with .incbin, so that compiling it takes no time. Header-only: each
// tool is one source file.
#pragma once
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "core/fnv1a.h"

namespace eyetrace::embed {

// One labelled slice of the binary: the symbol `name` covers bytes [offset, offset + size).
struct Slice {
  const char* name;
  size_t offset, size;
};

// Writes size bytes to path; false if the file cannot be written completely.
inline bool write_file(const std::string& path, const void* data, size_t size) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  const bool ok = std::fwrite(data, 1, size, f) == size;
  return std::fclose(f) == 0 && ok;
}

// The C++ file embedding `slices` of the binary at bin_path (whose content is bytes) in the
// section .rodata.<section>, 64-byte aligned. `comment` opens the file (each line "// ...\n").
// The checksum is part of the assembler text so that the preprocessed source changes whenever
// the data do (ccache).
inline std::string incbin_source(const std::string& comment, const std::string& section, const std::string& bin_path,
                                 const std::vector<unsigned char>& bytes, const std::vector<Slice>& slices) {
  std::string path;  // a backslash for C++ and one for the assembler before \ and "
  for (char ch : bin_path) {
    if (ch == '\\' || ch == '"') path += "\\\\\\";
    path += ch;
  }
  const auto sum = static_cast<unsigned long long>(
      fnv1a(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size())));
  char line[1024];
  std::string cpp = comment;
  std::snprintf(line, sizeof line, "// %zu bytes, FNV-1a 0x%016llx\n__asm__(\n    \"# %s, FNV-1a 0x%016llx\\n\"\n",
                bytes.size(), sum, section.c_str(), sum);
  cpp += line;
  cpp += "    \"\\t.pushsection .rodata." + section + ", \\\"a\\\", @progbits\\n\"\n";
  cpp += "    \"\\t.balign 64\\n\"\n";
  for (const Slice& s : slices) {
    std::snprintf(line, sizeof line, "    \"\\t.globl %s\\n\\t.type %s, @object\\n%s:\\n\"\n", s.name, s.name, s.name);
    cpp += line;
    std::snprintf(line, sizeof line, "    \"\\t.incbin \\\"%s\\\", %zu, %zu\\n\"\n", path.c_str(), s.offset, s.size);
    cpp += line;
    std::snprintf(line, sizeof line, "    \"\\t.size %s, %zu\\n\"\n", s.name, s.size);
    cpp += line;
  }
  cpp += "    \"\\t.popsection\\n\");\n";
  return cpp;
}

// Writes the binary and its C++ file; prints what failed (prefixed by tool) and returns false.
inline bool write_embedded(const char* tool, const std::string& bin_path, const std::string& cpp_path,
                           const std::vector<unsigned char>& bytes, const std::string& comment,
                           const std::string& section, const std::vector<Slice>& slices) {
  if (!write_file(bin_path, bytes.data(), bytes.size())) {
    std::fprintf(stderr, "%s: cannot write %s\n", tool, bin_path.c_str());
    return false;
  }
  const std::string cpp = incbin_source(comment, section, bin_path, bytes, slices);
  if (!write_file(cpp_path, cpp.data(), cpp.size())) {
    std::fprintf(stderr, "%s: cannot write %s\n", tool, cpp_path.c_str());
    return false;
  }
  return true;
}

}  // namespace eyetrace::embed
