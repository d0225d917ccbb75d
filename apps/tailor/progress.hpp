#pragma once
/// @file
/// Terminal output of long-running commands: a progress bar and summary table rows.

#include <string>

namespace tailor::cli {

/// A one-line progress bar on stderr, drawn only when stderr is a terminal (so logs and
/// pipes never see it): `[######........] frame 12/200  <detail>`.
class ProgressBar {
 public:
  /// `total` units of work, each called `unit` (e.g. "frame", "step").
  ProgressBar(int total, std::string unit);
  /// True when the bar is drawn (stderr is a terminal).
  bool enabled() const { return m_enabled; }
  /// Redraws the bar with `done` units finished and a free-form `detail`.
  void update(int done, const std::string& detail);
  /// Ends the bar's line, if one was drawn.
  void finish();

 private:
  int m_total;
  std::string m_unit;
  bool m_enabled;
  bool m_drawn = false;
};

/// Prints one row of a summary table on stdout: two spaces, the name padded to 30, the value.
void print_summary_row(const std::string& name, const std::string& value);

}  // namespace tailor::cli
