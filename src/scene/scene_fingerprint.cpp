#include "scene/scene_fingerprint.h"

#include <cstring>
#include <fstream>

#include "core/error.h"
#include "core/fnv1a.h"

namespace eyetrace {

namespace {

// Hashes a scene description field by field; values enter as their exact bits.
class Fingerprint {
 public:
  void add(std::string_view s) {
    uint64_t n = s.size();
    h_ = fnv1a(std::string_view(reinterpret_cast<const char*>(&n), sizeof n), h_);
    h_ = fnv1a(s, h_);
  }
  template <typename T>
  void add_pod(const T& v) {
    h_ = fnv1a(std::string_view(reinterpret_cast<const char*>(&v), sizeof v), h_);
  }
  void add(const ParameterList& params) {
    add_pod(params.params().size());
    for (const Param& p : params.params()) {
      add(p.type);
      add(p.name);
      add_pod(p.numbers.size());
      for (double v : p.numbers) add_pod(v);
      add_pod(p.strings.size());
      for (const std::string& s : p.strings) add(s);
      add_pod(p.bools.size());
      for (bool b : p.bools) add_pod(b);
    }
  }
  void add(const Transform& t) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) add_pod(t.matrix()[c][r]);
  }
  void add(const SceneEntity& e) {
    add(e.name);
    add(e.params);
  }
  void add(const TransformedEntity& e) {
    add(static_cast<const SceneEntity&>(e));
    add(e.world_from_object);
    add_pod(e.reverse_orientation);
  }
  void add(const ShapeEntity& s) {
    add(static_cast<const TransformedEntity&>(s));
    add_pod(s.material.index);
    add(s.material.name);
    add_pod(s.area_light);
    if (s.animated) add(s.world_from_object_end);  // static scenes keep their earlier fingerprints
  }
  template <typename T>
  void add_all(const std::vector<T>& v) {
    add_pod(v.size());
    for (const T& e : v) add(e);
  }
  // The file's bytes, read in blocks (meshes can be large).
  void add_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw_error(fmt::format("cannot read \"{}\" to fingerprint the scene", path));
    std::vector<char> block(1 << 20);
    while (in.read(block.data(), std::streamsize(block.size())) || in.gcount() > 0)
      h_ = fnv1a(std::string_view(block.data(), size_t(in.gcount())), h_);
  }
  uint64_t value() const { return h_; }

 private:
  uint64_t h_ = fnv1a("");
};

}  // namespace

uint64_t scene_fingerprint(const SceneDescription& d, const std::string& options,
                           const std::vector<std::string>& files_read) {
  Fingerprint f;
  f.add(options);
  f.add_pod(d.has_camera);
  f.add(d.camera);
  f.add(d.camera.world_from_camera);
  if (d.camera.animated) {
    f.add(d.camera.world_from_camera_end);
    f.add_pod(d.camera.transform_start_time);
    f.add_pod(d.camera.transform_end_time);
  }
  // The times matter only to what moves (and only then change the fingerprint).
  bool moves = d.camera.animated;
  for (const ShapeEntity& s : d.shapes) moves = moves || s.animated;
  for (const InstanceUse& u : d.instance_uses) moves = moves || u.animated();
  if (moves) {
    f.add_pod(d.transform_start_time);
    f.add_pod(d.transform_end_time);
  }
  for (const SceneEntity* e : {&d.film, &d.sampler, &d.integrator, &d.filter}) f.add(*e);
  f.add(d.color_space);
  f.add_all(d.options);
  f.add_all(d.materials);
  for (const auto& [name, m] : d.named_materials) {
    f.add(name);
    f.add(m);
  }
  f.add_pod(d.textures.size());
  for (const TextureEntity& t : d.textures) {
    f.add(static_cast<const TransformedEntity&>(t));
    f.add(t.texture_name);
    f.add(t.value_type);
  }
  f.add_all(d.shapes);
  f.add_all(d.lights);
  f.add_all(d.area_lights);
  for (const auto& [name, def] : d.instances) {
    f.add(name);
    f.add_all(def.shapes);
  }
  for (const InstanceUse& u : d.instance_uses) {
    f.add(u.name);
    f.add(*u.world_from_instance);
    if (u.animated()) f.add(*u.world_from_instance_end);
  }
  f.add(d.search_dir);
  f.add_pod(files_read.size());
  for (const std::string& path : files_read) {
    f.add(path);
    f.add_file(path);
  }
  return f.value();
}

}  // namespace eyetrace
