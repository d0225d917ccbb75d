#pragma once
/// @file
/// What a command line's frame arguments name: one frame sequence, plus an obstacle sequence.

#include <filesystem>
#include <string>
#include <vector>

namespace tailor {

/// A checked sequence and, when there is one, the obstacle moving with it.
struct FrameSources {
  std::vector<std::filesystem::path> frames;    ///< the sequence, in order (at least one file)
  std::vector<std::filesystem::path> obstacle;  ///< obstacle frames in order; empty: none
  std::string frames_pattern;                   ///< name pattern of the frames, e.g. `cloth_*.obj`
  std::string obstacle_pattern;  ///< name pattern of the obstacle frames ("" without one)
  /// True when the obstacle was taken from the simulator's layout (`arm_*.obj` beside
  /// `cloth_*.obj`) rather than named.
  bool obstacle_from_layout = false;
};

/// Resolves frame arguments into the files of one sequence:
/// - one argument: a folder, a printf pattern or a glob (list_frame_files), or a single
///   mesh file (a one-frame sequence);
/// - several arguments: mesh files (as a shell expands `out/cloth_*.obj`), put in natural
///   order (sort_frame_files).
/// The files must form one sequence: they all share one name pattern (frame_name_pattern)
/// and no two carry the same number (`f_2.obj` and `f_02.obj`). One exception: the
/// layout `tailor simulate` writes, `cloth_*.obj` beside `arm_*.obj`, is read as the cloth
/// sequence with the arm as its obstacle (unless `obstacle` names one). Any other mix is an
/// InputError that lists the sequences found and asks for a pattern.
/// `obstacle` (optional) is resolved the same way and must be one sequence.
/// Throws InputError naming the argument and the problem.
FrameSources resolve_frame_sources(const std::vector<std::string>& frames,
                                   const std::string& obstacle = "");

}  // namespace tailor
