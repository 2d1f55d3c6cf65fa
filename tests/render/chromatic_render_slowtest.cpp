// Chromatic aberration as the renderer shows it, against the optics library's own real-ray
// trace. Each test renders through the dispersive Navarro eye (no "float wavelength": every
// camera ray is traced at its hero wavelength) onto a spectral film, measures one quantity of
// the rendered image in a narrow wavelength bucket, and compares it with the same quantity from
// optics::trace_spot and optics::transverse_chromatic_aberration, which trace the prescription
// forwards from the object (the camera traces it backwards from the retina, with its own pupil
// sampling and weights):
//  - the RMS radius of the image of a point source on the axis (3 mm pupil) at 450, 550 and
//    650 nm, within 5 %;
//  - the red-blue offset of the colour fringes of a black-and-white edge at 20 degrees (4 mm
//    pupil): the shift, between the 450 and 650 nm buckets, of the centroid of the edge-spread
//    function's derivative (the line-spread function) against the centroid TCA, within 10 %.
// Every bucket is 20 nm wide. The optics side is averaged over the same 20 nm (the bucket holds
// the mean of the image over its wavelengths), so the comparison does not depend on the width.
// The statistical error is estimated from kSeeds renders with different seeds (their spread)
// and required to be a small fraction of the tolerance, so a noisy pass cannot hide a bias.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../support/unity_id.h"
#include "core/constants.h"
#include "optics/chromatic.h"
#include "optics/eye_models.h"
#include "optics/spot.h"
#include "render/film.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr double kBucketWidth_nm = 20.0;
constexpr int kBucketNodes = 8;  // midpoint rule over a bucket (the optics' bucket means)
constexpr int kSeeds = 8;        // independent renders per measurement (their spread is the error)
constexpr double kArcminPerDegree = 60.0;

optics::Prescription navarro(double pupil_mm) {
  optics::EyeOptions o;
  o.model = "navarro";
  o.pupil_diameter_mm = pupil_mm;
  return optics::make_eye(o);  // at the reference wavelength: what the camera maps pixels with
}

// Wavelengths at the midpoints of kBucketNodes equal parts of the bucket centred on centre_nm.
std::vector<double> bucket_nodes(double centre_nm) {
  std::vector<double> nodes;
  for (int k = 0; k < kBucketNodes; ++k)
    nodes.push_back(centre_nm + kBucketWidth_nm * ((k + 0.5) / kBucketNodes - 0.5));
  return nodes;
}

// A rendered spectral film over its pixel bounds: R, G, B, then one channel per bucket.
struct Grid {
  PixelBounds bounds;
  int channels = 0;
  std::vector<double> value;  // row-major, top row first
  double at(int x, int y, int c) const { return value[(size_t(y) * bounds.width() + x) * channels + c]; }
  double bucket(int x, int y, int b) const { return at(x, y, 3 + b); }
};

Grid render(const std::string& text) {
  set_warnings_enabled(false);
  RenderSetup s = build_render_setup(parse_scene_string(text, "chromatic.pbrt", "/"), {});
  RenderCounters counters;
  RenderOptions opts;
  opts.progress = false;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
  const Image img = s.film->image();
  return Grid{s.film->bounds(), img.channels, std::vector<double>(img.pixels.begin(), img.pixels.end())};
}

struct Estimate {
  double value = 0.0;           // from the sum of all seeds' images
  double standard_error = 0.0;  // spread of the seeds' values / sqrt(kSeeds)
  Grid sum;                     // the sum of all seeds' images
};

// `measure` applied to the sum of kSeeds renders of scene(seed) and to each one alone.
template <typename Scene, typename Measure>
Estimate measure_over_seeds(Scene&& scene, Measure&& measure) {
  Grid sum;
  std::vector<double> each;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const Grid g = render(scene(seed));
    each.push_back(measure(g));
    if (sum.value.empty())
      sum = g;
    else
      for (size_t i = 0; i < g.value.size(); ++i) sum.value[i] += g.value[i];
  }
  double mean = 0.0, var = 0.0;
  for (double v : each) mean += v / kSeeds;
  for (double v : each) var += (v - mean) * (v - mean) / (kSeeds - 1);
  return {measure(sum), std::sqrt(var / kSeeds), sum};
}

// --- 1. The image of a point source on the axis ----------------------------------------------

constexpr double kSourceDistance_m = 100.0;  // the scene's point source, on the axis

