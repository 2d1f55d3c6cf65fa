// The wave-optics figure of one field (see wave_plot.h).
#include "optics/wave_plot.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

const Rgb kBlack{0, 0, 0}, kGrid{225, 225, 225}, kTangential{31, 119, 180}, kSagittal{214, 39, 40},
    kLimit{150, 150, 150}, kMarkerT{0, 50, 110}, kMarkerS{130, 0, 20};

// A round step (1, 2 or 5 times a power of ten) that cuts span into about n intervals.
double round_step(double span, int n) {
  const double raw = span / n, decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw) return m * decade;
  return 10.0 * decade;
}

struct Box {
  int x0, y0, x1, y1;
};

void frame(RgbImage& img, const Box& b) {
  img.line(b.x0, b.y0, b.x1, b.y0, kBlack), img.line(b.x0, b.y1, b.x1, b.y1, kBlack);
  img.line(b.x0, b.y0, b.x0, b.y1, kBlack), img.line(b.x1, b.y0, b.x1, b.y1, kBlack);
}

// A polyline of (x, y) in data units mapped by px, py; dashed: 6 pixels on, 4 off (by segment).
template <class Px, class Py>
void curve(RgbImage& img, const std::vector<std::pair<double, double>>& points, Px px, Py py, Rgb c, bool dashed) {
  double run = 0.0;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const double ax = px(points[i].first), ay = py(points[i].second);
    const double bx = px(points[i + 1].first), by = py(points[i + 1].second);
    run += std::hypot(bx - ax, by - ay);
    if (!dashed || std::fmod(run, 10.0) < 6.0) img.line(ax, ay, bx, by, c, 2);
  }
}

void mtf_panel(RgbImage& img, const Box& b, const Psf& psf, const std::vector<MtfPoint>& markers) {
  // To the tangential cut-off D cos(field) / lambda, where both MTFs are defined (compute_mtf).
  const double cutoff_s = sagittal_cutoff_cpd(psf), cutoff_t = tangential_cutoff_cpd(psf);
  auto px = [&](double f) { return b.x0 + f / cutoff_t * (b.x1 - b.x0); };
  auto py = [&](double m) { return b.y1 - m * (b.y1 - b.y0); };
  const double xstep = round_step(cutoff_t, 6);
  for (double f = 0.0; f <= cutoff_t + 1e-9; f += xstep) {
    img.line(px(f), b.y0, px(f), b.y1, kGrid);
    const std::string label = fmt::format("{:g}", f);
    img.text(static_cast<int>(px(f)) - RgbImage::text_width(label) / 2, b.y1 + 5, label, kBlack);
  }
  for (int i = 0; i <= 5; ++i) {
    img.line(b.x0, py(0.2 * i), b.x1, py(0.2 * i), kGrid);
    const std::string label = fmt::format("{:.1f}", 0.2 * i);
    img.text(b.x0 - 5 - RgbImage::text_width(label), static_cast<int>(py(0.2 * i)) - 3, label, kBlack);
  }
  std::vector<double> freqs;
  for (int i = 0; i <= 100; ++i) freqs.push_back(std::min(cutoff_t, cutoff_t * i / 100.0));  // no ulp past it
  const std::vector<MtfPoint> mtf = compute_mtf(psf, freqs);
  std::vector<std::pair<double, double>> t, s, limit_t, limit_s;
  for (int i = 0; i <= 100; ++i) {
    const double f = freqs[static_cast<size_t>(i)];
    s.emplace_back(f, mtf[static_cast<size_t>(i)].sagittal);
    t.emplace_back(f, mtf[static_cast<size_t>(i)].tangential);
    limit_s.emplace_back(f, diffraction_limited_mtf(f / cutoff_s));
    limit_t.emplace_back(f, diffraction_limited_mtf(f / cutoff_t));
  }
  curve(img, limit_s, px, py, kLimit, false);
  if (cutoff_t < 0.999 * cutoff_s) curve(img, limit_t, px, py, kLimit, true);
  curve(img, s, px, py, kSagittal, false);
  curve(img, t, px, py, kTangential, false);
  for (const MtfPoint& m : markers) {
    if (m.freq_cpd > cutoff_t) continue;
    img.line(px(m.freq_cpd), py(m.tangential), px(m.freq_cpd), py(m.tangential), kMarkerT, 6);
    img.line(px(m.freq_cpd), py(m.sagittal), px(m.freq_cpd), py(m.sagittal), kMarkerS, 6);
  }
  frame(img, b);
  const std::string xlabel = "cycles/deg (visual angle)";
  img.text((b.x0 + b.x1 - RgbImage::text_width(xlabel)) / 2, b.y1 + 18, xlabel, kBlack);
  int y = b.y0 + 6;
  for (const auto& [name, c] : {std::pair{"tangential", kTangential}, std::pair{"sagittal", kSagittal},
                                std::pair{"diffraction limit", kLimit}}) {
    img.line(b.x1 - 150, y + 3, b.x1 - 130, y + 3, c, 2);
    img.text(b.x1 - 124, y, name, kBlack);
    y += 12;
  }
  if (!markers.empty()) {
    img.line(b.x1 - 146, y + 3, b.x1 - 146, y + 3, kMarkerT, 6);
    img.line(b.x1 - 134, y + 3, b.x1 - 134, y + 3, kMarkerS, 6);
    img.text(b.x1 - 124, y, "polychromatic t, s", kBlack);
  }
}

