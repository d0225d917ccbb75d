/// @file
/// Frame arguments to one sequence (plus the simulator's obstacle), with clear errors.

#include "tailor/io/frame_sources.hpp"

#include <fmt/format.h>

#include <system_error>

#include "tailor/geometry/error.hpp"
#include "tailor/io/frame_files.hpp"
#include "tailor/io/frame_sequence.hpp"

namespace tailor {
namespace {

// The file names `tailor simulate` writes (sim/frame_writer.hpp: cloth_0007.obj,
// arm_0007.obj); io/ sits below sim/, so the names are repeated here.
constexpr const char* kSimulatorCloth = "cloth_*.obj";
constexpr const char* kSimulatorArm = "arm_*.obj";

std::vector<std::filesystem::path> list_arguments(const std::vector<std::string>& arguments) {
  if (arguments.empty()) throw InputError("no frames given");
  std::error_code ec;
  if (arguments.size() == 1) {
    const std::filesystem::path path(arguments.front());
    if (std::filesystem::is_regular_file(path, ec)) return {path};
    return list_frame_files(path);
  }
  std::vector<std::filesystem::path> paths;
  for (const std::string& argument : arguments) {
    if (!std::filesystem::is_regular_file(argument, ec)) {
      throw InputError(fmt::format(
          "{}: cannot open (several frame arguments must each be a mesh file)", argument));
    }
    paths.emplace_back(argument);
  }
  sort_frame_files(paths);
  return paths;
}

std::string describe(const std::vector<std::string>& arguments) {
  return arguments.size() == 1 ? arguments.front()
                               : fmt::format("the {} frame files given", arguments.size());
}

/// Throws if two files of one sequence carry the same number (their order is ambiguous).
void check_distinct_numbers(const FrameFileGroup& group, const std::string& where) {
  for (std::size_t i = 1; i < group.paths.size(); ++i) {
    const std::string number = frame_number(group.paths[i]);
    if (!number.empty() && number == frame_number(group.paths[i - 1])) {
      throw InputError(fmt::format("{}: {} and {} both carry frame number {}", where,
                                   group.paths[i - 1].string(), group.paths[i].string(), number));
    }
  }
}

[[noreturn]] void throw_mixed(const std::vector<FrameFileGroup>& groups, const std::string& where,
                              const std::filesystem::path& folder) {
  std::string list;
  for (std::size_t i = 0; i < groups.size() && i < 5; ++i) {
    list += fmt::format("{}{} ({} file{})", i == 0 ? "" : ", ", groups[i].name_pattern,
                        groups[i].paths.size(), groups[i].paths.size() == 1 ? "" : "s");
  }
  if (groups.size() > 5) list += fmt::format(", and {} more", groups.size() - 5);
  const std::filesystem::path example = folder / groups.front().name_pattern;
  throw InputError(
      fmt::format("{} mixes {} frame sequences: {}; name one with a pattern such as '{}'", where,
                  groups.size(), list, example.string()));
}

}  // namespace

FrameSources resolve_frame_sources(const std::vector<std::string>& frames,
                                   const std::string& obstacle) {
  const std::string where = describe(frames);
  const std::vector<std::filesystem::path> paths = list_arguments(frames);
  std::vector<FrameFileGroup> groups = group_frame_files(paths);
  FrameSources sources;
  if (groups.size() == 2 && groups[0].name_pattern == kSimulatorArm &&
      groups[1].name_pattern == kSimulatorCloth) {
    std::swap(groups[0], groups[1]);
  }
  if (groups.size() == 2 && groups[0].name_pattern == kSimulatorCloth &&
      groups[1].name_pattern == kSimulatorArm) {
    check_distinct_numbers(groups[1], where);
    if (obstacle.empty()) {
      sources.obstacle = std::move(groups[1].paths);
      sources.obstacle_pattern = groups[1].name_pattern;
      sources.obstacle_from_layout = true;
    }
    groups.pop_back();
  }
  if (groups.size() != 1) throw_mixed(groups, where, paths.front().parent_path());
  check_distinct_numbers(groups.front(), where);
  sources.frames = std::move(groups.front().paths);
  sources.frames_pattern = groups.front().name_pattern;

  if (!obstacle.empty()) {
    const std::vector<std::filesystem::path> obstacle_paths = list_arguments({obstacle});
    std::vector<FrameFileGroup> obstacle_groups = group_frame_files(obstacle_paths);
    if (obstacle_groups.size() != 1) {
      throw_mixed(obstacle_groups, obstacle, obstacle_paths.front().parent_path());
    }
    check_distinct_numbers(obstacle_groups.front(), obstacle);
    sources.obstacle = std::move(obstacle_groups.front().paths);
    sources.obstacle_pattern = obstacle_groups.front().name_pattern;
  }
  return sources;
}

}  // namespace tailor