// Retina arc (um) per radian of field near the axis at lambda_nm: the chief ray of a source at
// kSourceDistance_m, 0.05 degrees off the axis.
double um_per_radian(const optics::Prescription& p, double lambda_nm) {
  const double field_deg = 0.05;
  const optics::ChiefRay c =
      optics::trace_chief_ray(optics::at_wavelength(p, lambda_nm), field_deg, kSourceDistance_m, &p);
  return 1e3 * std::abs(c.image_coordinate_mm) / (field_deg * kRadiansPerDegree);
}

// What the optics library says of the on-axis spot in the bucket centred on centre_nm.
struct SpotTruth {
  double rms_um = 0.0;         // sqrt of the bucket mean of rms^2
  double rms_centre_um = 0.0;  // at the bucket's centre wavelength alone
  double max_radius_um = 0.0;  // farthest ray from the centroid at any of the bucket's nodes
};

// The RMS radius of spot.h: about the spot's centroid, in um on the retina (3D distances on its
// surface; the render measures arc lengths along it, the same to 1e-7 within 50 um of the
// vertex). On the axis every wavelength's centroid is on the axis, so the bucket's image (the
// mean of its wavelengths' images, all of the same power) has the mean of their rms^2 as rms^2.
SpotTruth spot_truth(const optics::Prescription& p, double centre_nm) {
  SpotTruth t;
  optics::SpotOptions o;
  o.object_distance_m = kSourceDistance_m;
  o.grid = 256;
  double mean_rms2 = 0.0;
  for (double lambda : bucket_nodes(centre_nm)) {
    const optics::SpotResult s = optics::trace_spot(optics::at_wavelength(p, lambda), o);
    mean_rms2 += s.rms_radius_um * s.rms_radius_um / kBucketNodes;
    for (const glm::dvec2& q : s.points_um) t.max_radius_um = std::max(t.max_radius_um, std::hypot(q.x, q.y));
  }
  t.rms_um = std::sqrt(mean_rms2);
  t.rms_centre_um = optics::trace_spot(optics::at_wavelength(p, centre_nm), o).rms_radius_um;
  return t;
}

// The render of one bucket, scaled to its spot, and the RMS radius its image should have.
//
// The image of the source is the spot convolved with the source's own image (a uniform disk of
// retina radius s, whose rms^2 is s^2 / 2) and binned into square pixels of side h (Sheppard's
// correction: h^2 / 12 per axis); variances add. The source is a third of the spot's RMS radius
// and a pixel a tenth, so they add 1/18 and 1/600 of its rms^2 (2.8 % and 0.08 % of the
// radius): both are added to the expected value rather than ignored, and neither can dominate
// it. The image reaches 15 % beyond the farthest ray plus the source (the test checks that its
// border stays dark, so nothing is cut off).
struct PointSourceView {
  double fov_deg = 0.0;
  double half_um = 0.0;  // retina arc from the image centre to the middle of its edge
  int pixels = 0;
  double disk_m = 0.0;  // radius of the source disk
  double expected_rms_um = 0.0;
};

PointSourceView point_source_view(const optics::Prescription& eye, const SpotTruth& truth, double centre_nm) {
  PointSourceView v;
  const double source_um = truth.rms_um / 3.0, pixel_um = truth.rms_um / 10.0;
  const double half_deg = (1.15 * (truth.max_radius_um + source_um) + 2.0 * pixel_um) /
                          (um_per_radian(eye, eye.wavelength_nm) * kRadiansPerDegree);
  v.fov_deg = 2.0 * half_deg;
  // Mapping "retina" spans the shorter image axis over +-(the arc of the chief ray at fov/2, at
  // the camera's own wavelength, source at infinity): its pixels are linear in retina arc.
  v.half_um = 1e3 * std::abs(optics::trace_chief_ray(eye, half_deg).image_coordinate_mm);
  v.pixels = 2 * int(std::ceil(v.half_um / pixel_um));
  v.disk_m = kSourceDistance_m * std::tan(source_um / um_per_radian(eye, centre_nm));
  const double h = 2.0 * v.half_um / v.pixels;
  v.expected_rms_um = std::sqrt(truth.rms_um * truth.rms_um + source_um * source_um / 2.0 + h * h / 6.0);
  return v;
}

