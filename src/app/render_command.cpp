// `eyetrace render SCENE.pbrt`: parse, apply command-line overrides, render, write.
#include <fmt/core.h>

#include <sys/resource.h>

#include <tbb/task_arena.h>
#include <chrono>
#include <climits>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/interrupt.h"
#include "cameras/lens_system_camera.h"
#include "distributed/launch.h"
#include "render/adaptive_sampling.h"
#include "render/image_io.h"
#include "render/progress.h"
#include "render/render_state.h"
#include "scene/parser.h"
#include "scene/render_request.h"
#include "scene/scene_builder.h"
#include "scene/scene_fingerprint.h"

namespace eyetrace {

namespace {

struct RenderArgs {
  std::string scene;
  std::string output;
  int spp = 0;
  std::string resolution;
  int threads = 0;
  int64_t seed = -1;
  std::string crop;
  std::string camera;
  bool quiet = false;
  bool strict = false;
  std::string stats;
  double max_memory_gib = 0;
  double checkpoint = -1;  // seconds between checkpoints; 0: after every pass; < 0: none
  bool resume = false;
  int pass_samples = 0;  // 0: about a second per pass
  bool adaptive = false;
  double target_error = 0.01;
  int min_spp = 16;
  int max_spp = 0;  // 0: the sampler's samples per pixel
  std::string spp_image;
  std::string mpi_split = "interleaved";
};

void check_output_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& c : ext) c = char(std::tolower(c));
  if (ext != ".exr" && ext != ".png")
    throw_parameter_error({}, "--output",
                          fmt::format("\"{}\": the extension must be .exr (linear float) or .png (sRGB 8-bit)", path));
}

// Everything besides the scene description that changes the image, for the state fingerprint.
std::string image_options(const RenderArgs& a, const RenderSetup& setup) {
  const Film& f = *setup.film;
  const std::string adaptive =
      a.adaptive ? fmt::format(" adaptive={:.17g},{},{}", a.target_error, a.min_spp, a.max_spp) : "";
  return fmt::format("spp={} seed={} camera={} resolution={}x{} bounds={},{},{},{}{}\n{}",
                     setup.sampler->samples_per_pixel(), a.seed, a.camera, f.resolution().x, f.resolution().y,
                     f.bounds().lo.x, f.bounds().lo.y, f.bounds().hi.x, f.bounds().hi.y, adaptive, setup.description);
}

// Loads `path` into the film and tiles, refusing a state made for another render.
void resume_from(const std::string& path, uint64_t fingerprint, RenderSetup& setup, TileProgress& tiles) {
  RenderState s = read_render_state(path);
  const Film& f = *setup.film;
  int spp = setup.sampler->samples_per_pixel();
  if (s.samples_per_pixel != spp)
    throw_error(
        fmt::format("--resume: render state \"{}\" is for {} samples per pixel, this render asks for {} "
                    "(resume with the same --spp, or render without --resume)",
                    path, s.samples_per_pixel, spp));
  if (s.resolution != f.resolution() || s.bounds.lo != f.bounds().lo || s.bounds.hi != f.bounds().hi)
    throw_error(
        fmt::format("--resume: render state \"{}\" is for a {}x{} image (or another crop), this render is {}x{}", path,
                    s.resolution.x, s.resolution.y, f.resolution().x, f.resolution().y));
  if (s.spectral_buckets != f.buckets().count)
    throw_error(
        fmt::format("--resume: render state \"{}\" is for a film with {} spectral buckets, this render's has {}", path,
                    s.spectral_buckets, f.buckets().count));
  if (s.fingerprint != fingerprint)
    throw_error(fmt::format(
        "--resume: render state \"{}\" was made for another scene or other options (the scene "
        "file, an included file, a mesh, image or lens file it reads, --seed or --camera differ); render without "
        "--resume to start over",
        path));
  setup.film->restore(s.accumulators, s.nonfinite_samples);
  tiles = std::move(s.tiles);
}

