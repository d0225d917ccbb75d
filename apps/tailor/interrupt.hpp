#pragma once
/// @file
/// Ctrl-C for long-running commands: stop between units of work, keep what was written.

namespace tailor::cli {

/// While a guard lives, the first SIGINT (Ctrl-C) only sets a flag that the command polls
/// between units of work (a frame, a step), so every file it already wrote stays complete;
/// a second SIGINT ends the process at once. The previous handler is restored at the end.
/// One guard at a time.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// True once Ctrl-C was pressed.
  bool interrupted() const;
};

/// Exit code of a command stopped by Ctrl-C (128 + SIGINT, as shells report it).
inline constexpr int kInterruptedExitCode = 130;

}  // namespace tailor::cli
