// Diffraction as the renderer shows it (Camera "bool diffraction"), against the optics library's
// FFT point-spread function (optics/psf.h). A small disc at 100 m, on the axis and at 20
// degrees, is rendered through the monochromatic Navarro eye with a 2 mm iris at 450, 550 and
// 650 nm (mapping "retina": pixels linear in retinal arc), and the radii about the image's
// centroid that hold 50 % and 80 % of its light must be the PSF's within 10 %.
//
// Like with like: the image covers a square window of the retina, and the Airy pattern's tail
// (energy beyond radius v falls as 2 / (pi v)) reaches past any window a test can afford, so the
// fractions are of the light inside the window on both sides: the render's sum of pixels, and
// the PSF's energy inside the same square (its samples summed) with its encircled energy from
// optics::encircled_energy (exact for the sampled PSF). The disc is a fifth of the PSF's 50 %
// radius and a pixel a fifth too: they widen the image by about 2 % and 0.3 % in those radii
// (variances add), inside the tolerance and reported. The truth's PSF is computed on a finer
// pupil grid (128 across) than the camera's table (64), at the source's distance (the camera's
// table is at infinity): both are converged (docs/wavefront.md). kSeeds renders estimate the
// statistical error, which must be small against the tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../support/unity_id.h"
#include "optics/chromatic.h"
#include "optics/encircled_energy.h"
#include "optics/eye_models.h"
#include "optics/paraxial.h"
#include "optics/psf.h"
#include "optics/wavefront.h"
#include "render/film.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr double kPupil_mm = 2.0;
constexpr double kDistance_m = 100.0;
constexpr int kSeeds = 6;
constexpr double kDegree = std::numbers::pi / 180.0;

optics::Prescription navarro(double lambda_nm, double accommodation_D = 0.0) {
  optics::EyeOptions o;
  o.model = "navarro";
  o.accommodation_D = accommodation_D;
  o.pupil_diameter_mm = kPupil_mm;
  o.wavelength_nm = lambda_nm;
  return optics::make_eye(o);
}

// One measurement: the eye (wavelength, accommodation) and the source (field; distance from the
// corneal vertex, where the camera sits).
struct Case {
  double lambda_nm = 550.0;
  double field_deg = 0.0;
  double accommodation_D = 0.0;
  double distance_m = kDistance_m;
};

// The optics' PSF of the source (field in the camera's x-z plane; by symmetry the optics' y-z),
// at the source's distance from the entrance pupil.
optics::Psf truth_psf(const Case& c) {
  const double lambda_nm = c.lambda_nm, field_deg = c.field_deg;
  const optics::Prescription p = navarro(lambda_nm, c.accommodation_D);
  optics::WavefrontOptions o;
  o.field_deg = field_deg;
  o.object_distance_m = c.distance_m - 1e-3 * optics::paraxial_analysis(p).entrance_pupil.position_mm;
  o.clip_at_stop = true;
  o.grid = 128;
  o.zernike_order = 2;
  const optics::RetinalScale scale = optics::retinal_scale(p, field_deg, o.object_distance_m, lambda_nm);
  optics::Psf psf = optics::compute_psf(optics::trace_wavefront(p, o), scale);
  EXPECT_TRUE(psf.warning.empty()) << psf.warning;
  return psf;
}

// Energy of the PSF inside the square |x|, |y| <= half_um about its centroid (samples summed),
// as a fraction of all of it.
double window_fraction(const optics::Psf& psf, double half_um) {
  const int n = psf.fft_size;
  const double cx = psf.centroid_rad.x / psf.sample_x_rad * psf.sample_x_um;
  const double cy = psf.centroid_rad.y / psf.sample_y_rad * psf.sample_y_um;
  double in = 0.0, all = 0.0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double v = psf.at(x, y), px = (x - n / 2) * psf.sample_x_um - cx, py = (y - n / 2) * psf.sample_y_um - cy;
      all += v;
      if (std::abs(px) <= half_um && std::abs(py) <= half_um) in += v;
    }
  return in / all;
}