// What turns a spectral film's buckets, seen through a lens-system camera (an eye model or
// "realistic"), into spectral irradiance on the retina (or film): E = n'^2 * T * value / C, with
// C the camera's weight normalisation (1 / the cos-weighted solid angle of the passing cone at
// the image centre, in the image-space medium), n' that medium's index at the bucket's centre
// and T = 1 (no ocular media absorption or Fresnel loss is modelled). docs/spectral.md derives it.
struct RetinalIrradiance {
  double weight_normalisation = 0.0;  // C, 1/sr
  std::string medium;                 // the image-space medium (the vitreous of an eye)
  std::vector<double> centres_nm, index, factor_sr;

  std::map<std::string, std::string> metadata() const {
    auto list = [](const std::vector<double>& v) {
      std::string s;
      for (double x : v) s += (s.empty() ? "" : " ") + fmt::format("{:.9g}", x);
      return s;
    };
    return {{"eyetrace:camera_weight_normalisation", fmt::format("{:.9g}", weight_normalisation)},
            {"eyetrace:image_medium", medium},
            {"eyetrace:image_medium_index", list(index)},
            {"eyetrace:retinal_irradiance_factors", list(factor_sr)}};
  }
  nlohmann::json json() const {
    return {{"camera_weight_normalisation_per_sr", weight_normalisation},
            {"image_medium", medium},
            {"bucket_centres_nm", centres_nm},
            {"image_medium_index", index},
            {"factor_sr", factor_sr}};
  }
};

std::optional<RetinalIrradiance> retinal_irradiance(const RenderSetup& setup) {
  const SpectralBuckets& b = setup.film->buckets();
  const auto* camera = dynamic_cast<const LensSystemCamera*>(setup.camera.get());
  if (!b.spectral() || !camera) return std::nullopt;
  const optics::Prescription& p = camera->prescription();
  const optics::Surface& last = p.surfaces.at(size_t(p.image_index() - 1));  // the medium before the image
  const optics::Medium* medium = p.find_medium(last.medium);
  RetinalIrradiance r;
  r.weight_normalisation = camera->weight_normalisation();
  r.medium = last.medium.empty() ? "air" : last.medium;
  for (int i = 0; i < b.count; ++i) {
    const double centre = b.centre(i);
    const double n = medium ? medium->index_at(centre) : last.index_after;
    r.centres_nm.push_back(centre);
    r.index.push_back(n);
    r.factor_sr.push_back(n * n / r.weight_normalisation);
  }
  return r;
}

struct Snapshot {
  bool interrupted = false;
  bool final = false;
};

// Writes the image as it stands and, unless it is final, the state to resume it from.
void save(const std::string& output, const RenderArgs& a, const RenderSetup& setup, const TileProgress& tiles,
          uint64_t fingerprint, Snapshot kind, const std::optional<RetinalIrradiance>& irradiance, const Image& image) {
  int spp = setup.sampler->samples_per_pixel();
  std::map<std::string, std::string> meta = {{"eyetrace:samples_per_pixel", std::to_string(tiles.min_done())},
                                             {"eyetrace:samples_requested", std::to_string(spp)},
                                             {"eyetrace:interrupted", kind.interrupted ? "1" : "0"},
                                             {"eyetrace:scene", a.scene},
                                             {"eyetrace:camera", setup.camera->to_string()}};
  // A render stopped mid-pass has tiles one pass ahead: each pixel is still a proper mean.
  if (tiles.max_done() != tiles.min_done()) meta["eyetrace:samples_per_pixel_max"] = std::to_string(tiles.max_done());
  meta.merge(setup.film->image_metadata());
  if (irradiance) meta.merge(irradiance->metadata());
  if (!kind.final) {
    RenderState s;
    s.fingerprint = fingerprint;
    s.resolution = setup.film->resolution();
    s.bounds = setup.film->bounds();
    s.samples_per_pixel = spp;
    s.tiles = tiles;
    s.spectral_buckets = setup.film->buckets().count;
    s.accumulators = setup.film->accumulators();
    s.nonfinite_samples = setup.film->nonfinite_samples();
    write_render_state(state_path(output), s);
  }
  // The image after the state: a checkpoint image always has its state next to it.
  write_image(output, image, meta);
}

