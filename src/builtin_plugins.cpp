// The one registration list: every built-in plugin, one line each.
#include "cameras/eye_params.h"
#include "cameras/lens_system_camera.h"
#include "cameras/orthographic_camera.h"
#include "cameras/perspective_camera.h"
#include "cameras/spherical_camera.h"
#include "filters/box_filter.h"
#include "filters/gaussian_filter.h"
#include "filters/mitchell_filter.h"
#include "filters/sinc_filter.h"
#include "filters/triangle_filter.h"
#include "integrators/bdpt_integrator.h"
#include "integrators/path_integrator.h"
#include "integrators/sppm_integrator.h"
#include "lights/diffuse_area_light.h"
#include "lights/distant_light.h"
#include "lights/goniometric_light.h"
#include "lights/infinite_light.h"
#include "lights/point_light.h"
#include "lights/projection_light.h"
#include "lights/spot_light.h"
#include "materials/coated_conductor_material.h"
#include "materials/coated_diffuse_material.h"
#include "materials/conductor_material.h"
#include "materials/dielectric_material.h"
#include "materials/diffuse_material.h"
#include "materials/diffuse_transmission_material.h"
#include "materials/hair_material.h"
#include "materials/interface_material.h"
#include "materials/measured_material.h"
#include "materials/mix_material.h"
#include "materials/subsurface_material.h"
#include "materials/thin_dielectric_material.h"
#include "media/cloud_medium.h"
#include "media/grid_medium.h"
#include "media/homogeneous_medium.h"
#include "media/nanovdb_medium.h"
#include "media/rgb_grid_medium.h"
#include "optics/eye_models.h"
#include "samplers/halton_sampler.h"
#include "samplers/independent_sampler.h"
#include "samplers/padded_sobol_sampler.h"
#include "samplers/pmj02bn_sampler.h"
#include "samplers/sobol_sampler.h"
#include "samplers/stratified_sampler.h"
#include "samplers/zsobol_sampler.h"
#include "scene/registry.h"
#include "scene/scene_builder.h"
#include "shapes/bilinear_mesh.h"
#include "shapes/curve.h"
#include "shapes/cylinder.h"
#include "shapes/disk.h"
#include "shapes/loop_subdiv_mesh.h"
#include "shapes/ply_mesh.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"
#include "textures/bilerp_texture.h"
#include "textures/checkerboard_texture.h"
#include "textures/constant_texture.h"
#include "textures/direction_mix_texture.h"
#include "textures/dots_texture.h"
#include "textures/imagemap_texture.h"
#include "textures/marble_texture.h"
#include "textures/mix_texture.h"
#include "textures/noise_textures.h"
#include "textures/scale_texture.h"

