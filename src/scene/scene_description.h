// What the parser hands to the scene builder: every directive of a pbrt-v4 scene as a named
// entity with its parameters and transform, before any plugin is created. Keeping this step
// separate lets the command line override the camera or film without touching the file.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/transform.h"
#include "scene/params.h"

namespace eyetrace {

struct SceneEntity {
  std::string name;  // plugin name: "perspective", "trianglemesh", "diffuse", ...
  ParameterList params;
  SourceLoc loc;
};

// The names of a MediumInterface ("" is vacuum) and where it was given, for errors about them.
struct MediumNames {
  std::string inside, outside;
  SourceLoc loc;
};

// Motion blur: an entity whose transform differs between the two TransformTimes keeps both;
// `animated` is false (and the end equals the start) when it does not move.
struct CameraEntity : SceneEntity {
  Transform world_from_camera;  // at the start time
  Transform world_from_camera_end;
  bool animated = false;
  // The TransformTimes in effect at the Camera directive (pbrt-v4 reads them there: a later
  // TransformTimes moves the world's shapes, not the camera).
  float transform_start_time = 0.f, transform_end_time = 1.f;
  MediumNames media;  // the camera sits in `outside` (pbrt-v4)
};

struct TransformedEntity : SceneEntity {
  Transform world_from_object;
  bool reverse_orientation = false;
};

// A material is referenced by index into SceneDescription::materials (anonymous Material
// directives) or by name (MakeNamedMaterial). Exactly one of the two is set on a shape.
struct MaterialRef {
  int index = -1;
  std::string name;
};

struct ShapeEntity : TransformedEntity {
  Transform world_from_object_end;  // world_from_object is the start time's
  bool animated = false;
  MaterialRef material;
  int area_light = -1;  // index into SceneDescription::area_lights, -1 if the shape emits nothing
  MediumNames media;
};

struct TextureEntity : TransformedEntity {
  std::string texture_name;  // the user's name for it
  std::string value_type;    // "float" or "spectrum"
};

struct InstanceDefinition {
  std::string name;
  SourceLoc loc;
  std::vector<ShapeEntity> shapes;  // world_from_object is relative to the instance frame
};

// One ObjectInstance. A scene may hold millions: the transform is shared with the scene that
// places it (render/scene.h) rather than copied, and the end transform is kept only for the few
// that move.
struct InstanceUse {
  std::string name;
  SourceLoc loc;
  std::shared_ptr<const Transform> world_from_instance;      // at the start time; never null
  std::shared_ptr<const Transform> world_from_instance_end;  // null unless it moves
  bool animated() const { return world_from_instance_end != nullptr; }
  const Transform& end_transform() const { return animated() ? *world_from_instance_end : *world_from_instance; }
};

struct SceneDescription {
  bool has_camera = false;
  CameraEntity camera;  // default "perspective" if the file has no Camera
  SceneEntity film{"rgb", {}, {}};
  SceneEntity sampler{"zsobol", {}, {}};
  SceneEntity integrator{"volpath", {}, {}};
  SceneEntity filter{"gaussian", {}, {}};
  std::string color_space = "srgb";
  std::vector<SceneEntity> options;  // Option directives, one parameter each
  // TransformTimes: the times of the start and end transforms (pbrt-v4's defaults 0 and 1).
  float transform_start_time = 0.f, transform_end_time = 1.f;

  std::vector<SceneEntity> materials;                  // anonymous, by index
  std::map<std::string, SceneEntity> named_materials;  // MakeNamedMaterial
  std::vector<TextureEntity> textures;                 // in file order (later may use earlier)
  std::vector<ShapeEntity> shapes;
  std::vector<TransformedEntity> lights;
  std::vector<TransformedEntity> area_lights;      // AreaLightSource, referenced by shapes
  std::map<std::string, TransformedEntity> media;  // MakeNamedMedium; name: the medium's type
  std::map<std::string, InstanceDefinition> instances;
  std::vector<InstanceUse> instance_uses;

  // Relative file names (textures, PLY meshes, lens files) resolve against this directory,
  // the directory of the top-level scene file, as in pbrt-v4.
  std::string search_dir;
};

}  // namespace eyetrace