void write_stats(const RenderArgs& a, const nlohmann::json& j) {
  std::string tmp = a.stats + ".tmp";
  {
    std::ofstream f(tmp);
    f << j.dump(2) << "\n";
    if (!f) throw_error(fmt::format("--stats \"{}\": cannot write", a.stats));
  }
  std::filesystem::rename(tmp, a.stats);
}

// The adaptive options, checked against the sampler the scene and --spp / --max-spp gave.
std::optional<AdaptiveOptions> adaptive_options(const RenderArgs& a, const Sampler& sampler) {
  if (!a.adaptive) return std::nullopt;
  if (!sampler.progressive())
    throw_parameter_error({}, "--adaptive",
                          fmt::format("the sampler ({}) cannot stop a pixel at any sample count (a stratified grid "
                                      "fills its strata row by row); use \"zsobol\", \"sobol\", \"halton\" or "
                                      "\"independent\"",
                                      sampler.to_string()));
  AdaptiveOptions o;
  o.target_error = a.target_error;
  o.min_spp = a.min_spp;
  o.max_spp = sampler.samples_per_pixel();
  if (o.max_spp < o.min_spp)
    throw_parameter_error({}, "--max-spp",
                          fmt::format("{} samples per pixel (after the sampler's rounding) is below --min-spp {}, the "
                                      "first pass every pixel takes",
                                      o.max_spp, o.min_spp));
  return o;
}

// How the samples spread over the pixels: for --stats and the summary line.
nlohmann::json spp_distribution(const TileProgress& tiles, const PixelBounds& b) {
  std::vector<int> n = tiles.pixel_counts(b);
  std::sort(n.begin(), n.end());
  double sum = 0;
  std::map<int, size_t> histogram;
  for (int v : n) {
    sum += v;
    ++histogram[v];
  }
  nlohmann::json h = nlohmann::json::array();
  for (auto [spp, pixels] : histogram) h.push_back({{"spp", spp}, {"pixels", pixels}});
  auto at = [&](double q) { return n.empty() ? 0 : n[std::min(n.size() - 1, size_t(q * double(n.size())))]; };
  return {{"mean", n.empty() ? 0.0 : sum / double(n.size())},
          {"min", n.empty() ? 0 : n.front()},
          {"p10", at(0.1)},
          {"median", at(0.5)},
          {"p90", at(0.9)},
          {"max", n.empty() ? 0 : n.back()},
          {"histogram", h}};
}

// --spp-image: each pixel's sample count as a one-channel float EXR.
void write_spp_image(const std::string& path, const TileProgress& tiles, const PixelBounds& b) {
  Image img;
  img.width = b.width();
  img.height = b.height();
  img.channels = 1;
  img.channel_names = {"spp"};
  for (int n : tiles.pixel_counts(b)) img.pixels.push_back(float(n));
  write_image(path, img, {{"eyetrace:channel", "samples per pixel"}});
}

// Everything a render job prepares before its first sample, the same on every rank.
struct Job {
  SceneDescription desc;
  RenderSetup setup;
  std::string output;
  std::optional<RetinalIrradiance> irradiance;
  // scene_fingerprint of the render, made when a render state is first read or written (or ranks
  // compare scenes): hashing a scene of millions of triangles takes a few per cent of its loading.
  std::optional<uint64_t> fingerprint;
  int spp = 0;
  std::optional<AdaptiveOptions> adaptive;
  TileProgress tiles;
};

// The job's fingerprint, made on first use. A render that neither resumes nor checkpoints nor runs
// over several ranks needs it only if it is interrupted, to write its state then (the files it read
// are then hashed as they are at the interruption).
uint64_t state_fingerprint(const RenderArgs& a, Job& job) {
  if (!job.fingerprint)
    job.fingerprint = scene_fingerprint(job.desc, image_options(a, job.setup), job.setup.files_read);
  return *job.fingerprint;
}