namespace eyetrace {

void register_builtin_plugins(Registry& r) {
  r.cameras.add("perspective", create_perspective_camera, perspective_camera_spec());
  r.cameras.add("thinlens", create_thinlens_camera, perspective_camera_spec());
  r.cameras.add("pinhole", create_pinhole_camera, perspective_camera_spec());
  r.cameras.add("orthographic", create_orthographic_camera, orthographic_camera_spec());
  r.cameras.add("spherical", create_spherical_camera, spherical_camera_spec());
  r.cameras.add("eye", create_eye_camera, eye_camera_spec("eye"));
  for (const std::string& model : optics::eye_model_names())
    r.cameras.add(model, create_named_eye_camera(model), eye_camera_spec(model));
  r.cameras.add("realistic", create_realistic_camera, realistic_camera_spec());

  r.samplers.add("independent", create_independent_sampler, independent_sampler_spec());
  r.samplers.add("stratified", create_stratified_sampler, stratified_sampler_spec());
  r.samplers.add("halton", create_halton_sampler, halton_sampler_spec());
  r.samplers.add("sobol", create_sobol_sampler, sobol_sampler_spec());
  r.samplers.add("zsobol", create_zsobol_sampler, zsobol_sampler_spec());
  r.samplers.add("paddedsobol", create_paddedsobol_sampler, paddedsobol_sampler_spec());
  r.samplers.add("pmj02bn", create_pmj02bn_sampler, pmj02bn_sampler_spec());

  r.filters.add("box", create_box_filter, box_filter_spec());
  r.filters.add("gaussian", create_gaussian_filter, gaussian_filter_spec());
  r.filters.add("triangle", create_triangle_filter, triangle_filter_spec());
  r.filters.add("mitchell", create_mitchell_filter, mitchell_filter_spec());
  r.filters.add("sinc", create_sinc_filter, sinc_filter_spec());

  r.shapes.add("trianglemesh", create_trianglemesh_shapes, trianglemesh_shape_spec());
  r.shapes.add("plymesh", create_plymesh_shapes, plymesh_shape_spec());
  r.shapes.add("bilinearmesh", create_bilinearmesh_shapes, bilinearmesh_shape_spec());
  r.shapes.add("sphere", create_sphere_shapes, sphere_shape_spec());
  r.shapes.add("disk", create_disk_shapes, disk_shape_spec());
  r.shapes.add("cylinder", create_cylinder_shapes, cylinder_shape_spec());
  r.shapes.add("loopsubdiv", create_loopsubdiv_shapes, loopsubdiv_shape_spec());
  r.shapes.add("curve", create_curve_shapes, curve_shape_spec());

  r.materials.add("diffuse", create_diffuse_material, diffuse_material_spec());
  r.materials.add("coateddiffuse", create_coateddiffuse_material, coateddiffuse_material_spec());
  r.materials.add("conductor", create_conductor_material, conductor_material_spec());
  r.materials.add("coatedconductor", create_coatedconductor_material, coatedconductor_material_spec());
  r.materials.add("dielectric", create_dielectric_material, dielectric_material_spec());
  r.materials.add("interface", create_interface_material, interface_material_spec());
  r.materials.add("mix", create_mix_material, mix_material_spec());
  r.materials.add("diffusetransmission", create_diffusetransmission_material, diffusetransmission_material_spec());
  r.materials.add("thindielectric", create_thindielectric_material, thindielectric_material_spec());
  r.materials.add("hair", create_hair_material, hair_material_spec());
  r.materials.add("measured", create_measured_material, measured_material_spec());
  r.materials.add("subsurface", create_subsurface_material, subsurface_material_spec());

  r.float_textures.add("constant", create_constant_float_texture, constant_texture_spec());
  r.float_textures.add("scale", create_scale_float_texture, scale_texture_spec());
  r.float_textures.add("mix", create_mix_float_texture, mix_texture_spec());
  r.float_textures.add("checkerboard", create_checkerboard_float_texture, checkerboard_texture_spec());
  r.float_textures.add("imagemap", create_imagemap_float_texture, imagemap_texture_spec());
  r.float_textures.add("bilerp", create_bilerp_float_texture, bilerp_texture_spec());
  r.float_textures.add("directionmix", create_directionmix_float_texture, directionmix_texture_spec());
  r.float_textures.add("dots", create_dots_float_texture, dots_texture_spec());
  r.float_textures.add("fbm", create_fbm_texture, fbm_texture_spec());
  r.float_textures.add("wrinkled", create_wrinkled_texture, wrinkled_texture_spec());
  r.float_textures.add("windy", create_windy_texture, windy_texture_spec());
  r.spectrum_textures.add("constant", create_constant_spectrum_texture, constant_texture_spec());
  r.spectrum_textures.add("scale", create_scale_spectrum_texture, scale_texture_spec());
  r.spectrum_textures.add("mix", create_mix_spectrum_texture, mix_texture_spec());
  r.spectrum_textures.add("checkerboard", create_checkerboard_spectrum_texture, checkerboard_texture_spec());
  r.spectrum_textures.add("imagemap", create_imagemap_spectrum_texture, imagemap_texture_spec());
  r.spectrum_textures.add("bilerp", create_bilerp_spectrum_texture, bilerp_texture_spec());
  r.spectrum_textures.add("directionmix", create_directionmix_spectrum_texture, directionmix_texture_spec());
  r.spectrum_textures.add("dots", create_dots_spectrum_texture, dots_texture_spec());
  r.spectrum_textures.add("marble", create_marble_spectrum_texture, marble_texture_spec());

  r.lights.add("point", create_point_light, point_light_spec());
  r.lights.add("spot", create_spot_light, spot_light_spec());
  r.lights.add("goniometric", create_goniometric_light, goniometric_light_spec());
  r.lights.add("projection", create_projection_light, projection_light_spec());
  r.lights.add("distant", create_distant_light, distant_light_spec());
  r.lights.add("infinite", create_infinite_light, infinite_light_spec());
  r.area_lights.add("diffuse", create_diffuse_area_light, diffuse_area_light_spec());

  r.media.add("homogeneous", create_homogeneous_medium, homogeneous_medium_spec());
  r.media.add("uniformgrid", create_grid_medium, grid_medium_spec());
  r.media.add("rgbgrid", create_rgb_grid_medium, rgb_grid_medium_spec());
  r.media.add("cloud", create_cloud_medium, cloud_medium_spec());
  r.media.add("nanovdb", create_nanovdb_medium, nanovdb_medium_spec());

  r.integrators.add("path", create_path_integrator, path_integrator_spec());
  r.integrators.add("volpath", create_volpath_integrator, volpath_integrator_spec());
  r.integrators.add("direct", create_direct_integrator, direct_integrator_spec());
  r.integrators.add("bdpt", create_bdpt_integrator, bdpt_integrator_spec());
  r.integrators.add("sppm", create_sppm_integrator, sppm_integrator_spec());

  r.built_in.push_back({"film", "rgb", &film_spec()});
  r.built_in.push_back({"film", "spectral", &spectral_film_spec()});
  r.built_in.push_back({"film", "gbuffer", &gbuffer_film_spec()});
}

std::vector<PluginListing> Registry::listing() const {
  std::vector<PluginListing> out;
  auto add = [&out](const auto& table) {
    for (const auto& e : table.entries) out.push_back({table.kind, e.name, e.spec});
  };
  add(cameras);
  add(samplers);
  add(filters);
  add(shapes);
  add(materials);
  add(float_textures);
  add(spectrum_textures);
  add(lights);
  add(area_lights);
  add(media);
  add(integrators);
  out.insert(out.end(), built_in.begin(), built_in.end());
  return out;
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
