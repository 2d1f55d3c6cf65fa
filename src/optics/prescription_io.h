// Reading and writing prescriptions as self-describing JSON (the data/eyes/*.json format).
//
//   { "format": "eyetrace-prescription", "format_version": 1,
//     "model": "navarro", "variant": "", "title": "...", "source": "...", "status": "...",
//     "units": "mm", "sign_convention": "...", "reference_wavelength_nm": 589.3,
//     "object_index": 1.0,
//     "media": [ { "name": "cornea", "index": 1.376,
//                  "dispersion": { "law": "navarro-herzberger",
//                                  "indices_365_486.1_656.3_1014_nm": [...] } }, ... ],
//     "surfaces": [ { "name": "cornea anterior", "radius_mm": 7.72, "conic": -0.26,
//                     "thickness_mm": 0.55, "medium": "cornea", "semi_diameter_mm": 4.82,
//                     "role": "refract" }, ... ],
//     "notes": [ "..." ],
//     "dispersion_source": "Navarro et al. (1985) ...", "dispersion_assumed": false }
//
// An eye model file adds "accommodation" (read by eye_model.h; ignored here).
// Optional per-surface fields of a surface that is not rotationally symmetric (docs/eye-models.md,
// "Non-symmetric surfaces"): "cross_radius_mm" (null = flat) and "cross_conic" (default: conic)
// make it a biconic whose radius_mm / conic meridian lies at "axis_deg" ([0, 180), default 0,
// in the prescription frame from +x towards +y; the report's clinical axis is 180 - it) and whose cross meridian lies
// at axis_deg + 90; "decentre_mm": [x, y] and "tilt_deg": [about x, about y] place it (surface_placement.h). A
// decentred stop is a decentred iris. Absent, the surface is the rotationally symmetric one it always was. radius_mm
// null = flat; semi_diameter_mm null or 0 = unlimited; role refract | stop | image. Dispersion laws: "none",
// "navarro-herzberger", "cornu" (n_inf, k_nm, lambda0_nm), "abbe-linear" (nd, vd). dispersion_source (where the laws
// come from) and dispersion_assumed (true when the model's authors publish none and the laws are a choice made here)
// are optional. Unknown keys are errors, so a misspelt field is never ignored.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "optics/prescription.h"

namespace eyetrace::optics {

// `origin` names the text in error messages (a file name). Throws OpticsError; the result is
// validated.
Prescription prescription_from_json(const nlohmann::json& j, const std::string& origin);
Prescription prescription_from_json_text(const std::string& text, const std::string& origin);

// The inverse of prescription_from_json (documentation keys other than notes are not kept).
nlohmann::json prescription_to_json(const Prescription& p);

// A prescription file (this format) read from disk; errors name the path. Throws OpticsError.
Prescription load_prescription_file(const std::string& path);

// An embedded data file (data/eyes/<file_name>), parsed. Throws when it is not embedded.
Prescription load_embedded_prescription(const std::string& file_name);

}  // namespace eyetrace::optics