std::unique_ptr<Job> prepare(const RenderArgs& a, const RenderGroup& group) {
  auto job = std::make_unique<Job>();
  // Large Imports are parsed on tasks: --threads bounds them as it bounds the render.
  tbb::task_arena parse_arena(a.threads > 0 ? a.threads : tbb::task_arena::automatic);
  parse_arena.execute([&] { job->desc = parse_scene_file(a.scene); });
  RenderRequest request;
  request.camera = a.camera;
  request.resolution = a.resolution;
  request.crop = a.crop;
  request.spp = a.max_spp > 0 ? a.max_spp : a.spp;
  request.seed = a.seed;
  request.max_memory_gib = a.max_memory_gib;
  request.output = a.output;
  job->setup = build_requested_setup(job->desc, request);
  RenderSetup& setup = job->setup;
  job->output = a.output.empty() ? setup.output_filename : a.output;
  check_output_extension(job->output);
  prepare_image_output(job->output);
  // A gbuffer film's auxiliary sums are not part of the render state that checkpoints store and
  // MPI ranks exchange (render/gbuffer.h): refused rather than written half.
  if (setup.film->gbuffer() && (a.checkpoint >= 0 || a.resume || group.size() > 1))
    throw_error(
        "the gbuffer film cannot be checkpointed (--checkpoint), resumed (--resume) or rendered over several "
        "processes (mpirun); render it in one process, or use the rgb film");
  job->irradiance = retinal_irradiance(setup);
  if (a.resume || a.checkpoint >= 0 || group.size() > 1) state_fingerprint(a, *job);
  job->spp = setup.sampler->samples_per_pixel();
  job->adaptive = adaptive_options(a, *setup.sampler);
  job->tiles = TileProgress::start(setup.film->bounds());
  if (a.resume) {
    resume_from(state_path(job->output), *job->fingerprint, setup, job->tiles);
    // Every rank restores the whole state; the non-finite count is rank 0's alone to carry.
    if (group.rank() != 0) setup.film->restore(setup.film->accumulators(), 0);
  }
  return job;
}

// When rank `reporter` failed with `error` (the other ranks pass null): under mpirun the first
// rank to exit with an error ends the job and kills the others, which would cut off a rank still
// writing its message; so the reporter prints its error first, then every rank meets in a
// collective, and all return null (exit code 1). Alone, the error goes up to main as any other.
std::unique_ptr<Job> report_once(RenderGroup& group, int reporter, const std::exception_ptr& error) {
  if (group.size() == 1) std::rethrow_exception(error);
  if (group.rank() == reporter) report_error(error);
  group.any(false);  // no rank returns before the report is written
  return nullptr;
}

// Prepares on every rank; when any fails, the first rank that failed reports its error and the
// others return null, so that a scene error is printed once, and no rank goes on to wait for
// the others in a collective.
std::unique_ptr<Job> prepare_everywhere(const RenderArgs& a, RenderGroup& group) {
  std::unique_ptr<Job> job;
  std::exception_ptr error;
  try {
    job = prepare(a, group);
  } catch (...) {
    error = std::current_exception();
  }
  const int first_failed = group.min(error ? group.rank() : INT_MAX);
  if (first_failed != INT_MAX) return report_once(group, first_failed, error);
  // Every rank must render the same image: the fingerprint covers the scene, every file it
  // reads and the options that change the image (a rank started with other arguments, or on a
  // machine whose copy of a file differs, would otherwise add other pixels to the same film).
  const uint64_t mine = group.size() > 1 ? *job->fingerprint : 0;
  const uint64_t lead = group.broadcast(mine);
  const int odd = group.min(mine != lead ? group.rank() : INT_MAX);
  if (odd != INT_MAX) {
    if (group.rank() == odd) {
      try {
        throw_error(fmt::format(
            "rank {} sees another scene or other options than rank 0 (scene fingerprint {:016x} against {:016x}): "
            "every rank must be started with the same arguments and read the same files",
            odd, mine, lead));
      } catch (...) {
        error = std::current_exception();
      }
    }
    return report_once(group, odd, error);
  }
  return job;
}

