// The one registration list: every built-in plugin, one line each.
#include "cameras/lens_system_camera.h"
#include "cameras/perspective_camera.h"
#include "filters/box_filter.h"
#include "filters/gaussian_filter.h"
#include "filters/mitchell_filter.h"
#include "filters/triangle_filter.h"
#include "integrators/path_integrator.h"
#include "lights/diffuse_area_light.h"
#include "lights/distant_light.h"
#include "lights/infinite_light.h"
#include "lights/point_light.h"
#include "lights/spot_light.h"
#include "materials/coated_diffuse_material.h"
#include "materials/conductor_material.h"
#include "materials/dielectric_material.h"
#include "materials/diffuse_material.h"
#include "materials/interface_material.h"
#include "optics/eye_models.h"
#include "samplers/halton_sampler.h"
#include "samplers/independent_sampler.h"
#include "samplers/sobol_sampler.h"
#include "samplers/stratified_sampler.h"
#include "samplers/zsobol_sampler.h"
#include "scene/registry.h"
#include "shapes/bilinear_mesh.h"
#include "shapes/disk.h"
#include "shapes/ply_mesh.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"
#include "textures/checkerboard_texture.h"
#include "textures/constant_texture.h"
#include "textures/imagemap_texture.h"
#include "textures/mix_texture.h"
#include "textures/scale_texture.h"

namespace eyetrace {

void register_builtin_plugins(Registry& r) {
  r.cameras["perspective"] = create_perspective_camera;
  r.cameras["pinhole"] = create_pinhole_camera;
  r.cameras["thinlens"] = create_thinlens_camera;
  r.cameras["eye"] = create_eye_camera;
  for (const std::string& model : optics::eye_model_names()) r.cameras[model] = create_named_eye_camera(model);
  r.cameras["realistic"] = create_realistic_camera;

  r.samplers["independent"] = create_independent_sampler;
  r.samplers["stratified"] = create_stratified_sampler;
  r.samplers["halton"] = create_halton_sampler;
  r.samplers["sobol"] = create_sobol_sampler;
  r.samplers["zsobol"] = create_zsobol_sampler;

  r.filters["box"] = create_box_filter;
  r.filters["gaussian"] = create_gaussian_filter;
  r.filters["triangle"] = create_triangle_filter;
  r.filters["mitchell"] = create_mitchell_filter;

  r.shapes["trianglemesh"] = create_trianglemesh_shapes;
  r.shapes["plymesh"] = create_plymesh_shapes;
  r.shapes["bilinearmesh"] = create_bilinearmesh_shapes;
  r.shapes["sphere"] = create_sphere_shapes;
  r.shapes["disk"] = create_disk_shapes;

  r.materials["diffuse"] = create_diffuse_material;
  r.materials["coateddiffuse"] = create_coateddiffuse_material;
  r.materials["conductor"] = create_conductor_material;
  r.materials["dielectric"] = create_dielectric_material;
  r.materials["interface"] = create_interface_material;

  r.float_textures["imagemap"] = create_imagemap_float_texture;
  r.float_textures["checkerboard"] = create_checkerboard_float_texture;
  r.float_textures["constant"] = create_constant_float_texture;
  r.float_textures["scale"] = create_scale_float_texture;
  r.float_textures["mix"] = create_mix_float_texture;
  r.spectrum_textures["imagemap"] = create_imagemap_spectrum_texture;
  r.spectrum_textures["checkerboard"] = create_checkerboard_spectrum_texture;
  r.spectrum_textures["constant"] = create_constant_spectrum_texture;
  r.spectrum_textures["scale"] = create_scale_spectrum_texture;
  r.spectrum_textures["mix"] = create_mix_spectrum_texture;

  r.lights["point"] = create_point_light;
  r.lights["spot"] = create_spot_light;
  r.lights["distant"] = create_distant_light;
  r.lights["infinite"] = create_infinite_light;
  r.area_lights["diffuse"] = create_diffuse_area_light;

  r.integrators["path"] = create_path_integrator;
  r.integrators["direct"] = create_direct_integrator;
  r.integrators["volpath"] = create_volpath_integrator;
}

const Registry& Registry::builtin() {
  static const Registry registry = [] {
    Registry r;
    register_builtin_plugins(r);
    return r;
  }();
  return registry;
}

}  // namespace eyetrace
