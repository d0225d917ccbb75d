/// @file
/// Progress bar and summary rows.

#include "progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace tailor::cli {

ProgressBar::ProgressBar(int total, std::string unit)
    : m_total(total), m_unit(std::move(unit)), m_enabled(isatty(fileno(stderr)) != 0) {}

void ProgressBar::update(int done, const std::string& detail) {
  if (!m_enabled) return;
  const int width = 30;
  const int filled = m_total > 0 ? std::clamp(width * done / m_total, 0, width) : width;
  fmt::print(stderr, "\r[{}{}] {} {}/{}  {}   ", std::string(static_cast<std::size_t>(filled), '#'),
             std::string(static_cast<std::size_t>(width - filled), '.'), m_unit, done, m_total,
             detail);
  std::fflush(stderr);
  m_drawn = true;
}

void ProgressBar::finish() {
  if (m_drawn) fmt::print(stderr, "\n");
  m_drawn = false;
}

void print_summary_row(const std::string& name, const std::string& value) {
  fmt::print("  {:<30} {}\n", name, value);
}

}  // namespace tailor::cli