// A disk at kSourceDistance_m on the axis emitting a flat spectrum (a tabulated spectrum is
// normalised to luminance 1: flat 1), seen by the 3 mm Navarro eye with mapping "retina"; one
// 20 nm bucket centred on centre_nm.
std::string point_source_scene(const PointSourceView& v, double centre_nm, int spp, int seed) {
  return fmt::format(R"(LookAt 0 0 0  0 0 1  0 1 0
Camera "navarro" "float pupildiameter" 3 "float fov" {:.9g} "string mapping" "retina"
Film "spectral" "integer xresolution" {} "integer yresolution" {} "integer nbuckets" 1
     "float lambdamin" {} "float lambdamax" {}
Sampler "zsobol" "integer pixelsamples" {} "integer seed" {}
Integrator "path" "integer maxdepth" 1
PixelFilter "box"
WorldBegin
AreaLightSource "diffuse" "spectrum L" [360 1 830 1] "bool twosided" true
Translate 0 0 {}
Shape "disk" "float radius" {:.9g}
)",
                     v.fov_deg, v.pixels, v.pixels, centre_nm - 0.5 * kBucketWidth_nm,
                     centre_nm + 0.5 * kBucketWidth_nm, spp, seed, kSourceDistance_m, v.disk_m);
}

// RMS radius about the image's own centroid, in um, from the pixel centres (a square image
// spanning +-half_um on the retina, pixel values proportional to retinal irradiance).
double image_rms_um(const Grid& g, double half_um) {
  const int n = g.bounds.width();
  const double pixel = 2.0 * half_um / n;
  auto coord = [&](int i) { return (i + 0.5) * pixel - half_um; };
  double sum = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double v = g.bucket(x, y, 0), cx = coord(x), cy = coord(y);
      sum += v, sx += v * cx, sy += v * cy, sxx += v * (cx * cx + cy * cy);
    }
  return std::sqrt(sxx / sum - (sx * sx + sy * sy) / (sum * sum));
}

// Light on the outermost ring of pixels, relative to the total.
double border_fraction(const Grid& g) {
  const int n = g.bounds.width();
  double border = 0.0, sum = 0.0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      sum += g.bucket(x, y, 0);
      if (x == 0 || y == 0 || x == n - 1 || y == n - 1) border += g.bucket(x, y, 0);
    }
  return border / sum;
}

TEST(ChromaticRender, PointSourceRmsRadiusMatchesTheOpticsSpotAtEachWavelength) {
  const optics::Prescription eye = navarro(3.0);
  for (double centre_nm : {450.0, 550.0, 650.0}) {
    const SpotTruth truth = spot_truth(eye, centre_nm);
    const PointSourceView view = point_source_view(eye, truth, centre_nm);
    const Estimate rms = measure_over_seeds([&](int seed) { return point_source_scene(view, centre_nm, 256, seed); },
                                            [&](const Grid& g) { return image_rms_um(g, view.half_um); });
    const double expected = view.expected_rms_um;
    std::printf(
        "%g nm: render RMS radius %.4f um (standard error %.4f); optics %.4f um (spot %.4f, with the source "
        "and pixels); at %g nm alone %.4f um; %d x %d pixels of %.3f um\n",
        centre_nm, rms.value, rms.standard_error, expected, truth.rms_um, centre_nm, truth.rms_centre_um, view.pixels,
        view.pixels, 2.0 * view.half_um / view.pixels);
    EXPECT_NEAR(rms.value, expected, 0.05 * expected) << centre_nm << " nm";
    EXPECT_LT(rms.standard_error, 0.015 * expected) << centre_nm << " nm: too noisy to tell";
    EXPECT_EQ(border_fraction(rms.sum), 0.0)
        << centre_nm << " nm: light reaches the image's border (the spot is cut off)";
  }
}

// --- 2. The colour fringes of an edge at 20 degrees -------------------------------------------

constexpr double kEdgeField_deg = 20.0;
constexpr double kPlaneDistance_m = 100.0;  // the edge's plane, facing the eye
// Mapping "angle" (pixels linear in the visual angle of the reference-wavelength chief ray,
// the angle the optics' TCA is measured in): 5280 pixels over 44 degrees, 0.5 arcmin each.
constexpr int kEdgeResolution = 5280;
constexpr double kEdgeFov_deg = 44.0;
constexpr double kPixel_arcmin = kEdgeFov_deg * kArcminPerDegree / kEdgeResolution;
// Columns used, in arcmin from the edge (20 degrees): the window, where the blur of the 4 mm
// pupil lies (it reaches 40 arcmin towards the axis, the 440 nm end's coma flare, and a few
// arcmin outwards), then the white plateau. Rows: either side of the horizontal meridian.
constexpr double kWindowFrom_arcmin = -50.0, kWindowTo_arcmin = 15.0, kPlateauTo_arcmin = 35.0;
constexpr double kRowHalf_arcmin = 15.0;

