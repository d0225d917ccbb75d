/// @file
/// The SIGINT handler behind InterruptGuard.

#include "interrupt.hpp"

#include <csignal>

namespace tailor::cli {
namespace {

volatile std::sig_atomic_t g_interrupted = 0;
using Handler = void (*)(int);
Handler g_previous = SIG_DFL;

extern "C" void on_sigint(int) {
  if (g_interrupted != 0) {
    // Second Ctrl-C: stop now.
    std::signal(SIGINT, SIG_DFL);
    std::raise(SIGINT);
  }
  g_interrupted = 1;
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_interrupted = 0;
  g_previous = std::signal(SIGINT, on_sigint);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, g_previous);
}

bool InterruptGuard::interrupted() const {
  return g_interrupted != 0;
}

}  // namespace tailor::cli
