// Import, as pbrt-v4 parses it (parser.cpp, scene.cpp: CopyForImport, MergeImported): each
// imported file by a parser of its own that starts from a copy of the importing file's
// graphics state, a large file on a task of its own; what it defines is merged in the order of
// the Import statements, so that the scene (its shapes' order, the materials' and area
// lights' numbers, the errors and warnings) is the one a parse in order would make.
#include <set>

#include "scene/scene_parser.h"

namespace eyetrace::parsing {

SceneParser::SceneParser(const SceneParser& parent, const std::vector<std::string>& ancestors)
    : options_(parent.options_),
      state_(parent.state_),
      coordinate_systems_(parent.coordinate_systems_),
      texture_names_(parent.texture_names_),
      named_material_locs_(parent.named_material_locs_),
      medium_locs_(parent.medium_locs_),
      instance_locs_(parent.instance_locs_),
      current_object_(parent.current_object_),
      in_world_(true),
      warned_transform_begin_(parent.warned_transform_begin_),
      material_base_(parent.material_base_ + int(parent.desc_.materials.size())),
      area_light_base_(parent.area_light_base_ + int(parent.desc_.area_lights.size())),
      is_import_(true),
      ancestors_(ancestors) {
  desc_.search_dir = parent.desc_.search_dir;
  desc_.transform_start_time = parent.desc_.transform_start_time;
  desc_.transform_end_time = parent.desc_.transform_end_time;
  desc_.color_space = parent.desc_.color_space;
}

SceneParser::~SceneParser() {
  // The tasks hold pointers to the parsers in pending_: they must end first.
  if (!tasks_) return;
  try {
    tasks_->wait();
  } catch (...) {  // a destructor does not throw; a failure was either reported or is moot
  }
}

void SceneParser::import(Tokenizer& tok, const SourceLoc& loc) {
  require_world(loc, "Import");  // pbrt-v4: "Import statement only allowed inside world definition block"
  fs::path path = included_file(tok, loc, "Import");
  std::vector<std::string> ancestors = ancestors_;
  for (const TokenFile* f : tok.open_files()) ancestors.push_back(f->canonical);
  auto pending = std::make_unique<PendingImport>();
  pending->child.reset(new SceneParser(*this, ancestors));
  pending->shapes_at = desc_.shapes.size();
  pending->errors_at = errors_.kept().size();
  pending->warnings_at = warnings_.size();
  SceneParser* child = pending->child.get();
  pending_.push_back(std::move(pending));

  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size >= options_.import_task_min_bytes) {
    if (!tasks_) tasks_ = std::make_unique<tbb::task_group>();
    tasks_->run([child, path, loc] { child->import_file(path, loc); });
    return;
  }
  child->import_file(path, loc);
  if (pending_.size() == 1) sync();  // nothing runs before it: merge it now
}

// Runs on the import's task. Its errors are its own (errors_) until merged; anything but a
// SceneError is kept for sync() to throw in the importing parser's thread.
void SceneParser::import_file(const fs::path& path, const SourceLoc& at) {
  WarningCapture capture(&warnings_);
  try {
    Tokenizer tok(read_scene_text(path, &at), token_file(path));
    run(tok);
    sync();
    check_import_end();
  } catch (const SceneError& e) {
    errors_.add_all(e.diagnostics());
  } catch (...) {
    failure_ = std::current_exception();
  }
}

// pbrt-v4's MergeImported reports blocks left open by an imported file ("Missing end to
// AttributeBegin"): its graphics state ends with it.
void SceneParser::check_import_end() {
  if (cut_short_ || blocks_.empty()) return;
  const OpenBlock& b = blocks_.back();
  const char* closer = b.directive == "ObjectBegin"      ? "ObjectEnd"
                       : b.directive == "TransformBegin" ? "TransformEnd"
                                                         : "AttributeEnd";
  errors_.add(
      Diagnostic{b.loc, "", Severity::Error,
                 fmt::format("{} has no matching {} before the end of the imported file", b.directive, closer)});
}

// Directives that read or define nothing an Import may define, and add nothing whose place
// among the imports' additions matters, except shapes (whose places are kept): the parse goes
// on past pending imports with these.
bool SceneParser::needs_imports_merged(std::string_view directive) const {
  static const std::set<std::string_view> independent = {"Include",         "Import",           "AttributeBegin",
                                                         "AttributeEnd",    "TransformEnd",     "Attribute",
                                                         "Translate",       "Rotate",           "Scale",
                                                         "LookAt",          "Transform",        "ConcatTransform",
                                                         "Identity",        "CoordinateSystem", "CoordSysTransform",
                                                         "ActiveTransform", "MediumInterface",  "ReverseOrientation",
                                                         "WorldEnd"};
  if (directive == "Shape") return current_object_.has_value();        // into an instance: its order
  if (directive == "TransformBegin") return !warned_transform_begin_;  // warned once: by whom
  return !independent.count(directive);
}

