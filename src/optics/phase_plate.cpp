// Phase plate: the Zernike series as one Cartesian polynomial, evaluated with its gradient per
// ray (see phase_plate.h).
#include "optics/phase_plate.h"

#include <array>
#include <cmath>
#include <memory>
#include <numbers>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/prescription.h"
#include "optics/sequential_trace.h"
#include "optics/zernike.h"

namespace eyetrace::optics {

namespace {

double binomial(int n, int k) {
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

constexpr double kMm_per_um = 1e-3;

}  // namespace

// Z_j = N R(rho) cos(m theta) (or sin): rho^k cos(m theta) = (u^2 + v^2)^((k - |m|)/2) Re((u + i
// v)^|m|) and likewise with Im for the sine terms, each expanded binomially into u^p v^q. One
// polynomial then gives W and its gradient per ray without trigonometry, and its u^2, u v, v^2
// coefficients are the curvature at the centre.
PhasePlate::PhasePlate(std::vector<double> coefficients_um, double radius_mm)
    : coefficients_um_(std::move(coefficients_um)), radius_mm_(radius_mm) {
  if (!(radius_mm_ > 0.0) || !std::isfinite(radius_mm_))
    throw OpticsError(fmt::format("phase plate: radius {} mm must be positive", radius_mm_));
  if (coefficients_um_.empty()) coefficients_um_.push_back(0.0);
  const int last = static_cast<int>(coefficients_um_.size()) - 1;
  order_ = zernike_index(last).n;
  if (order_ > kMaxZernikeFileOrder)
    throw OpticsError(fmt::format("phase plate: order {} is beyond the supported {}", order_, kMaxZernikeFileOrder));
  const int side = order_ + 1;
  poly_.assign(static_cast<size_t>(side * side), 0.0);
  for (int j = 0; j <= last; ++j) {
    const double c = coefficients_um_[j];
    if (!std::isfinite(c)) throw OpticsError(fmt::format("phase plate: coefficient j = {} is not finite", j));
    if (c == 0.0) continue;
    const ZernikeIndex z = zernike_index(j);
    const int am = std::abs(z.m);
    const double norm = std::sqrt((z.m == 0 ? 1.0 : 2.0) * (z.n + 1));
    for (int t = 0; t <= am; ++t) {  // (u + i v)^am = sum_t C(am, t) u^(am - t) (i v)^t
      const bool real = t % 2 == 0;
      if (real != (z.m >= 0)) continue;  // cos: real part (t even); sin: imaginary part (t odd)
      const double angular = binomial(am, t) * ((t % 4 == 0 || t % 4 == 1) ? 1.0 : -1.0);
      for (int k = am; k <= z.n; k += 2) {
        const double radial = zernike_radial_coefficient(z.n, z.m, k);
        const int s = (k - am) / 2;
        for (int l = 0; l <= s; ++l)
          poly_[static_cast<size_t>((am - t + 2 * l) * side + t + 2 * (s - l))] +=
              c * norm * radial * angular * binomial(s, l);
      }
    }
  }
}

double PhasePlate::wavefront_mm(double x, double y) const {
  const int side = order_ + 1;
  const double u = -x / radius_mm_, v = y / radius_mm_;
  std::array<double, kMaxZernikeFileOrder + 1> vp{};
  vp[0] = 1.0;
  for (int q = 1; q < side; ++q) vp[q] = vp[q - 1] * v;
  double w = 0.0, up = 1.0;
  for (int p = 0; p < side; ++p, up *= u)
    for (int q = 0; p + q < side; ++q) w += poly_[p * side + q] * up * vp[q];
  return w * kMm_per_um;
}

glm::dvec2 PhasePlate::gradient(double x, double y) const {
  const int side = order_ + 1;
  const double u = -x / radius_mm_, v = y / radius_mm_;
  std::array<double, kMaxZernikeFileOrder + 1> up{}, vp{};
  up[0] = vp[0] = 1.0;
  for (int k = 1; k < side; ++k) up[k] = up[k - 1] * u, vp[k] = vp[k - 1] * v;
  double wu = 0.0, wv = 0.0;
  for (int p = 0; p < side; ++p)
    for (int q = 0; p + q < side; ++q) {
      const double a = poly_[p * side + q];
      if (p > 0) wu += a * p * up[p - 1] * vp[q];
      if (q > 0) wv += a * q * up[p] * vp[q - 1];
    }
  // du/dx = -1/r, dv/dy = 1/r.
  const double scale = kMm_per_um / radius_mm_;
  return {-wu * scale, wv * scale};
}

PlateHessian PhasePlate::hessian_at_centre() const {
  const int side = order_ + 1;
  if (side < 3) return {};
  const double scale = kMm_per_um / (radius_mm_ * radius_mm_);
  // W_uu = 2 a(2,0), W_vv = 2 a(0,2), W_uv = a(1,1); x = -r u flips the sign of the cross term.
  return {2.0 * poly_[2 * side] * scale, -poly_[1 * side + 1] * scale, 2.0 * poly_[2] * scale};
}

namespace {

// The iris height that the rim of a measured pupil of radius r_mm maps to: the mean distance from
// the stop's centre at which rays parallel to the axis (an axial object at infinity, as the
// aberrometer's beacon is seen), entering through the entrance pupil's rim, cross the stop (in
// its own frame, where the plate's disc is), over 16 azimuths (the iris may be decentred and the cornea astigmatic).
// The stop is opened so that it blocks none of them.
double iris_radius_of_pupil_rim(const Prescription& p, double r_mm) {
  Prescription open = p;
  const int stop = p.stop_index();
  open.surfaces[stop].semi_diameter_mm = 1e3;
  const CompiledSystem sys(open);
  const Pupil ep = paraxial_analysis(p).entrance_pupil;
  const trace_detail::PlacedSurface iris(p.surfaces[stop], sys.vertex_z(stop));  // its frame
  constexpr int kAzimuths = 16;
  double sum = 0.0;
  for (int k = 0; k < kAzimuths; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / kAzimuths;
    const Ray ray{{ep.centre_x_mm + r_mm * std::cos(phi), ep.centre_y_mm + r_mm * std::sin(phi), -1.0},
                  {0.0, 0.0, 1.0}};
    const TraceResult t = sys.trace_range(ray, 0, stop);
    if (!t.ok())
      throw OpticsError(
          fmt::format("phase plate: a ray through the rim of the {} mm measured pupil does not reach "
                      "the iris ({})",
                      2.0 * r_mm, to_string(t.status)));
    const glm::dvec3 local = iris.local_from_system * (t.ray.origin - iris.origin);
    sum += std::hypot(local.x, local.y);
  }
  return sum / kAzimuths;
}

}  // namespace

void add_phase_plate(Prescription& p, const ZernikeFile& file) {
  const int s = p.stop_index();
  if (s < 0) throw OpticsError("phase plate: the system has no aperture stop to carry it");
  Surface& stop = p.surfaces[s];
  if (stop.phase_plate)
    throw OpticsError(fmt::format("phase plate: the stop already carries {}", stop.phase_plate->origin));
  const double paraxial_m = paraxial_analysis(p).entrance_pupil.magnification;
  if (!(paraxial_m > 0.0) || !std::isfinite(paraxial_m))
    throw OpticsError(
        fmt::format("phase plate: pupil magnification {} (the entrance pupil must be an upright image "
                    "of the stop)",
                    paraxial_m));
  const double r = 0.5 * file.pupil_diameter_mm;
  const double m = r / iris_radius_of_pupil_rim(p, r);
  auto plate = std::make_shared<PhasePlate>(file.coefficients_um, r / m);
  plate->origin = file.origin;
  plate->measured_pupil_diameter_mm = file.pupil_diameter_mm;
  plate->measured_wavelength_nm = file.wavelength_nm;
  plate->pupil_magnification = m;
  if (stop.limited() && stop.semi_diameter_mm > plate->radius_mm() * (1.0 + 1e-12))
    p.notes.push_back(fmt::format(
        "the iris ({:.3f} mm, entrance pupil {:.3f} mm) is wider than the pupil {} was measured over ({:.3f} mm): "
        "the phase plate passes rays within the measured pupil only (it is then the aperture)",
        2.0 * stop.semi_diameter_mm, 2.0 * stop.semi_diameter_mm * m, file.origin, file.pupil_diameter_mm));
  stop.phase_plate = std::move(plate);
}

}  // namespace eyetrace::optics
