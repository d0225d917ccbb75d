#pragma once
/// @file
/// A minimal SVG line-plot writer for the benchmark figures.

#include <filesystem>
#include <string>
#include <vector>

namespace tailor {

/// One named series of (x, y) points.
struct PlotSeries {
  std::string name;
  std::vector<double> x, y;
};

/// A line plot with axes, ticks, a legend and optional logarithmic axes.
struct LinePlot {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  std::vector<PlotSeries> series;

  /// The plot as an SVG document.
  std::string to_svg() const;
  /// Writes to_svg() to `path` (via a temporary file, then renamed).
  void write(const std::filesystem::path& path) const;
};

}  // namespace tailor