void SceneParser::sync() {
  if (!pending_.empty()) {
    if (tasks_) tasks_->wait();
    for (const auto& p : pending_)
      if (p->child->failure_) std::rethrow_exception(p->child->failure_);
    size_t shapes_shift = 0, warnings_shift = 0;
    for (const auto& p : pending_) {
      const size_t shapes = p->child->desc_.shapes.size(), warnings = p->child->warnings_.size();
      merge(*p->child, p->shapes_at + shapes_shift, p->warnings_at + warnings_shift);
      shapes_shift += shapes;
      warnings_shift += warnings;
    }
    // The last first: a splice moves only what stands after its own place.
    for (auto it = pending_.rbegin(); it != pending_.rend(); ++it)
      errors_.splice((*it)->errors_at, (*it)->child->errors_);
    pending_.clear();
  }
  if (!is_import_) deliver_root_warnings();
}

void SceneParser::deliver_root_warnings() {
  deliver_warnings(warnings_);
  warnings_.clear();
}

namespace {

template <typename T>
void append(std::vector<T>& to, std::vector<T>& from) {
  to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
  from.clear();
}

template <typename T>
void insert_at(std::vector<T>& to, size_t at, std::vector<T>& from) {
  to.insert(to.begin() + std::ptrdiff_t(at), std::make_move_iterator(from.begin()),
            std::make_move_iterator(from.end()));
  from.clear();
}

Diagnostic redefined(const SourceLoc& loc, const std::string& what, const SourceLoc& first) {
  return Diagnostic{loc, "", Severity::Error, fmt::format("{} is already defined at {}", what, first.to_string())};
}

}  // namespace

// While imports are pending this parser adds no material, area light, named thing, texture,
// light or instance (those directives sync() first): the child's additions go after all of
// this parser's, renumbered past the siblings merged before it. A name an earlier sibling
// defined too is an error at the child's definition (pbrt-v4: "multiply defined"), the first
// definition kept.
void SceneParser::merge(SceneParser& child, size_t shapes_at, size_t warnings_at) {
  SceneDescription& c = child.desc_;
  const int material_shift = material_base_ + int(desc_.materials.size()) - child.material_base_;
  const int light_shift = area_light_base_ + int(desc_.area_lights.size()) - child.area_light_base_;
  auto renumber = [&](ShapeEntity& s) {
    if (s.material.index >= child.material_base_) s.material.index += material_shift;
    if (s.area_light >= child.area_light_base_) s.area_light += light_shift;
  };
  for (ShapeEntity& s : c.shapes) renumber(s);
  for (auto& [name, def] : c.instances)
    for (ShapeEntity& s : def.shapes) renumber(s);
  append(desc_.materials, c.materials);
  append(desc_.area_lights, c.area_lights);

  for (auto& [name, m] : c.named_materials) {
    auto [it, fresh] = named_material_locs_.emplace(name, m.loc);
    if (!fresh) {
      child.errors_.add(redefined(m.loc, fmt::format("MakeNamedMaterial: material \"{}\"", name), it->second));
      continue;
    }
    desc_.named_materials[name] = std::move(m);
  }
  for (TextureEntity& t : c.textures) {
    auto [it, fresh] = texture_names_.emplace(std::pair(t.texture_name, t.value_type), t.loc);
    if (!fresh) {
      child.errors_.add(
          redefined(t.loc, fmt::format("Texture: {} texture \"{}\"", t.value_type, t.texture_name), it->second));
      continue;
    }
    desc_.textures.push_back(std::move(t));
  }
  for (auto& [name, m] : c.media) {
    auto [it, fresh] = medium_locs_.emplace(name, m.loc);
    if (!fresh) {
      child.errors_.add(redefined(m.loc, fmt::format("MakeNamedMedium: medium \"{}\"", name), it->second));
      continue;
    }
    desc_.media[name] = std::move(m);
  }
  for (auto& [name, def] : c.instances) {
    if (def.name.empty()) {  // shapes of an ObjectBegin open in the importing file
      append(desc_.instances[name].shapes, def.shapes);
      continue;
    }
    auto [it, fresh] = instance_locs_.emplace(name, def.loc);
    if (!fresh) {
      child.errors_.add(redefined(def.loc, fmt::format("ObjectBegin: object \"{}\"", name), it->second));
      continue;
    }
    desc_.instances[name] = std::move(def);
  }
  append(desc_.lights, c.lights);
  append(desc_.instance_uses, c.instance_uses);
  append(desc_.options, c.options);
  insert_at(desc_.shapes, shapes_at, c.shapes);
  insert_at(warnings_, warnings_at, child.warnings_);
  if (child.color_space_set_) {
    desc_.color_space = c.color_space;
    color_space_set_ = true;
  }
  warned_transform_begin_ = warned_transform_begin_ || child.warned_transform_begin_;
  import_cut_short_ = import_cut_short_ || child.cut_short_ || child.import_cut_short_;
}

}  // namespace eyetrace::parsing
