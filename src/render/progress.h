// A one-line progress display (percent, time left, rays/s) for terminals; silent otherwise.
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

namespace eyetrace {

class ProgressLine {
 public:
  // Shows progress only when `enabled` and stderr is a terminal.
  explicit ProgressLine(bool enabled);
  // A resumed render starts part-way: time left is estimated from the work done since.
  void resume_at(double fraction) { start_fraction_ = fraction; }
  void update(double fraction, uint64_t rays);
  void finish();
  double elapsed_seconds() const;

 private:
  bool active_;
  bool drawn_ = false;
  double start_fraction_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace eyetrace