// The job's counters, summed over ranks, and each rank's times (rank 0 gets them; collective).
struct Totals {
  uint64_t samples, camera_rays, lost, rays, shadow_rays, shadow_rays_skipped, nonfinite, share_rays;
  std::vector<double> busy_seconds, render_seconds, cpu_seconds;

  nlohmann::json ranks_json() const {
    double mean = 0, most = 0;
    for (double s : busy_seconds) {
      mean += s / double(busy_seconds.size());
      most = std::max(most, s);
    }
    return {{"count", busy_seconds.size()},
            {"render_seconds", render_seconds},
            {"busy_seconds", busy_seconds},
            {"cpu_seconds", cpu_seconds},
            {"load_imbalance", mean > 0 ? most / mean : 1.0}};
  }
};

// CPU seconds of this process (all its threads) so far.
double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

Totals totals(RenderGroup& g, const RenderCounters& c, double render_seconds, double cpu_seconds) {
  return {g.sum(c.samples),           g.sum(c.camera_rays),
          g.sum(c.camera_rays_lost),  g.sum(c.rays_traced),
          g.sum(c.shadow_rays),       g.sum(c.shadow_rays_skipped),
          g.sum(c.nonfinite_samples), g.sum(c.camera_rays_for_shares),
          g.gather(c.busy_seconds),   g.gather(render_seconds),
          g.gather(cpu_seconds)};
}

// The image and state of a finished or interrupted render (rank 0).
// The image rank 0 writes, with rank 0's progress made whole: a finished uniform render
// gathers the other ranks' image values alone (RenderGroup::collect_image), an interrupted one
// their film sums too (the resumable state needs them); an adaptive render's film is whole
// already (shared after every pass). Every rank calls it; the others get an empty image.
Image whole_image(RenderGroup& g, Film& film, TileProgress& tiles, bool complete) {
  if (!tiles.adaptive() && complete) return g.collect_image(film, tiles);
  if (!tiles.adaptive()) g.collect(film, tiles);
  return g.rank() == 0 ? film.image() : Image{};
}

void write_result(const RenderArgs& a, Job& job, bool complete, const Image& image) {
  const TileProgress& tiles = job.tiles;
  if (complete) {
    save(job.output, a, job.setup, tiles, 0, Snapshot{false, true}, job.irradiance, image);  // no state: no fingerprint
    std::error_code ec;
    std::filesystem::remove(state_path(job.output), ec);  // finished: nothing left to resume
  } else if (tiles.max_done() > 0) {
    save(job.output, a, job.setup, tiles, state_fingerprint(a, job), Snapshot{true, false}, job.irradiance, image);
    fmt::print(stderr,
               "eyetrace: interrupted: wrote {} with {} of {} samples per pixel{}, and {}; continue with --resume\n",
               job.output, tiles.min_done(), job.spp,
               tiles.max_done() != tiles.min_done() ? fmt::format(" (up to {} in some tiles)", tiles.max_done()) : "",
               state_path(job.output));
  } else {
    fmt::print(stderr, "eyetrace: interrupted before any sample was finished: nothing written\n");
  }
  if (!a.spp_image.empty() && tiles.max_done() > 0) write_spp_image(a.spp_image, tiles, job.setup.film->bounds());
}

void print_summary(const Job& job, const Totals& t, const nlohmann::json& spread, double seconds, double render_seconds,
                   int resumed_at, int ranks) {
  const std::string spp_text =
      job.adaptive ? fmt::format("adaptive {:.1f} spp (min {}, median {}, max {})", spread["mean"].get<double>(),
                                 spread["min"].get<int>(), spread["median"].get<int>(), spread["max"].get<int>())
                   : fmt::format("{} spp", job.spp);
  fmt::print("{}: {:.2f} s ({:.2f} s render{}{}), {}, {} camera rays ({:.1f}% lost), {:.2f} Mrays/s{}\n", job.output,
             seconds, render_seconds, resumed_at > 0 ? fmt::format(", resumed at {} spp", resumed_at) : "",
             ranks > 1 ? fmt::format(", {} processes", ranks) : "", spp_text, t.camera_rays,
             t.camera_rays ? 100.0 * t.lost / t.camera_rays : 0.0,
             render_seconds > 0 ? t.rays / render_seconds / 1e6 : 0.0,
             t.nonfinite ? fmt::format(", {} non-finite samples discarded", t.nonfinite) : "");
}

