#pragma once
// Writes procedural frame sequences to disk for the sequence-checking tests.

#include <fmt/format.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tailor/io/mesh_io.hpp"
#include "tailor/mesh/procedural_sequences.hpp"

namespace tailor::testing {

/// Writes frame k of `sequence` to `folder / fmt::format(name_format, k)` (e.g.
/// "fold_{:04d}.ply"; OBJ or PLY by the extension) and returns the paths in order.
inline std::vector<std::filesystem::path> write_sequence(const std::filesystem::path& folder,
                                                         const ProceduralSequence& sequence,
                                                         const std::string& name_format) {
  std::vector<std::filesystem::path> paths;
  for (std::size_t k = 0; k < sequence.frames.size(); ++k) {
    paths.push_back(folder / fmt::format(fmt::runtime(name_format), k));
    write_mesh(paths.back(), sequence.frames[k], sequence.faces);
  }
  return paths;
}

}  // namespace tailor::testing
