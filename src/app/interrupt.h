// SIGINT and SIGTERM during a render: the first signal asks the render to stop (it then
// writes the image so far and its resumable state, and exits with 128 + the signal number);
// a second signal exits at once without writing anything more.
#pragma once
#include <atomic>

namespace eyetrace {

class InterruptGuard {
 public:
  // Installs the handlers; the destructor restores the previous ones.
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Becomes true at the first signal; the render loop polls it between tiles.
  const std::atomic<bool>& stop_requested() const;
  // The signal received (SIGINT, SIGTERM), 0 if none.
  int signal_number() const;
};

}  // namespace eyetrace
