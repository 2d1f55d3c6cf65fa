// Camera directive parameters of the lens-system cameras -> a prescription and the camera's
// view settings. Every parameter is read through the ParameterList (so misspellings are
// reported) and every optics error is rethrown as a SceneError naming the parameter.
#pragma once

#include <string>

#include "cameras/lens_system_camera.h"
#include "optics/eye_models.h"
#include "optics/prescription.h"
#include "scene/param_spec.h"
#include "scene/params.h"

namespace eyetrace {

// Defaults (documented in docs/eye-camera.md).
inline constexpr double kDefaultPupilDiameter_mm = 4.0;
inline constexpr double kDefaultEyeFov_deg = 60.0;
inline constexpr double kDefaultApertureDiameter_mm = 1.0;  // pbrt-v4 "realistic"
inline constexpr double kDefaultFocusDistance = 10.0;       // pbrt-v4 "realistic", scene units (m)
inline constexpr double kDefaultFilmDiagonal_mm = 35.0;     // pbrt-v4 Film "diagonal"

// Declared parameters of the eye cameras ("eye" adds "model") and of "realistic".
const PluginSpec& eye_camera_spec(const std::string& camera_name);
const PluginSpec& realistic_camera_spec();

// The eye of camera `camera_name` ("eye" reads "string model"; "navarro" etc. are the model).
// Files the parameters name (zernikefile) are relative to search_dir (the scene's directory;
// empty: the working directory).
optics::Prescription eye_prescription_from_params(const std::string& camera_name, const ParameterList& params,
                                                  const std::string& search_dir = "");
// fov, mapping, sceneunit of an eye camera.
LensSystemCamera::Settings eye_view_settings(const std::string& camera_name, const ParameterList& params);

// pbrt-v4 "realistic": lensfile (relative to search_dir), aperturediameter, focusdistance (scene
// units = metres, measured from the film as pbrt does).
optics::Prescription realistic_prescription_from_params(const ParameterList& params, const std::string& search_dir);
LensSystemCamera::Settings realistic_view_settings(const ParameterList& params, IVec2 resolution);

}  // namespace eyetrace