int edge_column() { return kEdgeResolution / 2 + int(std::lround(kEdgeField_deg * kArcminPerDegree / kPixel_arcmin)); }

// The eye looks along +z; a white half-plane (flat spectrum) covers x >= the 20-degree line of
// the plane z = kPlaneDistance_m, so the edge is vertical in the image at 20 degrees right of the
// centre: the fringes' offset is along the rows. The film is cropped to the columns and rows
// used (crop fractions half a pixel inside, so that pbrt's rounding up gives these pixels).
std::string edge_scene(int spp, int seed) {
  const double x_edge = kPlaneDistance_m * std::tan(kEdgeField_deg * kRadiansPerDegree);
  const int e = edge_column(), rows = int(std::lround(kRowHalf_arcmin / kPixel_arcmin));
  auto fraction = [](int pixel) { return (pixel - 0.5) / kEdgeResolution; };
  const int x0 = e + int(std::lround(kWindowFrom_arcmin / kPixel_arcmin));
  const int x1 = e + int(std::lround(kPlateauTo_arcmin / kPixel_arcmin));
  const int y0 = kEdgeResolution / 2 - rows, y1 = kEdgeResolution / 2 + rows;
  return fmt::format(R"(LookAt 0 0 0  0 0 1  0 1 0
Camera "navarro" "float pupildiameter" 4 "float fov" {}
Film "spectral" "integer xresolution" {} "integer yresolution" {} "integer nbuckets" 11
     "float lambdamin" 440 "float lambdamax" 660 "float cropwindow" [{:.9g} {:.9g} {:.9g} {:.9g}]
Sampler "zsobol" "integer pixelsamples" {} "integer seed" {}
Integrator "path" "integer maxdepth" 1
PixelFilter "box"
WorldBegin
AreaLightSource "diffuse" "spectrum L" [360 1 830 1] "bool twosided" true
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
      "point3 P" [{x} -100 {z}  400 -100 {z}  400 100 {z}  {x} 100 {z}]
)",
                     kEdgeFov_deg, kEdgeResolution, kEdgeResolution, fraction(x0), fraction(x1), fraction(y0),
                     fraction(y1), spp, seed, fmt::arg("x", x_edge), fmt::arg("z", kPlaneDistance_m));
}

// Visual angle of column x's centre (absolute raster column) from the edge, arcmin.
double from_edge_arcmin(int x) {
  return (x + 0.5 - kEdgeResolution / 2) * kPixel_arcmin - kEdgeField_deg * kArcminPerDegree;
}

// The edge-spread function of bucket b: each column's mean over the rows.
std::vector<double> edge_spread(const Grid& g, int b) {
  std::vector<double> esf(g.bounds.width(), 0.0);
  for (int y = 0; y < g.bounds.height(); ++y)
    for (int x = 0; x < g.bounds.width(); ++x) esf[x] += g.bucket(x, y, b) / g.bounds.height();
  return esf;
}

// Mean of the edge-spread function over the columns whose centres lie in (from, to] arcmin from
// the edge.
double esf_mean(const std::vector<double>& esf, const PixelBounds& bounds, double from, double to) {
  double sum = 0.0;
  int n = 0;
  for (int x = 0; x < bounds.width(); ++x) {
    const double at = from_edge_arcmin(bounds.lo.x + x);
    if (at > from && at <= to) sum += esf[x], ++n;
  }
  return sum / n;
}

// Centroid of the line-spread function (the derivative of the edge-spread function E, rising
// from 0 to the plateau P across the window [a, b]): integral x dE / P = b - integral E dx / P.
// The box filter makes each pixel the mean of E over it, so the integral is exact in the pixels.
// The plateau is flat to 2e-5 per arcmin (measured), so its mean is P at b. Arcmin from the edge.
double edge_centroid_arcmin(const Grid& g, int bucket) {
  const std::vector<double> esf = edge_spread(g, bucket);
  const double plateau = esf_mean(esf, g.bounds, kWindowTo_arcmin, kPlateauTo_arcmin);
  double integral = 0.0, b = 0.0;
  for (int x = 0; x < g.bounds.width(); ++x) {
    const double at = from_edge_arcmin(g.bounds.lo.x + x);
    if (at > kWindowTo_arcmin) break;
    integral += esf[x] * kPixel_arcmin;
    b = at + 0.5 * kPixel_arcmin;
  }
  return b - integral / plateau;
}

