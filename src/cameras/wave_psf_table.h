// Diffraction for the lens-system camera: the eye's wave point-spread function (the optics
// library's FFT PSF, optics/psf.h), precomputed on a grid of field angles x wavelengths, from
// which each camera ray's outgoing direction is drawn (docs/wavefront.md, "Diffraction in
// renders").
//
// Why the direction, and what is discarded: the irradiance at a retina point x from a distant
// point source s is PSF(angle of x's chief ray - angle of s), the PSF being the image's
// intensity about the chief ray's image point in object-space angle. So a ray leaving x in the
// direction of x's chief ray turned by -a, a drawn from the PSF, samples exactly that. The
// geometric trace still picks where the ray leaves the cornea (the pupil point), decides
// vignetting and gives the relative-illumination weight; its direction is discarded, since the
// PSF already holds every aberration of the wavefront (using both would count them twice).
//
// Depth: the PSF is computed for objects at the eye's focus distance F (its far point at the
// reference wavelength; infinity for an emmetropic or hyperopic eye), and every ray is aimed
// at the point at distance F along the sampled direction, from its own pupil point. A point
// source at F gets the PSF; one at another distance z also gets the geometric blur of the
// pupil's projection, the disc of a perfect eye defocused by 1/z - 1/F dioptres.
//
// Grid and interpolation: field nodes every kFieldStep_deg from the axis to the camera's
// farthest pixel; wavelength nodes every 0.25 D of chromatic refraction over 400-830 nm for a dispersive eye,
// one node for a monochromatic one. Between nodes the node is chosen at random with the
// linear-interpolation weights (the sampled PSF is the interpolated mixture). Each node's PSF
// is cropped to the centred square holding kKeptEnergy of its energy and stored as an alias
// table over its samples (Walker 1977, Vose 1991); a ray picks a sample by the table and a
// uniform point within it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "cameras/retina_mapping.h"
#include "cameras/retina_surface.h"
#include "optics/prescription.h"

namespace eyetrace {

class WavePsfTable {
 public:
  static constexpr double kFieldStep_deg = 2.5;
  static constexpr double kKeptEnergy = 0.999;
  static constexpr int kUniforms = 6;
  static constexpr int kBlock = 16;
  struct Options {
    double max_field_deg = 30.0;  // farthest chief-ray field angle needed
    bool dispersive = false;      // wavelength nodes over the visible range, else one at the prescription's
    double focus_distance_m = 0;  // objects the PSF is computed for; 0 = infinity
  };
  struct Sample {
    double field_deg = 0.0;     // the chief ray's field angle at the ray's wavelength
    glm::dvec2 angle_rad{0.0};  // (sagittal, tangential) offset; tangential > 0 moves the image outwards
    bool ok = false;            // false beyond the table (no chief ray): keep the geometric ray
  };

  WavePsfTable() = default;
  // Computes every node (in parallel). aiming: the camera's chief-ray prescription (apertures
  // opened, chief_ray.h). Throws optics::OpticsError when the eye's paraxial data cannot be
  // had; nodes that cannot be computed are left geometric (geometric_nodes).
  WavePsfTable(const optics::Prescription& prescription, const optics::Prescription& aiming,
               const RetinaSurface& retina, double z_plane, double max_arc_mm, const Options& options);

  // The chief field angle at retina arc a and wavelength lambda_nm, and an offset drawn from the
  // PSF there with the uniform numbers u.
  Sample sample(double arc_mm, double lambda_nm, const double u[kUniforms]) const;

  // Entrance-pupil position (mm from the corneal vertex) and the focus distance (mm, 0 = infinity).
  double entrance_pupil_z_mm() const { return entrance_pupil_z_mm_; }
  double focus_distance_mm() const { return focus_distance_mm_; }
  int field_nodes() const { return field_nodes_; }
  int wavelength_nodes() const { return int(lambdas_.size()); }
  // Nodes left geometric (rays there keep their traced direction): the chief ray or too many
  // rays lost, or the wavefront too steep for a 128 pupil grid (aberration-dominated).
  int geometric_nodes() const { return geometric_nodes_; }
  int nodes() const { return int(nodes_.size()); }
  std::string describe() const;

 private:
  struct Node {
    bool ok = false;
    int size = 0;  // cropped samples across
    double sample_x_rad = 0.0, sample_y_rad = 0.0;
    int origin = 0;  // offset of the crop's first sample from the PSF centre (negative)
    // Two levels of Walker's alias tables (a pick is one lookup, no search): over blocks of
    // kBlock x kBlock samples, then over the samples of the chosen block. Entry i is kept with
    // probability keep / 65536, else its alias is taken. A flat table over the whole crop (up to
    // 256 x 256 samples, 256 kB) left each ray a cache miss (half the camera's time); most rays
    // land in the few central blocks, whose 1 kB tables stay in the cache.
    struct Cell {
      uint16_t keep;
      uint16_t alias;
    };
    int blocks_across = 0;
    std::vector<Cell> blocks;  // blocks_across^2, row-major
    std::vector<Cell> cells;   // kBlock^2 per block, block after block, row-major within
  };
  void build_node(const optics::Prescription& prescription, int field, int wavelength, Node* node) const;
  glm::dvec2 sample_node(const Node& n, const double u[kUniforms]) const;

  std::vector<double> lambdas_;
  std::vector<FieldAngleTable> angles_;  // per wavelength node: retina arc -> chief field angle
  std::vector<Node> nodes_;              // wavelength-major
  int field_nodes_ = 0;
  double entrance_pupil_z_mm_ = 0.0;
  double focus_distance_mm_ = 0.0;
  int geometric_nodes_ = 0;
};

}  // namespace eyetrace
