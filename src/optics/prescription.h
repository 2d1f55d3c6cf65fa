// Prescription: the data of a sequential optical system, ordered from the object side to the
// image. Conventions (see docs/eye-models.md): millimetres, z along the axis, z = 0 at the first
// surface vertex, +z towards the image; radius > 0 when the centre of curvature lies on the +z
// side; each surface carries the thickness to the next vertex and the medium after it. Surfaces
// are numbered from 0 in every message and result. A surface may be biconic (conic_surface.h)
// and may be decentred and tilted (surface_placement.h); the system is then not rotationally
// symmetric and is traced by the general path of sequential_trace.h. A flat surface may carry a
// phase plate (phase_plate.h), which makes the system non-symmetric too.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "optics/conic_surface.h"
#include "optics/medium.h"
#include "optics/surface_placement.h"

namespace eyetrace::optics {

class PhasePlate;

enum class SurfaceRole {
  Refract,  // an interface between two media
  Stop,     // the aperture stop (iris): flat, clips at its semi-diameter, does not refract
  Image,    // the image surface (retina or film); always last
};

const char* to_string(SurfaceRole role);

struct Surface {
  std::string name;
  SurfaceProfile profile;         // shape in the surface's local frame
  double thickness_mm = 0.0;      // axial distance to the next vertex (0 for the image)
  std::string medium;             // name of the medium after the surface
  double index_after = 1.0;       // its index at the prescription's wavelength
  double semi_diameter_mm = 0.0;  // clear radius; 0 or +inf = unlimited
  SurfaceRole role = SurfaceRole::Refract;
  // Decentration and tilt of the surface's local frame; the clear aperture (and a stop's
  // opening) is centred on the local axis, so a decentred stop is a decentred iris.
  SurfacePlacement placement;
  // A wavefront laid on the (flat) surface, e.g. an aberrometer's measurement on the iris; null
  // for none. Shared: copies of a prescription (at_wavelength) keep the one plate.
  std::shared_ptr<const PhasePlate> phase_plate;

  bool limited() const { return semi_diameter_mm > 0.0 && semi_diameter_mm < 1e300; }
};

struct Prescription {
  std::string name;                        // model name, e.g. "navarro", or a lens file name
  std::string variant;                     // e.g. "wu2011"; empty for the default
  std::string source;                      // literature source of the data
  double reference_wavelength_nm = 589.3;  // wavelength of the tabulated indices
  double wavelength_nm = 589.3;            // wavelength the surface indices are evaluated at
  double object_index = 1.0;               // object space is air
  std::vector<Surface> surfaces;           // object side first, image surface last
  std::vector<Medium> media;               // by name; lets at_wavelength() re-evaluate indices
  std::vector<std::string> notes;          // caveats (unverified data, extrapolation, ...)
  // Where the media's dispersion laws come from; dispersion_assumed when the model's authors
  // publish no dispersion and the laws are a choice made here (see docs/eye-models.md).
  std::string dispersion_source;
  bool dispersion_assumed = false;

  int image_index() const { return static_cast<int>(surfaces.size()) - 1; }
  int stop_index() const;  // -1 when there is none (validate() requires one)
  double stop_diameter_mm() const;
  // z of every vertex (first = 0); the last entry is the image vertex.
  std::vector<double> vertex_z_mm() const;
  double axial_length_mm() const;  // first vertex to image vertex
  double index_before(int surface) const { return surface == 0 ? object_index : surfaces[surface - 1].index_after; }
  const Medium* find_medium(const std::string& name) const;
  // No biconic profile, no placement and no phase plate: the closed-form batched kernel traces
  // the system.
  bool rotationally_symmetric() const;
};

// Throws OpticsError naming the surface and parameter at the first problem found: non-finite
// numbers, thickness outside [0, 1e6] mm, index outside [1, 10], no or several stops, image not
// last, a semi-diameter beyond a closed conic's reach, adjacent surfaces that cross within their
// clear apertures, a phase plate on a curved surface.
void validate(const Prescription& p);

// Same system with every surface index re-evaluated at lambda_nm from the media table (media
// without dispersion keep their index). Throws OpticsError outside [360, 1020] nm or when a
// surface names a medium the table lacks.
Prescription at_wavelength(const Prescription& p, double lambda_nm);

// Sets the stop's semi-diameter to half of diameter_mm (throws when there is no stop).
void set_stop_diameter(Prescription& p, double diameter_mm);

// Height at which two profiles, with vertices at z_a and z_b, meet (searched on [0, h_max]);
// returns h_max when they do not meet below it. Used for the edge of a lens (e.g. Gullstrand's
// nucleus) and for validate()'s crossing check.
double meeting_height(const SurfaceProfile& a, double z_a, const SurfaceProfile& b, double z_b, double h_max);

// A readable table of the surfaces (one line each).
std::string describe(const Prescription& p);

}  // namespace eyetrace::optics