// Whether the window holds the blur of bucket b: the edge-spread function is 0 at the window's
// inner end, and over its last 5 arcmin it is the plateau's (returned: the relative step).
double window_step(const Grid& g, int bucket) {
  const std::vector<double> esf = edge_spread(g, bucket);
  EXPECT_EQ(esf.front(), 0.0) << "bucket " << bucket << ": the blur reaches beyond the window's inner end";
  const double plateau = esf_mean(esf, g.bounds, kWindowTo_arcmin, kPlateauTo_arcmin);
  return esf_mean(esf, g.bounds, kWindowTo_arcmin - 5.0, kWindowTo_arcmin) / plateau - 1.0;
}

// The optics' TCA between the 450 and 650 nm buckets at the edge's point: each bucket's mean
// visual angle (of the chief ray, or of the spot's centroid) relative to 700 nm, averaged over
// its wavelengths; visual angles are those of the reference-wavelength chief rays, as the
// camera's mapping "angle".
struct TcaTruth {
  double centroid_arcmin = 0.0, chief_arcmin = 0.0;
};

TcaTruth tca_truth(const optics::Prescription& p) {
  const double distance_m = kPlaneDistance_m / std::cos(kEdgeField_deg * kRadiansPerDegree);
  optics::ChromaticOptions o;
  o.tca_long_nm = 700.0;
  o.centroid_grid = 128;
  TcaTruth t;
  for (double centre_nm : {450.0, 650.0}) {
    const double sign = centre_nm == 450.0 ? 1.0 : -1.0;
    for (double lambda : bucket_nodes(centre_nm)) {
      o.tca_short_nm = lambda;
      const optics::TransverseChromatic r = optics::transverse_chromatic_aberration(p, kEdgeField_deg, distance_m, o);
      EXPECT_TRUE(r.ok && r.centroid_ok) << lambda << " nm: " << r.lost;
      t.centroid_arcmin += sign * r.centroid_tca_arcmin / kBucketNodes;
      t.chief_arcmin += sign * r.tca_arcmin / kBucketNodes;
    }
  }
  return t;
}

// The image of the edge is the scene convolved with the eye's point-spread function, so the
// derivative of the edge-spread function is that function projected on the row, and its
// centroid is the spot's centroid: the fringes' offset is the centroid TCA, not the chief
// ray's (the chief ray is one ray of the bundle; at 20 degrees the 4 mm pupil's coma puts the
// centroids 0.28 arcmin further apart than the chief rays, which this render resolves).
TEST(ChromaticRender, EdgeFringeOffsetMatchesTheCentroidTcaAt20Degrees) {
  const TcaTruth truth = tca_truth(navarro(4.0));
  const int blue = 0, red = 10;  // buckets 440-460 and 640-660 nm of the 11 over 440-660
  auto offset = [&](const Grid& g) { return edge_centroid_arcmin(g, blue) - edge_centroid_arcmin(g, red); };
  const Estimate tca = measure_over_seeds([](int seed) { return edge_scene(128, seed); }, offset);
  const double step = std::max(std::abs(window_step(tca.sum, blue)), std::abs(window_step(tca.sum, red)));
  std::printf(
      "edge at 20 deg, 4 mm pupil: fringe offset 450 - 650 nm %.4f arcmin (standard error %.4f); optics "
      "TCA %.4f arcmin by the spots' centroids, %.4f by the chief rays; plateau step %.4f\n",
      tca.value, tca.standard_error, truth.centroid_arcmin, truth.chief_arcmin, step);
  EXPECT_NEAR(tca.value, truth.centroid_arcmin, 0.1 * std::abs(truth.centroid_arcmin));
  EXPECT_LT(tca.standard_error, 0.02 * std::abs(truth.centroid_arcmin)) << "too noisy to tell";
  EXPECT_LT(step, 0.01) << "the edge-spread function has not reached the plateau at the window's end";
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
