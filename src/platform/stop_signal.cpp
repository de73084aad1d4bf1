#include "platform/stop_signal.hpp"

#include <csignal>
#include <initializer_list>

namespace cardemo {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void onStopSignal(int sig) {
  g_stop_signal = sig;
}

}  // namespace

// SA_RESETHAND: a second signal of the same kind kills at once, which loses at most the last
// second of the recording (it is flushed every second). A full disk or a file-size limit must be
// an error on write, not SIGXFSZ; a closed standard output (--progress into a pipe) must not kill
// the game with SIGPIPE.
void installStopSignals() {
  static bool installed = false;  // again would re-arm a handler SA_RESETHAND already reset
  if (installed) return;
  installed = true;
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &action, nullptr);
  std::signal(SIGXFSZ, SIG_IGN);
  std::signal(SIGPIPE, SIG_IGN);
}

int stopSignal() {
  return static_cast<int>(g_stop_signal);
}

}  // namespace cardemo
