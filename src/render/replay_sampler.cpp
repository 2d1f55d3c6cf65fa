#include "render/replay_sampler.h"

namespace eyetrace {

void ReplaySampler::record(IVec2 pixel, int sample_index, int dimension) {
  pixel_ = pixel;
  sample_index_ = sample_index;
  dimension_ = dimension;
  base_->start_pixel_sample(pixel, sample_index, dimension);
  calls_.clear();
  complete_ = true;
  mode_ = Mode::Record;
}

void ReplaySampler::replay() {
  next_ = 0;
  mode_ = Mode::Replay;
  // A recording cut short by the path's own repositioning cannot be continued from: the path
  // asks the underlying sampler from the start.
  if (!complete_) go_live();
}

void ReplaySampler::start_pixel_sample(IVec2 pixel, int sample_index, int dimension) {
  if (mode_ == Mode::Record) complete_ = false;
  mode_ = Mode::Live;
  base_->start_pixel_sample(pixel, sample_index, dimension);
}

Vec2 ReplaySampler::ask(Kind kind) {
  switch (kind) {
    case Kind::OneD: return Vec2(base_->get_1d(), 0.f);
    case Kind::TwoD: return base_->get_2d();
    case Kind::Pixel2D: break;
  }
  return base_->get_pixel_2d();
}

// The underlying sampler where the replayed calls so far have left a path: at the recording's
// start, the same calls made again.
void ReplaySampler::go_live() {
  base_->start_pixel_sample(pixel_, sample_index_, dimension_);
  for (size_t i = 0; i < next_; ++i) ask(calls_[i].kind);
  mode_ = Mode::Live;
}

Vec2 ReplaySampler::next(Kind kind) {
  if (mode_ == Mode::Replay) {
    if (next_ < calls_.size() && calls_[next_].kind == kind) return calls_[next_++].value;
    go_live();  // the path departs from the recording here
  }
  const Vec2 v = ask(kind);
  if (mode_ == Mode::Record) calls_.push_back({kind, v});
  return v;
}

}  // namespace eyetrace
