// A sampler that gives several paths of one camera sample the same stream of values without
// computing it again: the per-wavelength scene paths of a dispersive eye (Camera::
// traces_wavelengths_apart) all start from the sample's own sampler dimensions, and the sampler's
// values are a function of (pixel, sample index, dimension) alone (core/sampler.h), so the
// second path's values are the first's. record() starts a path that asks the underlying
// sampler and keeps what it gave; replay() starts one that is given the kept values, call by
// call. A path that departs from the recording (another kind of call, or more calls) gets from
// then on what the underlying sampler gives there: it is positioned at the recording's start
// and the replayed calls are made again. Every path therefore sees exactly the values it would
// have seen from the underlying sampler.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/sampler.h"

namespace eyetrace {

class ReplaySampler final : public Sampler {
 public:
  explicit ReplaySampler(Sampler& base) : base_(&base) {}
  // Positions the underlying sampler at (pixel, sample_index, dimension) and records the calls
  // that follow.
  void record(IVec2 pixel, int sample_index, int dimension);
  // Replays the last recording from its start.
  void replay();

  int samples_per_pixel() const override { return base_->samples_per_pixel(); }
  // Positions the underlying sampler, ending the recording there (a replay past this point asks
  // the underlying sampler from the recording's start).
  void start_pixel_sample(IVec2 pixel, int sample_index, int dimension = 0) override;
  float get_1d() override { return next(Kind::OneD).x; }
  Vec2 get_2d() override { return next(Kind::TwoD); }
  Vec2 get_pixel_2d() override { return next(Kind::Pixel2D); }
  // A clone is the underlying sampler's: a recording belongs to one thread's paths.
  std::unique_ptr<Sampler> clone() const override { return base_->clone(); }
  std::string to_string() const override { return base_->to_string(); }

 private:
  enum class Kind : unsigned char { OneD, TwoD, Pixel2D };
  enum class Mode : unsigned char { Live, Record, Replay };
  struct Call {
    Kind kind;
    Vec2 value;
  };
  Vec2 next(Kind kind);
  Vec2 ask(Kind kind);
  void go_live();

  Sampler* base_;
  Mode mode_ = Mode::Live;
  std::vector<Call> calls_;  // the recording
  bool complete_ = true;     // false: the recorded path repositioned the sampler itself
  size_t next_ = 0;          // replay: the next call's place in the recording
  IVec2 pixel_{0};
  int sample_index_ = 0, dimension_ = 0;
};

}  // namespace eyetrace
