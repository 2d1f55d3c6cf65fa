#include "app/interrupt.h"

#include <signal.h>
#include <unistd.h>

#include <cstring>

namespace eyetrace {

namespace {

// Only lock-free atomics and write()/_exit() are safe inside a signal handler.
std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};
struct sigaction g_previous[2];
constexpr int kSignals[2] = {SIGINT, SIGTERM};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

void say(const char* text) {
  ssize_t ignored = write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

void on_signal(int sig) {
  int none = 0;
  g_signal.compare_exchange_strong(none, sig);  // before the stop flag: the exit code needs it
  if (g_stop.exchange(true)) {
    say("\neyetrace: second signal: exiting at once, nothing more written\n");
    _exit(128 + sig);
  }
  say("\neyetrace: interrupted: finishing the tiles in flight, then writing the image so far "
      "(signal again to quit at once)\n");
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_stop = false;
  g_signal = 0;
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // a signal must not make a file write fail half-way
  for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &sa, &g_previous[i]);
}

InterruptGuard::~InterruptGuard() {
  for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
}

const std::atomic<bool>& InterruptGuard::stop_requested() const { return g_stop; }

int InterruptGuard::signal_number() const { return g_signal; }

}  // namespace eyetrace
