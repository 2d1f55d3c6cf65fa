#include "cameras/wave_psf_table.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "optics/chromatic.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/psf_image.h"
#include "optics/wavefront.h"

namespace eyetrace {

namespace {

// Wavelength nodes of a dispersive eye: from 400 nm to the top of the range the renderer
// samples (core/sampled_spectrum.h), a node wherever the eye's chromatic refraction has changed
// by kNodeRefraction_D since the last one (scanned every 5 nm): the PSF changes with
// wavelength mostly through that defocus, fastest in the blue. 0.25 D is 0.05 waves RMS over
// a 2 mm pupil at 550 nm. Navarro: 11 nodes. Below 400 nm the relaxed Navarro eye is more
// than 2 D myopic, its blur geometric, and its wave PSFs would need pupil grids (and FFTs)
// several times larger: rays there keep their traced direction. The last node is at 830 nm,
// the top of the sampled range.
constexpr double kLambdaLo_nm = 400.0, kLambdaHi_nm = 830.0, kLambdaScan_nm = 5.0;
constexpr double kNodeRefraction_D = 0.25;
// The pupil grid starts at the wave report's default and is refined, as the report does
// (optics/wave_optics_report.cpp), until neighbouring pupil samples differ by at most pi/2 of
// phase, up to kMaxGrid. A node that needs more has a PSF wider than about 32 lambda / D in
// radius, some 60 times the Airy pattern's 50 % radius: its blur is the aberrations', which the
// traced rays render, so it is left geometric (this also bounds a node to a 512 x 512 FFT).
constexpr int kStartGrid = 64, kMaxGrid = 128;
constexpr double kMaxPhaseStep_rad = 0.5 * std::numbers::pi;

optics::PsfImage node_psf(const optics::Prescription& p, optics::WavefrontOptions o) {
  optics::PsfImage psf = optics::psf_image(optics::trace_wavefront(p, o));
  while (psf.max_phase_step_rad > kMaxPhaseStep_rad && o.grid < kMaxGrid) {
    const double needed = o.grid * psf.max_phase_step_rad / kMaxPhaseStep_rad;
    o.grid = std::min(kMaxGrid, 16 * static_cast<int>(std::ceil(needed / 16.0)));
    psf = optics::psf_image(optics::trace_wavefront(p, o));
  }
  return psf;
}

// Half-width h (samples) of the smallest square about the centre holding `fraction` of the
// energy, growing it ring by ring.
int crop_half_width(const optics::PsfImage& psf, double fraction) {
  const int n = psf.fft_size, c = n / 2;
  double total = 0.0;
  for (double v : psf.intensity) total += v;
  double inside = psf.at(c, c);
  int h = 0;
  while (inside < fraction * total && h < c - 1) {
    ++h;
    for (int i = -h; i <= h; ++i) {
      inside += psf.at(c + i, c - h) + psf.at(c + i, c + h);
      if (i != -h && i != h) inside += psf.at(c - h, c + i) + psf.at(c + h, c + i);
    }
  }
  return h;
}

// Vose's alias method: cell i is kept with probability keep / 65536, else its alias is taken,
// so that cell j is chosen with probability weights[j] / sum (to the 16-bit rounding of keep,
// 1.5e-5 of a cell's share). False when the weights sum to 0 or there are more than 65536.
template <typename Cell>
bool build_alias_table(const std::vector<double>& weights, Cell* cells) {
  const size_t n = weights.size();
  double sum = 0.0;
  for (double w : weights) sum += w;
  if (!(sum > 0.0) || n > 65536) return false;
  std::vector<double> scaled(n);
  std::vector<uint32_t> small, large;
  for (size_t i = 0; i < n; ++i) {
    scaled[i] = weights[i] * double(n) / sum;
    (scaled[i] < 1.0 ? small : large).push_back(uint32_t(i));
  }
  for (size_t i = 0; i < n; ++i) cells[i] = {65535, uint16_t(i)};
  while (!small.empty() && !large.empty()) {
    const uint32_t s = small.back(), l = large.back();
    small.pop_back();
    cells[s] = {uint16_t(std::lround(scaled[s] * 65536.0 - 0.5)), uint16_t(l)};
    scaled[l] -= 1.0 - scaled[s];
    if (scaled[l] < 1.0) large.pop_back(), small.push_back(l);
  }
  return true;  // what is left has probability 1 up to rounding: kept
}

}  // namespace

WavePsfTable::WavePsfTable(const optics::Prescription& prescription, const optics::Prescription& aiming,
                           const RetinaSurface& retina, double z_plane, double max_arc_mm, const Options& options) {
  if (options.dispersive) {
    auto refraction = [&](double lambda) {
      return optics::paraxial_analysis(optics::at_wavelength(prescription, lambda)).refraction_D;
    };
    lambdas_.push_back(kLambdaLo_nm);
    double last = refraction(kLambdaLo_nm);
    for (double lambda = kLambdaLo_nm + kLambdaScan_nm; lambda < kLambdaHi_nm; lambda += kLambdaScan_nm) {
      const double r = refraction(lambda);
      if (std::abs(r - last) >= kNodeRefraction_D) lambdas_.push_back(lambda), last = r;
    }
    lambdas_.push_back(kLambdaHi_nm);
  } else {
    lambdas_.push_back(prescription.wavelength_nm);
  }
  const double max_field = std::max(options.max_field_deg, 0.0);
  field_nodes_ = static_cast<int>(std::ceil(max_field / kFieldStep_deg)) + 1;
  entrance_pupil_z_mm_ = optics::paraxial_analysis(prescription).entrance_pupil.position_mm;
  focus_distance_mm_ = options.focus_distance_m > 0.0 ? options.focus_distance_m * 1e3 : 0.0;
  for (double lambda : lambdas_) {
    const optics::CompiledSystem system(optics::at_wavelength(aiming, lambda));
    angles_.emplace_back(system, retina, z_plane, max_field + kFieldStep_deg, max_arc_mm);
  }
  nodes_.resize(lambdas_.size() * size_t(field_nodes_));
  tbb::parallel_for(size_t(0), nodes_.size(), [&](size_t k) {
    build_node(prescription, int(k % size_t(field_nodes_)), int(k / size_t(field_nodes_)), &nodes_[k]);
  });
  for (const Node& n : nodes_) geometric_nodes_ += !n.ok;
}

void WavePsfTable::build_node(const optics::Prescription& p, int field, int wavelength, Node* node) const {
  optics::WavefrontOptions o;
  o.field_deg = field * kFieldStep_deg;
  o.wavelength_nm = lambdas_[size_t(wavelength)];
  if (focus_distance_mm_ > 0.0) o.object_distance_m = focus_distance_mm_ * 1e-3;
  o.clip_at_stop = true;  // the real iris is the pupil
  o.grid = kStartGrid;
  o.zernike_order = 2;  // the PSF needs the OPD only
  optics::PsfImage psf;
  try {
    psf = node_psf(p, o);
  } catch (const optics::OpticsError&) {
    return;  // node->ok stays false: rays there keep their geometric direction
  }
  if (psf.max_phase_step_rad > kMaxPhaseStep_rad) return;  // aberration-dominated: geometric
  const int h = crop_half_width(psf, kKeptEnergy), c = psf.fft_size / 2;
  node->size = 2 * h + 1;
  node->origin = -h;
  node->sample_x_rad = psf.sample_x_rad;
  node->sample_y_rad = psf.sample_y_rad;
  // Blocks of kBlock x kBlock samples over the crop (padded with zeros), their sums, and the
  // alias tables of both levels.
  const int nb = node->blocks_across = (node->size + kBlock - 1) / kBlock;
  const size_t per_block = size_t(kBlock) * kBlock;
  std::vector<double> block_sums(size_t(nb) * nb, 0.0), weights(per_block);
  node->blocks.resize(block_sums.size());
  node->cells.resize(block_sums.size() * per_block);
  for (int b = 0; b < nb * nb; ++b) {
    for (int j = 0; j < kBlock; ++j)
      for (int i = 0; i < kBlock; ++i) {
        const int x = (b % nb) * kBlock + i, y = (b / nb) * kBlock + j;
        const double w = x < node->size && y < node->size ? std::max(psf.at(c - h + x, c - h + y), 0.0) : 0.0;
        weights[size_t(j) * kBlock + size_t(i)] = w;
        block_sums[size_t(b)] += w;
      }
    if (!build_alias_table(weights, &node->cells[size_t(b) * per_block]))
      for (size_t i = 0; i < per_block; ++i)
        node->cells[size_t(b) * per_block + i] = {65535, uint16_t(i)};  // never picked
  }
  if (!build_alias_table(block_sums, node->blocks.data())) return;
  node->ok = true;
}

// A sample of the node's PSF by its alias table, then uniform within the sample's cell:
// (sagittal, tangential) angle, radians. The cell's width (lambda / 4D at the automatic FFT
// size) widens the PSF by its variance, 1/12 of a cell squared per axis.
glm::dvec2 WavePsfTable::sample_node(const Node& n, const double u[kUniforms]) const {
  auto pick = [](const Node::Cell* table, size_t count, double v) {
    const double x = v * double(count);
    const size_t k = std::min(size_t(x), count - 1);
    return (x - double(k)) * 65536.0 >= table[k].keep + 0.5 ? size_t(table[k].alias) : k;
  };
  const size_t per_block = size_t(kBlock) * kBlock;
  const size_t b = pick(n.blocks.data(), n.blocks.size(), u[0]);
  const size_t k = pick(&n.cells[b * per_block], per_block, u[5]);
  const int ix = int(b % size_t(n.blocks_across)) * kBlock + int(k % kBlock);
  const int iy = int(b / size_t(n.blocks_across)) * kBlock + int(k / kBlock);
  return {(n.origin + ix + u[1] - 0.5) * n.sample_x_rad, (n.origin + iy + u[2] - 0.5) * n.sample_y_rad};
}

WavePsfTable::Sample WavePsfTable::sample(double arc_mm, double lambda_nm, const double u[kUniforms]) const {
  Sample s;
  size_t j = 0;
  if (lambdas_.size() > 1) {
    if (lambda_nm < lambdas_.front()) return s;  // geometric (see kLambdaLo_nm)
    const double lambda = std::min(lambda_nm, lambdas_.back());
    j = std::min(size_t(std::upper_bound(lambdas_.begin(), lambdas_.end(), lambda) - lambdas_.begin()),
                 lambdas_.size() - 1) -
        1;
    const double t = (lambda - lambdas_[j]) / (lambdas_[j + 1] - lambdas_[j]);
    if (u[3] < t) ++j;  // the nearer node more often: linear interpolation in lambda
  }
  double slope = 0.0;
  const double field = angles_[j].angle_for_arc(arc_mm, &slope);
  if (!(field >= 0.0)) return s;
  const double x = field / kFieldStep_deg;
  size_t i = size_t(x);
  if (u[4] < x - double(i)) ++i;
  if (i >= size_t(field_nodes_)) return s;
  const Node& n = nodes_[j * size_t(field_nodes_) + i];
  if (!n.ok) return s;
  s.field_deg = field;
  s.angle_rad = sample_node(n, u);
  s.ok = true;
  return s;
}

std::string WavePsfTable::describe() const {
  size_t floats = 0;
  for (const Node& n : nodes_) floats += n.cells.size() + n.blocks.size();
  return fmt::format("wave PSF on {} fields (every {} deg) x {} wavelengths, {:.1f} MB, {} of {} nodes geometric",
                     field_nodes_, kFieldStep_deg, lambdas_.size(), floats * 4e-6, geometric_nodes_, nodes_.size());
}

}  // namespace eyetrace
