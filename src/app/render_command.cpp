// `eyetrace render SCENE.pbrt`: parse, apply command-line overrides, render, write.
#include <fmt/core.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "core/parser.h"
#include "core/progress.h"
#include "core/scene_builder.h"

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
  std::string stats;
  double max_memory_gib = 0;
};

IVec2 parse_resolution(const std::string& s) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 1 || h < 1 ||
      w > 32768 || h > 32768)
    throw_error(fmt::format("--resolution \"{}\": expected WxH with 1 <= W, H <= 32768", s));
  return IVec2(w, h);
}

Vec4 parse_crop(const std::string& s) {
  float v[4];
  char extra = 0;
  if (std::sscanf(s.c_str(), "%f,%f,%f,%f%c", &v[0], &v[1], &v[2], &v[3], &extra) != 4)
    throw_error(fmt::format("--crop \"{}\": expected four fractions x0,x1,y0,y1", s));
  if (!(v[0] >= 0 && v[0] < v[1] && v[1] <= 1 && v[2] >= 0 && v[2] < v[3] && v[3] <= 1))
    throw_error(fmt::format("--crop \"{}\": needs 0 <= x0 < x1 <= 1 and 0 <= y0 < y1 <= 1", s));
  return Vec4(v[0], v[1], v[2], v[3]);
}

uint64_t default_memory_limit() {
  long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) / 4 * 3 : 0;
}

void check_output_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& c : ext) c = char(std::tolower(c));
  if (ext != ".exr" && ext != ".png")
    throw_error(fmt::format("output \"{}\": the extension must be .exr (linear float) or .png (sRGB 8-bit)", path));
}

int run_render(const RenderArgs& a) {
  set_warnings_enabled(!a.quiet);
  SceneDescription desc = parse_scene_file(a.scene);
  RenderOverrides o;
  if (!a.camera.empty()) o.camera = parse_directive_text(a.camera, "Camera", "--camera");
  if (!a.resolution.empty()) o.resolution = parse_resolution(a.resolution);
  if (!a.crop.empty()) o.crop = parse_crop(a.crop);
  o.spp = a.spp;
  if (a.seed >= 0) o.seed = uint64_t(a.seed);
  o.max_memory_bytes = a.max_memory_gib > 0 ? uint64_t(a.max_memory_gib * 1073741824.0) : default_memory_limit();

  ProgressLine progress(!a.quiet);
  RenderSetup setup = build_render_setup(desc, o);
  std::string output = a.output.empty() ? setup.output_filename : a.output;
  check_output_extension(output);
  double setup_seconds = progress.elapsed_seconds();

  RenderCounters counters;
  RenderOptions ro;
  ro.threads = a.threads;
  ro.on_progress = [&](double f, uint64_t rays) { progress.update(f, rays); };
  setup.integrator->render(*setup.camera, *setup.sampler, *setup.film, ro, counters);
  progress.finish();
  double seconds = progress.elapsed_seconds();
  double render_seconds = seconds - setup_seconds;

  int spp = setup.sampler->samples_per_pixel();
  write_image(output, setup.film->image(),
              {{"eyetrace:samples_per_pixel", std::to_string(spp)},
               {"eyetrace:scene", a.scene},
               {"eyetrace:camera", setup.camera->to_string()}});
  uint64_t rays = counters.rays_traced, cam = counters.camera_rays, lost = counters.camera_rays_lost;
  if (!a.quiet)
    fmt::print("{}: {:.2f} s ({:.2f} s render), {} spp, {} camera rays ({:.1f}% lost), {:.2f} Mrays/s{}\n", output,
               seconds, render_seconds, spp, cam, cam ? 100.0 * lost / cam : 0.0,
               render_seconds > 0 ? rays / render_seconds / 1e6 : 0.0,
               counters.nonfinite_samples ? fmt::format(", {} non-finite samples discarded", counters.nonfinite_samples.load()) : "");
  if (!a.stats.empty()) {
    nlohmann::json j = {{"scene", a.scene},
                        {"output", output},
                        {"seconds", seconds},
                        {"setup_seconds", setup_seconds},
                        {"render_seconds", render_seconds},
                        {"samples_per_pixel", spp},
                        {"samples", counters.samples.load()},
                        {"camera_rays", cam},
                        {"camera_rays_lost", lost},
                        {"useful_camera_ray_fraction", cam ? double(cam - lost) / cam : 0.0},
                        {"rays_traced", rays},
                        {"rays_per_second", render_seconds > 0 ? rays / render_seconds : 0.0},
                        {"nonfinite_samples", counters.nonfinite_samples.load()},
                        {"threads", a.threads},
                        {"resolution", {setup.film->resolution().x, setup.film->resolution().y}},
                        {"camera", setup.camera->to_string()},
                        {"warnings", warning_count()}};
    std::string tmp = a.stats + ".tmp";
    {
      std::ofstream f(tmp);
      f << j.dump(2) << "\n";
      if (!f) throw_error(fmt::format("--stats \"{}\": cannot write", a.stats));
    }
    std::filesystem::rename(tmp, a.stats);
  }
  return 0;
}

}  // namespace

CommandRunner add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* c = app.add_subcommand("render", "Render a pbrt-v4 scene file");
  c->add_option("scene", args->scene, "Scene file (pbrt-v4 text format)")->required();
  c->add_option("-o,--output", args->output, "Output image: .exr (linear float) or .png (sRGB 8-bit); default: the Film's filename");
  c->add_option("--spp", args->spp, "Samples per pixel (overrides the Sampler's pixelsamples)")->check(CLI::Range(1, 1 << 24));
  c->add_option("--resolution", args->resolution, "Image size WxH (overrides the Film's xresolution/yresolution)");
  c->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  c->add_option("--seed", args->seed, "Sampler seed; the same seed gives the same image for any thread count")->check(CLI::NonNegativeNumber);
  c->add_option("--crop", args->crop, "Render only x0,x1,y0,y1 (fractions of the image, as pbrt's cropwindow)");
  c->add_option("--camera", args->camera,
                "Replace the scene's camera with a Camera directive, e.g. 'Camera \"navarro\" \"float accommodation\" 2'");
  c->add_flag("-q,--quiet", args->quiet, "No progress line, summary or warnings");
  c->add_option("--stats", args->stats, "Write render statistics as JSON to this file");
  c->add_option("--max-memory", args->max_memory_gib, "Refuse renders predicted to need more GiB (default: 3/4 of RAM)");
  return [args] { return run_render(*args); };
}

}  // namespace eyetrace