// Wall-clock seconds of a render's stages on rank 0: `total` from the start to the last
// sample, of which `setup` (scene, camera tables) and `render`; `output` after it (gathering
// the other ranks' results, the image, writing it).
struct Timing {
  double total, setup, render, output;
};

void write_render_stats(const RenderArgs& a, const Job& job, const Totals& t, const nlohmann::json& spread,
                        const Timing& time, int resumed_at, bool complete) {
  const double render_seconds = time.render;
  const SpectralBuckets& b = job.setup.film->buckets();
  nlohmann::json film = {{"type", b.spectral() ? "spectral" : "rgb"}};
  if (b.spectral()) {
    film["buckets"] = b.count;
    film["lambda_min_nm"] = b.lambda_min;
    film["lambda_max_nm"] = b.lambda_max;
  }
  if (job.irradiance) film["retinal_irradiance"] = job.irradiance->json();
  const std::optional<AdaptiveOptions>& ad = job.adaptive;
  write_stats(
      a, {{"scene", a.scene},
          {"output", job.output},
          {"seconds", time.total},
          {"setup_seconds", time.setup},
          {"render_seconds", time.render},
          {"output_seconds", time.output},
          {"samples_per_pixel", job.spp},
          {"samples_per_pixel_completed", job.tiles.min_done()},
          {"samples_per_pixel_distribution", spread},
          {"adaptive",
           ad ? nlohmann::json{{"target_error", ad->target_error}, {"min_spp", ad->min_spp}, {"max_spp", ad->max_spp}}
              : nlohmann::json(nullptr)},
          {"resumed_at_samples_per_pixel", resumed_at},
          {"interrupted", !complete},
          {"samples", t.samples},
          {"camera_rays", t.camera_rays},
          {"camera_rays_lost", t.lost},
          {"useful_camera_ray_fraction", t.camera_rays ? double(t.camera_rays - t.lost) / t.camera_rays : 0.0},
          {"camera_rays_for_shares", t.share_rays},
          {"rays_traced", t.rays},
          {"shadow_rays", t.shadow_rays},
          {"shadow_rays_skipped", t.shadow_rays_skipped},
          {"rays_per_second", render_seconds > 0 ? t.rays / render_seconds : 0.0},
          {"nonfinite_samples", t.nonfinite},
          {"threads", a.threads},
          {"ranks", t.ranks_json()},
          {"resolution", {job.setup.film->resolution().x, job.setup.film->resolution().y}},
          {"camera", job.setup.camera->to_string()},
          {"film", film},
          {"warnings", warning_count()}});
}

