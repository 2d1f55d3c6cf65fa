#include "render/progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>

namespace eyetrace {

ProgressLine::ProgressLine(bool enabled)
    : active_(enabled && isatty(fileno(stderr))), start_(std::chrono::steady_clock::now()) {}

double ProgressLine::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressLine::update(double fraction, uint64_t rays) {
  if (!active_) return;
  double t = elapsed_seconds();
  double run = fraction - start_fraction_;
  double left = run > 0 ? t * (1 - fraction) / run : 0;
  const int width = 30;
  int filled = int(fraction * width);
  std::string bar(filled, '=');
  bar.resize(width, ' ');
  std::fprintf(stderr, "\r[%s] %5.1f%%  %6.1fs elapsed  %6.1fs left  %7.2f Mrays/s ", bar.c_str(), 100 * fraction, t,
               left, t > 0 ? rays / t / 1e6 : 0.0);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::finish() {
  if (active_ && drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace eyetrace
