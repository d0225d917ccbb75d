#include "bench/svg_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "tailor/io/file_bytes.hpp"

namespace tailor {
namespace {

constexpr double kWidth = 760, kHeight = 440;
constexpr double kLeft = 80, kRight = 190, kTop = 40, kBottom = 60;
constexpr std::array<const char*, 8> kColors{"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                             "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};

struct Axis {
  double lo, hi;
  bool log;
  double map(double v, double from, double to) const {
    const double a = log ? std::log10(lo) : lo, b = log ? std::log10(hi) : hi;
    const double t = ((log ? std::log10(v) : v) - a) / (b - a);
    return from + t * (to - from);
  }
  std::vector<double> ticks() const {
    std::vector<double> out;
    if (log) {
      for (double p = std::floor(std::log10(lo)); p <= std::ceil(std::log10(hi)); ++p) {
        const double v = std::pow(10.0, p);
        if (v >= lo && v <= hi) out.push_back(v);
      }
    } else {
      const double raw = (hi - lo) / 5;
      const double mag = std::pow(10.0, std::floor(std::log10(raw)));
      const double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
      for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) {
        out.push_back(v);
      }
    }
    return out;
  }
};

Axis make_axis(const std::vector<PlotSeries>& series, bool use_x, bool log) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& s : series) {
    for (double v : use_x ? s.x : s.y) {
      if (log && !(v > 0)) continue;
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
  }
  if (!(lo <= hi)) lo = log ? 1 : 0, hi = log ? 10 : 1;
  if (!log && lo > 0 && !use_x) lo = 0;
  if (hi == lo) hi = log ? lo * 10 : lo + 1;
  return {lo, hi, log};
}

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

}  // namespace

std::string LinePlot::to_svg() const {
  const Axis ax = make_axis(series, true, log_x), ay = make_axis(series, false, log_y);
  const double x0 = kLeft, x1 = kWidth - kRight, y0 = kHeight - kBottom, y1 = kTop;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
      "fill=\"white\"/>\n<text x=\"{}\" y=\"22\" font-size=\"15\">{}</text>\n",
      kWidth, kHeight, kLeft, escape(title));
  for (double t : ax.ticks()) {
    const double x = ax.map(t, x0, x1);
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#ddd\"/>"
        "<text x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\">{4:g}</text>\n",
        x, y0, y1, y0 + 16, t);
  }
  for (double t : ay.ticks()) {
    const double y = ay.map(t, y0, y1);
    svg += fmt::format(
        "<line x1=\"{1}\" y1=\"{0:.1f}\" x2=\"{2}\" y2=\"{0:.1f}\" stroke=\"#ddd\"/>"
        "<text x=\"{3}\" y=\"{0:.1f}\" text-anchor=\"end\" dy=\"4\">{4:g}</text>\n",
        y, x0, x1, x0 - 6, t);
  }
  svg += fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" "
      "stroke=\"black\"/>\n",
      x0, y1, x1 - x0, y0 - y1);
  svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", 0.5 * (x0 + x1),
                     kHeight - 18, escape(x_label));
  svg += fmt::format(
      "<text x=\"18\" y=\"{0}\" text-anchor=\"middle\" "
      "transform=\"rotate(-90 18 {0})\">{1}</text>\n",
      0.5 * (y0 + y1), escape(y_label));
  for (std::size_t i = 0; i < series.size(); ++i) {
    const PlotSeries& s = series[i];
    const char* color = kColors[i % kColors.size()];
    std::string points;
    for (std::size_t k = 0; k < std::min(s.x.size(), s.y.size()); ++k) {
      if ((log_x && !(s.x[k] > 0)) || (log_y && !(s.y[k] > 0))) continue;
      points += fmt::format("{:.1f},{:.1f} ", ax.map(s.x[k], x0, x1), ay.map(s.y[k], y0, y1));
    }
    svg += fmt::format(
        "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.6\" "
        "points=\"{}\"/>\n",
        color, points);
    const double ly = kTop + 14 + 18 * static_cast<double>(i);
    svg += fmt::format(
        "<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"{3}\" "
        "stroke-width=\"3\"/><text x=\"{4}\" y=\"{1}\" dy=\"4\">{5}</text>\n",
        x1 + 12, ly, x1 + 32, color, x1 + 38, escape(s.name));
  }
  return svg + "</svg>\n";
}

void LinePlot::write(const std::filesystem::path& path) const {
  write_file_atomically(path, to_svg());
}

}  // namespace tailor
