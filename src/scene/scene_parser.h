// The pbrt-v4 scene parser's state machine, shared by parser.cpp (files, Include, the
// directive loop) and scene_parser.cpp (one handler per directive). Internal to the parser:
// everything else uses core/parser.h.
#pragma once
#include <array>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <tbb/task_group.h>

#include "scene/parser.h"
#include "scene/scene_description.h"
#include "scene/tokenizer.h"

namespace eyetrace::parsing {

namespace fs = std::filesystem;

inline constexpr size_t kMaxIncludeDepth = 64;

// pbrt keeps two transforms, at the two TransformTimes, so that ActiveTransform can animate
// between them (motion blur).
using TransformPair = std::array<Transform, 2>;

struct GraphicsState {
  TransformPair ctm;
  std::array<bool, 2> active{true, true};
  bool reverse_orientation = false;
  MaterialRef material{0, ""};  // index 0 is the implicit default material
  // Where a Transform or ConcatTransform made the CTM singular (ctm then keeps its value from
  // before): the shapes under it are dropped with a warning, anything else there is an error.
  std::optional<SourceLoc> singular_at;
  int area_light = -1;
  MediumNames media;  // the current MediumInterface
  std::vector<Param> shape_attributes, light_attributes, material_attributes, texture_attributes;
};

// One open AttributeBegin, TransformBegin or ObjectBegin.
struct OpenBlock {
  std::string directive;
  SourceLoc loc;
  GraphicsState saved;
};

inline std::string hint_suffix(const std::string& word, const std::vector<std::string>& candidates) {
  std::string m = closest_match(word, candidates);
  return m.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", m);
}

template <typename Map>
std::vector<std::string> keys_of(const Map& m) {
  std::vector<std::string> keys;
  for (const auto& kv : m) keys.emplace_back(kv.first);
  return keys;
}

class SceneParser {
 public:
  SceneParser(fs::path search_dir, const ParseOptions& options);
  ~SceneParser();
  SceneParser(const SceneParser&) = delete;
  SceneParser& operator=(const SceneParser&) = delete;
  void parse_file(const fs::path& path);
  void parse_text(std::string text, const std::string& filename);
  SceneDescription finish(const std::string& top_file);
  ParsedScene finish_collecting(const std::string& top_file);

 private:
  using Handler = void (SceneParser::*)(Tokenizer&, const SourceLoc&);
  static const std::map<std::string, Handler, std::less<>>& handlers();

  // Import (scene_import.cpp). pbrt-v4's CopyForImport: an imported file is parsed by a parser
  // of its own that starts from a copy of the graphics state at the Import (and the names
  // defined so far), on a task of its own when the file is large. What it defines is merged
  // into this parser in the order of the Import statements (pbrt-v4's MergeImported), so the
  // scene is the one a parse in order would make. Until then this parser goes on only with
  // directives that need nothing the imports define (shapes, transforms, blocks);
  // any other first waits for them and merges them (sync()).
  struct PendingImport;
  SceneParser(const SceneParser& parent, const std::vector<std::string>& ancestors);
  void import_file(const fs::path& path, const SourceLoc& at);
  bool needs_imports_merged(std::string_view directive) const;
  void sync();
  void merge(SceneParser& child, size_t shapes_at, size_t warnings_at);
  void check_import_end();
  void deliver_root_warnings();

  void run(Tokenizer& tok);
  void check_end(const std::string& top_file);
  bool skip_to_directive(Tokenizer& tok);
  [[noreturn]] void unknown_directive(const Token& t, const SourceLoc& loc) const;

  // Reading helpers.
  std::string read_name(Tokenizer& tok, const char* directive, const char* what, SourceLoc* at = nullptr);
  std::vector<float> read_numbers(Tokenizer& tok, const char* directive, size_t count);
  SceneEntity read_entity(Tokenizer& tok, const SourceLoc& loc, const char* directive);
  static ParameterList with_attributes(ParameterList list, const std::vector<Param>& attributes);

  // Block and transform state.
  void require_world(const SourceLoc& loc, const char* directive) const;
  void require_options(const SourceLoc& loc, const char* directive) const;
  void note_option(const SourceLoc& loc, const char* directive);
  void apply(const SourceLoc& loc, const char* directive, const Transform& t, bool replace = false);
  Transform current_transform(const SourceLoc& loc, const char* directive) const;
  // Both transforms, for the directives that may move (Shape, ObjectInstance, Camera); true in
  // `animated` when they differ (checked to be interpolable, else an error at loc).
  TransformPair current_transforms(const SourceLoc& loc, const char* directive, bool* animated) const;
  void push_block(const SourceLoc& loc, const char* directive);
  void pop_block(const SourceLoc& loc, const char* directive, const char* opener);
  fs::path resolve_include(const std::string& name, const SourceLoc& loc, const char* directive,
                           const fs::path& dir) const;
  static std::string read_scene_text(const fs::path& path, const SourceLoc* included_from);
  static TokenFile token_file(const fs::path& path);