// The radius holding `fraction` of the light inside the window.
double truth_radius(const optics::Psf& psf, double half_um, double fraction) {
  const double target = fraction * window_fraction(psf, half_um);
  double lo = 0.0, hi = half_um;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (optics::encircled_energy(psf, mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// --- The render ----------------------------------------------------------------------------

struct View {
  double fov_deg = 0.0;  // the camera's full field (mapping "retina": the arc at fov/2 spans half the shorter axis)
  int resolution = 0;    // square film
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;  // crop (pixels)
  double pixel_um = 0.0;               // retinal arc per pixel
  double centre_arc_um = 0.0;          // retinal arc of the window's centre along +x
  double disk_m = 0.0;
  int half_pixels = 0;
};

// Arc (um) of the chief ray at field_deg at the camera's wavelength, and um of arc per radian.
double chief_arc_um(const optics::Prescription& p, double field_deg) {
  return 1e3 * std::abs(optics::trace_chief_ray(p, field_deg).image_coordinate_mm);
}

View make_view(const Case& c, double ee50_um, double ee80_um) {
  const double field_deg = c.field_deg;
  const optics::Prescription p = navarro(c.lambda_nm, c.accommodation_D);
  View v;
  v.pixel_um = ee50_um / 5.0;
  v.half_pixels = int(std::ceil(6.0 * ee80_um / v.pixel_um));
  // On the axis the film is the window (about 290 um of retina per degree); off it, a crop of
  // a film reaching past the field.
  const double half_fov = field_deg > 0.0 ? 1.1 * field_deg : v.half_pixels * v.pixel_um / 290.0;
  v.fov_deg = 2.0 * half_fov;
  const double edge_um = chief_arc_um(p, half_fov);  // screen radius 1
  v.resolution = 2 * int(std::round(edge_um / v.pixel_um));
  v.pixel_um = 2.0 * edge_um / v.resolution;
  v.centre_arc_um = field_deg > 0.0 ? chief_arc_um(p, field_deg) : 0.0;
  if (field_deg == 0.0) v.half_pixels = v.resolution / 2;
  const int cx = v.resolution / 2 + int(std::round(v.centre_arc_um / v.pixel_um)), cy = v.resolution / 2;
  v.x0 = cx - v.half_pixels, v.x1 = cx + v.half_pixels, v.y0 = cy - v.half_pixels, v.y1 = cy + v.half_pixels;
  const double um_per_rad = chief_arc_um(p, field_deg + 0.05) - chief_arc_um(p, field_deg);
  v.disk_m = c.distance_m * (ee50_um / 5.0) / (um_per_rad / (0.05 * kDegree));
  return v;
}

std::string scene(const View& v, const Case& c, int spp, int seed) {
  const double lambda_nm = c.lambda_nm, field_deg = c.field_deg;
  auto fraction = [&](int pixel) { return std::clamp((pixel + 0.5) / v.resolution, 0.0, 1.0); };
  const double x = c.distance_m * std::sin(field_deg * kDegree), z = c.distance_m * std::cos(field_deg * kDegree);
  return fmt::format(R"(LookAt 0 0 0  0 0 1  0 1 0
Camera "navarro" "float pupildiameter" {} "float wavelength" {} "float accommodation" {} "bool diffraction" true
       "float fov" {:.9g} "string mapping" "retina"
Film "rgb" "integer xresolution" {} "integer yresolution" {}
     "float cropwindow" [{:.9g} {:.9g} {:.9g} {:.9g}]
Sampler "zsobol" "integer pixelsamples" {} "integer seed" {}
Integrator "path" "integer maxdepth" 1
PixelFilter "box"
WorldBegin
AreaLightSource "diffuse" "rgb L" [1 1 1] "bool twosided" true
AttributeBegin
Translate {:.9g} 0 {:.9g}
Rotate {:.9g} 0 1 0
Shape "disk" "float radius" {:.9g}
AttributeEnd
)",
                     kPupil_mm, lambda_nm, c.accommodation_D, v.fov_deg, v.resolution, v.resolution, fraction(v.x0 - 1),
                     fraction(v.x1 - 1), fraction(v.y0 - 1), fraction(v.y1 - 1), spp, seed, x, z, field_deg, v.disk_m);
}

struct Image {
  int width = 0, height = 0;
  std::vector<double> value;  // luminance-free: the green channel (a monochromatic eye: all alike)
};

Image render(const std::string& text) {
  set_warnings_enabled(false);
  RenderSetup s = build_render_setup(parse_scene_string(text, "diffraction.pbrt", "/"), {});
  RenderCounters counters;
  RenderOptions opts;
  opts.progress = false;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
  const eyetrace::Image img = s.film->image();
  Image out{s.film->bounds().width(), s.film->bounds().height(), {}};
  for (size_t i = 0; i < size_t(out.width) * out.height; ++i) out.value.push_back(img.pixels[i * img.channels + 1]);
  return out;
}

// Encircled-energy radii of an image about its centroid (um), each pixel spread uniformly over
// its square (8 x 8 sub-points), the sagittal axis (image y) scaled by sag_scale: with mapping
// "retina" a pixel spans pixel_um of arc along the meridian but pixel_um h / a across it (h
// the point's height from the axis, a its arc).
std::vector<double> image_radii(const Image& g, double pixel_um, double sag_scale, std::vector<double> fractions) {
  double sum = 0.0, sx = 0.0, sy = 0.0;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const double v = g.value[size_t(y) * g.width + x];
      sum += v, sx += v * (x + 0.5), sy += v * (y + 0.5);
    }
  const double cx = sx / sum, cy = sy / sum;
  std::vector<std::pair<double, double>> pts;  // (radius um, energy)
  constexpr int kSub = 8;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const double v = g.value[size_t(y) * g.width + x];
      if (v == 0.0) continue;
      for (int j = 0; j < kSub; ++j)
        for (int i = 0; i < kSub; ++i) {
          const double dx = (x + (i + 0.5) / kSub - cx) * pixel_um,
                       dy = (y + (j + 0.5) / kSub - cy) * pixel_um * sag_scale;
          pts.push_back({std::hypot(dx, dy), v / (kSub * kSub)});
        }
    }
  std::sort(pts.begin(), pts.end());
  std::vector<double> radii;
  for (double f : fractions) {
    double acc = 0.0;
    for (const auto& [r, e] : pts)
      if ((acc += e) >= f * sum) {
        radii.push_back(r);
        break;
      }
  }
  return radii;
}