int run_render(const RenderArgs& a) {
  std::unique_ptr<RenderGroup> group = join_render_group();
  RenderGroup& g = *group;
  g.set_split(a.mpi_split == "blocks" ? RenderGroup::Split::kBlocks : RenderGroup::Split::kInterleaved);
  const bool lead = g.rank() == 0;  // prints, writes files
  set_warnings_enabled(!a.quiet && lead);
  set_warnings_fatal(a.strict);
  ProgressLine progress(!a.quiet && lead);
  std::unique_ptr<Job> job = prepare_everywhere(a, g);
  if (!job) return 1;
  RenderSetup& setup = job->setup;
  TileProgress& tiles = job->tiles;
  const int spp = job->spp;
  const int resumed_at = tiles.min_done();
  progress.resume_at(double(tiles.samples(setup.film->bounds())) / (double(setup.film->bounds().area()) * spp));
  const double setup_seconds = progress.elapsed_seconds();

  const double cpu_before = process_cpu_seconds();
  InterruptGuard interrupt;
  RenderCounters counters;
  RenderOptions ro;
  ro.threads = a.threads;
  ro.on_progress = [&](double f, uint64_t rays) { progress.update(f, rays); };
  ro.tiles = &tiles;
  ro.stop = &interrupt.stop_requested();
  ro.pass_samples = a.pass_samples;
  ro.adaptive = job->adaptive ? &*job->adaptive : nullptr;
  ro.group = &g;
  auto last_checkpoint = std::chrono::steady_clock::now();
  if (a.checkpoint >= 0)
    ro.on_pass = [&](const TileProgress&) {
      // Rank 0's clock decides for all (a collective), then rank 0's film is made whole.
      const double since = std::chrono::duration<double>(std::chrono::steady_clock::now() - last_checkpoint).count();
      if (!g.any(lead && since >= a.checkpoint)) return;
      g.collect(*setup.film, tiles);
      if (lead && !tiles.complete(spp))
        save(job->output, a, setup, tiles, *job->fingerprint, Snapshot{}, job->irradiance, setup.film->image());
      last_checkpoint = std::chrono::steady_clock::now();
    };
  try {
    setup.integrator->render(*setup.camera, *setup.sampler, *setup.film, ro, counters);
  } catch (...) {
    g.abort_job();  // the other ranks may be waiting for this one in a collective
    throw;
  }
  progress.finish();
  const double seconds = progress.elapsed_seconds(), render_seconds = seconds - setup_seconds;
  const Totals t = totals(g, counters, render_seconds, process_cpu_seconds() - cpu_before);
  const int signal = int(g.max(interrupt.signal_number()));
  const bool complete = g.complete(tiles, spp);
  const Image image = whole_image(g, *setup.film, tiles, complete);
  if (!lead) return complete ? 0 : 128 + signal;
  write_result(a, *job, complete, image);
  const double output_seconds = progress.elapsed_seconds() - seconds;
  const nlohmann::json spread = spp_distribution(tiles, setup.film->bounds());
  if (!a.quiet && complete) print_summary(*job, t, spread, seconds, render_seconds, resumed_at, g.size());
  if (!a.stats.empty())
    write_render_stats(a, *job, t, spread, Timing{seconds, setup_seconds, render_seconds, output_seconds}, resumed_at,
                       complete);
  return complete ? 0 : 128 + signal;
}

// CLI11 validators, so that a malformed value is a command-line error (exit status 2). CLI11
// puts the option's name in front of the message, so the validator returns the diagnostic's
// message alone.
CLI::Validator validator(std::function<void(const std::string&)> check, const std::string& what) {
  return CLI::Validator(
      [check](std::string& value) -> std::string {
        try {
          check(value);
        } catch (const SceneError& e) {
          return e.first().message;
        }
        return "";
      },
      what);
}

const char* kRenderFooter = R"(Interrupting: the first SIGINT (Ctrl-C) or SIGTERM stops the render after the tiles in
flight, writes the image so far (EXR metadata eyetrace:interrupted = 1 and
eyetrace:samples_per_pixel = the samples completed) and OUTPUT.state, and exits with 130
(SIGINT) or 143 (SIGTERM); a second signal exits at once. --resume continues from
OUTPUT.state to the same image an uninterrupted render gives, bit for bit.

Exit status: 0 done; 1 error in the scene, a file or a value read as scene text (--camera);
2 bad command line (unknown option, value out of range); 130 / 143 interrupted.)";

}  // namespace