// The PSF at a retinal point (um from its zero angle), bilinear between samples.
double psf_value(const Psf& psf, double x_um, double y_um) {
  const int n = psf.fft_size;
  const double u = x_um / psf.sample_x_um + n / 2, v = y_um / psf.sample_y_um + n / 2;
  const int iu = static_cast<int>(std::floor(u)), iv = static_cast<int>(std::floor(v));
  if (iu < 0 || iv < 0 || iu + 1 >= n || iv + 1 >= n) return 0.0;
  const double a = u - iu, c = v - iv;
  return (1 - c) * ((1 - a) * psf.at(iu, iv) + a * psf.at(iu + 1, iv)) +
         c * ((1 - a) * psf.at(iu, iv + 1) + a * psf.at(iu + 1, iv + 1));
}

void psf_panel(RgbImage& img, const Box& b, const Psf& psf, bool log_scale) {
  const double cx = psf.centroid_rad.x / psf.sample_x_rad * psf.sample_x_um;
  const double cy = psf.centroid_rad.y / psf.sample_y_rad * psf.sample_y_um;
  const double half = std::max(3.0 * psf.ee80_um, 12.0 * std::max(psf.sample_x_um, psf.sample_y_um));
  const double peak = *std::max_element(psf.intensity.begin(), psf.intensity.end());
  const int side = b.x1 - b.x0;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      // Image rows top to bottom: +y (the tangential axis) up.
      const double v =
          psf_value(psf, cx + (2.0 * (i + 0.5) / side - 1.0) * half, cy - (2.0 * (j + 0.5) / side - 1.0) * half) / peak;
      const double level =
          log_scale ? std::clamp(1.0 + std::log10(std::max(v, 1e-300)) / 3.0, 0.0, 1.0) : std::clamp(v, 0.0, 1.0);
      const auto g = static_cast<std::uint8_t>(std::lround(255.0 * level));
      img.put(b.x0 + i, b.y0 + j, {g, g, g});
    }
  frame(img, b);
  const double step = round_step(half, 3);
  for (double t = -std::floor(half / step) * step; t <= half + 1e-9; t += step) {
    const double p = b.x0 + (t / half + 1.0) * 0.5 * side, q = b.y1 - (t / half + 1.0) * 0.5 * side;
    const std::string label = fmt::format("{:g}", t + 0.0);
    img.line(p, b.y1, p, b.y1 + 4, kBlack), img.line(b.x0 - 4, q, b.x0, q, kBlack);
    img.text(static_cast<int>(p) - RgbImage::text_width(label) / 2, b.y1 + 6, label, kBlack);
    img.text(b.x0 - 6 - RgbImage::text_width(label), static_cast<int>(q) - 3, label, kBlack);
  }
  const std::string xlabel =
      fmt::format("um on the retina from the centroid, {}", log_scale ? "log10, 3 decades" : "linear");
  img.text((b.x0 + b.x1 - RgbImage::text_width(xlabel)) / 2, b.y1 + 18, xlabel, kBlack);
}

}  // namespace

RgbImage wave_figure(const Psf& psf, const std::vector<MtfPoint>& markers, const std::string& title,
                     const WavePlotOptions& o) {
  if (o.width < 480 || o.height < 240)
    throw OpticsError(fmt::format("wave figure: needs >= 480 x 240 pixels (got {} x {})", o.width, o.height));
  if (psf.intensity.empty()) throw OpticsError("wave figure: the PSF has no samples");
  RgbImage img(o.width, o.height);
  const int top = 24, bottom = 34, side = o.height - top - bottom;
  const Box psf_box{o.width - 12 - side, top, o.width - 12, top + side};
  const Box mtf_box{40, top, psf_box.x0 - 56, top + side};
  mtf_panel(img, mtf_box, psf, markers);
  psf_panel(img, psf_box, psf, o.log_psf);
  img.text(mtf_box.x0, 8, title, kBlack);
  return img;
}

}  // namespace eyetrace::optics