  // Directives.
  void include(Tokenizer& tok, const SourceLoc& loc);
  void import(Tokenizer& tok, const SourceLoc& loc);
  // The file an Include or Import names, checked against recursion and the nesting limit.
  fs::path included_file(Tokenizer& tok, const SourceLoc& loc, const char* directive);
  void attribute_begin(Tokenizer&, const SourceLoc& loc);
  void attribute_end(Tokenizer&, const SourceLoc& loc);
  void transform_begin(Tokenizer&, const SourceLoc& loc);
  void transform_end(Tokenizer&, const SourceLoc& loc);
  void attribute(Tokenizer& tok, const SourceLoc& loc);
  void translate(Tokenizer& tok, const SourceLoc& loc);
  void rotate(Tokenizer& tok, const SourceLoc& loc);
  void scale(Tokenizer& tok, const SourceLoc& loc);
  void look_at(Tokenizer& tok, const SourceLoc& loc);
  void transform(Tokenizer& tok, const SourceLoc& loc) { matrix_directive(tok, loc, "Transform", true); }
  void concat_transform(Tokenizer& tok, const SourceLoc& loc) { matrix_directive(tok, loc, "ConcatTransform", false); }
  void matrix_directive(Tokenizer& tok, const SourceLoc& loc, const char* directive, bool replace);
  void identity(Tokenizer&, const SourceLoc& loc) { apply(loc, "Identity", Transform(), true); }
  void coordinate_system(Tokenizer& tok, const SourceLoc& loc);
  void coord_sys_transform(Tokenizer& tok, const SourceLoc& loc);
  void reverse_orientation(Tokenizer&, const SourceLoc& loc);
  void active_transform(Tokenizer& tok, const SourceLoc& loc);
  void transform_times(Tokenizer& tok, const SourceLoc& loc);
  void camera(Tokenizer& tok, const SourceLoc& loc);
  void film(Tokenizer& tok, const SourceLoc& loc) { option_entity(tok, loc, "Film", desc_.film); }
  void sampler(Tokenizer& tok, const SourceLoc& loc) { option_entity(tok, loc, "Sampler", desc_.sampler); }
  void integrator(Tokenizer& tok, const SourceLoc& loc) { option_entity(tok, loc, "Integrator", desc_.integrator); }
  void pixel_filter(Tokenizer& tok, const SourceLoc& loc) { option_entity(tok, loc, "PixelFilter", desc_.filter); }
  void option_entity(Tokenizer& tok, const SourceLoc& loc, const char* directive, SceneEntity& out);
  void accelerator(Tokenizer& tok, const SourceLoc& loc);
  void color_space(Tokenizer& tok, const SourceLoc& loc);
  void option(Tokenizer& tok, const SourceLoc& loc);
  void world_begin(Tokenizer&, const SourceLoc& loc);
  void world_end(Tokenizer&, const SourceLoc& loc);
  void light_source(Tokenizer& tok, const SourceLoc& loc);
  void area_light_source(Tokenizer& tok, const SourceLoc& loc);
  void material(Tokenizer& tok, const SourceLoc& loc);
  void make_named_material(Tokenizer& tok, const SourceLoc& loc);
  void named_material(Tokenizer& tok, const SourceLoc& loc);
  void texture(Tokenizer& tok, const SourceLoc& loc);
  void shape(Tokenizer& tok, const SourceLoc& loc);
  void object_begin(Tokenizer& tok, const SourceLoc& loc);
  void object_end(Tokenizer&, const SourceLoc& loc);
  void object_instance(Tokenizer& tok, const SourceLoc& loc);
  void make_named_medium(Tokenizer& tok, const SourceLoc& loc);
  void medium_interface(Tokenizer& tok, const SourceLoc& loc);

  ParseOptions options_;
  SceneDescription desc_;
  GraphicsState state_;
  std::vector<OpenBlock> blocks_;
  std::map<std::string, TransformPair> coordinate_systems_;
  std::map<std::string, SourceLoc> options_seen_;
  std::map<std::pair<std::string, std::string>, SourceLoc> texture_names_;
  std::map<std::string, SourceLoc> named_material_locs_, medium_locs_, instance_locs_;
  std::optional<std::string> current_object_;
  DiagnosticList errors_;   // every failed directive, reported together by finish()
  bool cut_short_ = false;  // an error ended the parse before the end of the text
  bool in_world_ = false;
  bool warned_transform_begin_ = false;

  // An imported file's parser numbers its anonymous materials and area lights on from the
  // importing parser's (desc_ holds only its own); merge() renumbers them.
  int material_base_ = 0, area_light_base_ = 0;
  bool is_import_ = false;
  bool color_space_set_ = false;        // by a ColorSpace directive in this file
  bool import_cut_short_ = false;       // an imported file's text was cut short by an error
  std::vector<std::string> ancestors_;  // canonical names of the files importing this one
  std::vector<Diagnostic> warnings_;    // this file's warnings, delivered in statement order
  std::exception_ptr failure_;          // what a task ended with that is not a SceneError
  std::vector<std::unique_ptr<PendingImport>> pending_;
  std::unique_ptr<tbb::task_group> tasks_;
};

// An Import parsed (or being parsed) by `child`, and where its shapes, errors and warnings go
// in this parser's lists: where they stood at the Import.
struct SceneParser::PendingImport {
  std::unique_ptr<SceneParser> child;
  size_t shapes_at = 0, errors_at = 0, warnings_at = 0;
};

}  // namespace eyetrace::parsing
