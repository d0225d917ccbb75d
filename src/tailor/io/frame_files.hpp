#pragma once
/// @file
/// Frame file names: natural order, glob expansion, and telling sequences apart by name.

#include <filesystem>
#include <string>
#include <vector>

namespace tailor {

/// Sorts frame files in natural order: by the number in the file name (the last run of
/// digits, compared as a number of any length, so `frame_2` comes before `frame_10` and
/// `frame_02` ties with `frame_2`), names without a number last, ties by file name.
void sort_frame_files(std::vector<std::filesystem::path>& paths);

/// The number in a frame file's name: the last run of digits of its stem, leading zeros
/// dropped (`cloth_0012.obj` → `12`); empty when the name has no digit.
std::string frame_number(const std::filesystem::path& path);

/// True when `text` holds a glob wildcard (`*`, `?` or `[`).
bool has_glob_wildcard(const std::string& text);

/// The `.obj`/`.ply` files (any case) matching the shell glob `pattern` (`*`, `?`, `[...]`,
/// in any path component), in natural order (sort_frame_files). Throws InputError naming
/// the pattern if no mesh file matches.
std::vector<std::filesystem::path> expand_frame_glob(const std::string& pattern);

/// The name pattern of a frame file: its file name with the last run of digits replaced by
/// `*` and the extension in lower case (`cloth_0012.OBJ` → `cloth_*.obj`); the file name
/// as is when it has no digit. Files of one sequence share their name pattern.
std::string frame_name_pattern(const std::filesystem::path& path);

/// Frame files that share one name pattern, in the order given.
struct FrameFileGroup {
  std::string name_pattern;                  ///< e.g. `cloth_*.obj`
  std::vector<std::filesystem::path> paths;  ///< the files, in the order given
};

/// Splits `paths` by name pattern (frame_name_pattern), each group in the order given,
/// groups in order of their first file.
std::vector<FrameFileGroup> group_frame_files(const std::vector<std::filesystem::path>& paths);

}  // namespace tailor