CommandRunner add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* c = app.add_subcommand("render", "Render a pbrt-v4 scene file");
  c->footer(kRenderFooter);
  c->add_option("scene", args->scene, "Scene file (pbrt-v4 text format)")->required();
  c->add_option("-o,--output", args->output,
                "Output image: .exr (linear float) or .png (sRGB 8-bit); default: the Film's filename")
      ->check(validator(check_output_extension, "PATH"));
  c->add_option("--spp", args->spp, "Samples per pixel (overrides the Sampler's pixelsamples)")
      ->check(CLI::Range(1, 1 << 24));
  c->add_option("--resolution", args->resolution, "Image size WxH (overrides the Film's xresolution/yresolution)")
      ->check(validator(parse_resolution, "WxH"));
  c->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  c->add_option("--seed", args->seed, "Sampler seed; the same seed gives the same image for any thread count")
      ->check(CLI::NonNegativeNumber);
  c->add_option("--crop", args->crop, "Render only x0,x1,y0,y1 (fractions of the image, as pbrt's cropwindow)")
      ->check(validator(parse_crop, "X0,X1,Y0,Y1"));
  c->add_option(
      "--camera", args->camera,
      "Replace the scene's camera with a Camera directive, e.g. 'Camera \"navarro\" \"float accommodation\" 2'");
  c->add_flag("-q,--quiet", args->quiet, "No progress line, summary or warnings");
  c->add_flag("--strict", args->strict,
              "Treat warnings (unsupported but ignorable input) as errors: nothing is rendered");
  c->add_option("--stats", args->stats, "Write render statistics as JSON to this file");
  c->add_option("--max-memory", args->max_memory_gib,
                "Refuse renders predicted to need more GiB (default: 3/4 of RAM)");
  c->add_option("--checkpoint", args->checkpoint,
                "Every SECONDS (0: after every pass), write the image so far to the output and its resumable state to "
                "OUTPUT.state")
      ->check(CLI::Range(0.0, 1e9));
  c->add_flag("--resume", args->resume, "Continue the render saved in OUTPUT.state (same scene and options)");
  c->add_option("--pass-samples", args->pass_samples,
                "Samples per pixel per pass (default: passes of about a second); the image does not depend on it")
      ->check(CLI::Range(1, 1 << 24));
  c->add_flag("--adaptive", args->adaptive,
              "Adaptive sampling: each pixel takes samples in proportion to how noisy its samples are, until the "
              "image's error reaches --target-error (docs/adaptive-sampling.md)");
  c->add_option("--target-error", args->target_error,
                "Adaptive: the RMS over pixels of the relative error of their mean luminance (default 0.01)")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            double e = 0;
            try {
              e = std::stod(v);
            } catch (const std::exception&) {
              return "\"" + v + "\" is not a number";
            }
            return std::isfinite(e) && e > 0 && e < 1e3 ? "" : "\"" + v + "\": must be a number in (0, 1000)";
          },
          "E"));
  c->add_option("--min-spp", args->min_spp, "Adaptive: samples every pixel takes before any stops (default 16)")
      ->check(CLI::Range(2, 1 << 20));
  c->add_option("--max-spp", args->max_spp,
                "Adaptive: the most samples a pixel takes (default: --spp or the Sampler's)")
      ->check(CLI::Range(1, 1 << 24));
  c->add_option("--spp-image", args->spp_image, "Write each pixel's sample count to this EXR (one channel, \"spp\")")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            std::string ext = std::filesystem::path(v).extension().string();
            for (auto& ch : ext) ch = char(std::tolower(ch));
            return ext == ".exr" ? "" : "\"" + v + "\": the sample-count image is written as .exr";
          },
          "PATH"));
  c->add_option("--mpi-split", args->mpi_split,
                "Under mpirun: deal tiles out \"interleaved\" (tile t to rank t mod N; the default) or in "
                "\"blocks\" of rows (docs/cluster.md); the image is the same either way")
      ->check(CLI::IsMember({"interleaved", "blocks"}));
  c->callback([args, c] {
    for (const char* o : {"--target-error", "--min-spp", "--max-spp"})
      if (c->count(o) && !args->adaptive) throw CLI::ValidationError(o, "needs --adaptive");
    if (args->adaptive && args->max_spp > 0 && args->max_spp < args->min_spp)
      throw CLI::ValidationError("--max-spp", fmt::format("{} is below --min-spp {}, the first pass every pixel takes",
                                                          args->max_spp, args->min_spp));
    if (c->count("--max-spp") && c->count("--spp") && args->max_spp != args->spp)
      throw CLI::ValidationError("--max-spp", "differs from --spp: with --adaptive, give one of them");
  });
  return [args] { return run_render(*args); };
}

}  // namespace eyetrace
