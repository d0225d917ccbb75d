/// @file
/// Natural order, glob expansion and name patterns of frame files.

#include "tailor/io/frame_files.hpp"

#include <fmt/format.h>
#include <glob.h>

#include <algorithm>
#include <cctype>
#include <system_error>
#include <unordered_map>

#include "tailor/geometry/error.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor {
namespace {

/// Where the last run of digits of a file stem starts and ends (`end == 0`: no digit).
struct DigitRun {
  std::size_t begin = 0, end = 0;
};

DigitRun last_digit_run(const std::string& stem) {
  std::size_t end = stem.size();
  while (end > 0 && !std::isdigit(static_cast<unsigned char>(stem[end - 1]))) --end;
  std::size_t begin = end;
  while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
  return {begin, end};
}

/// Orders numbers as digit strings, so any length works without overflow.
bool number_less(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return a.size() < b.size();
  return a < b;
}

std::string lower_case(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

std::string frame_number(const std::filesystem::path& path) {
  const std::string stem = path.stem().string();
  DigitRun run = last_digit_run(stem);
  if (run.end == 0) return {};
  while (run.begin + 1 < run.end && stem[run.begin] == '0') ++run.begin;
  return stem.substr(run.begin, run.end - run.begin);
}

void sort_frame_files(std::vector<std::filesystem::path>& paths) {
  struct Entry {
    std::string number;  // empty: no number
    std::filesystem::path path;
  };
  std::vector<Entry> entries;
  entries.reserve(paths.size());
  for (auto& path : paths) entries.push_back({frame_number(path), std::move(path)});
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    if (a.number.empty() != b.number.empty()) return b.number.empty();
    if (a.number != b.number) return number_less(a.number, b.number);
    return a.path.filename() < b.path.filename();
  });
  paths.clear();
  for (Entry& entry : entries) paths.push_back(std::move(entry.path));
}

bool has_glob_wildcard(const std::string& text) {
  return text.find_first_of("*?[") != std::string::npos;
}

std::vector<std::filesystem::path> expand_frame_glob(const std::string& pattern) {
  glob_t matches{};
  const int status = ::glob(pattern.c_str(), GLOB_NOSORT, nullptr, &matches);
  std::vector<std::filesystem::path> paths;
  if (status == 0) {
    for (std::size_t i = 0; i < matches.gl_pathc; ++i) {
      std::filesystem::path path(matches.gl_pathv[i]);
      std::error_code ec;
      if (std::filesystem::is_regular_file(path, ec) && is_mesh_file_name(path)) {
        paths.push_back(std::move(path));
      }
    }
  }
  globfree(&matches);
  if (status != 0 && status != GLOB_NOMATCH) {
    throw InputError(
        fmt::format("cannot expand the frame pattern '{}' (a folder on the way "
                    "cannot be read, or out of memory)",
                    pattern));
  }
  if (paths.empty()) {
    throw InputError(fmt::format("no .obj or .ply files match '{}'", pattern));
  }
  sort_frame_files(paths);
  return paths;
}

std::string frame_name_pattern(const std::filesystem::path& path) {
  const std::string stem = path.stem().string();
  const std::string extension = lower_case(path.extension().string());
  const DigitRun run = last_digit_run(stem);
  if (run.end == 0) return stem + extension;
  return stem.substr(0, run.begin) + "*" + stem.substr(run.end) + extension;
}

std::vector<FrameFileGroup> group_frame_files(const std::vector<std::filesystem::path>& paths) {
  std::vector<FrameFileGroup> groups;
  std::unordered_map<std::string, std::size_t> group_of_name;
  for (const auto& path : paths) {
    std::string name = frame_name_pattern(path);
    const auto [it, added] = group_of_name.try_emplace(name, groups.size());
    if (added) groups.push_back({std::move(name), {}});
    groups[it->second].paths.push_back(path);
  }
  return groups;
}

}  // namespace tailor