void check(const Case& c) {
  const double lambda_nm = c.lambda_nm, field_deg = c.field_deg;
  const optics::Psf psf = truth_psf(c);
  const double ee50 = psf.ee50_um, ee80 = psf.ee80_um;
  const View v = make_view(c, ee50, ee80);
  const double half_um = v.half_pixels * v.pixel_um;
  const double t50 = truth_radius(psf, half_um, 0.5), t80 = truth_radius(psf, half_um, 0.8);
  // Sagittal scale of mapping "retina" at the window's centre (Navarro's retina: radius 12 mm).
  const double a = v.centre_arc_um * 1e-3, R = 12.0;
  const double sag = a > 0.0 ? R * std::sin(a / R) / a : 1.0;
  std::vector<double> r50, r80;
  Image sum;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const Image g = render(scene(v, c, 256, seed));
    const std::vector<double> r = image_radii(g, v.pixel_um, sag, {0.5, 0.8});
    r50.push_back(r[0]), r80.push_back(r[1]);
    if (sum.value.empty())
      sum = g;
    else
      for (size_t i = 0; i < g.value.size(); ++i) sum.value[i] += g.value[i];
  }
  auto spread = [](const std::vector<double>& x) {
    double m = 0.0, s = 0.0;
    for (double e : x) m += e / x.size();
    for (double e : x) s += (e - m) * (e - m) / (x.size() - 1);
    return std::sqrt(s / x.size());
  };
  const std::vector<double> r = image_radii(sum, v.pixel_um, sag, {0.5, 0.8});
  std::printf(
      "%g nm, %g deg, %g D at %g m: render EE50 %.3f um (se %.3f), EE80 %.3f (se %.3f); optics in the window %.3f, "
      "%.3f "
      "(whole PSF %.3f, %.3f; window +-%.1f um, pixel %.3f um, %d px)\n",
      lambda_nm, field_deg, c.accommodation_D, c.distance_m, r[0], spread(r50), r[1], spread(r80), t50, t80, ee50, ee80,
      half_um, v.pixel_um, 2 * v.half_pixels);
  EXPECT_NEAR(r[0], t50, 0.1 * t50) << lambda_nm << " nm, " << field_deg << " deg";
  EXPECT_NEAR(r[1], t80, 0.1 * t80) << lambda_nm << " nm, " << field_deg << " deg";
  EXPECT_LT(spread(r50), 0.03 * t50) << "too noisy to tell";
  EXPECT_LT(spread(r80), 0.03 * t80) << "too noisy to tell";
}

TEST(DiffractionRender, PointSourceEncircledEnergyMatchesTheFftPsfOnAxis) {
  for (double lambda : {450.0, 550.0, 650.0}) check({lambda, 0.0});
}

TEST(DiffractionRender, PointSourceEncircledEnergyMatchesTheFftPsfAt20Degrees) {
  for (double lambda : {450.0, 550.0, 650.0}) check({lambda, 20.0});
}

// Between two field nodes of the camera's table (17.5 and 20 degrees) the camera samples their
// mixture: measured against the PSF of the field between, at 550 and 450 nm.
TEST(DiffractionRender, PointSourceBetweenFieldNodes) {
  for (double lambda : {550.0, 450.0}) check({lambda, 18.75});
}

// An eye accommodated by 2 D (Navarro's parameter) is focused at its far point at the reference
// wavelength, about 0.5 m: the camera computes its PSFs there and aims every ray at that
// distance from its own pupil point (wave_psf_table.h), so a source there must image as the PSF
// of that object distance.
TEST(DiffractionRender, AccommodatedEyeImagesASourceAtItsFocusAsThePsf) {
  const optics::Prescription reference = navarro(589.3, 2.0);
  const double far_point_m = -1.0 / optics::paraxial_analysis(reference).refraction_D;
  ASSERT_GT(far_point_m, 0.3);
  ASSERT_LT(far_point_m, 1.0);
  check({550.0, 0.0, 2.0, far_point_m});
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
