#pragma once
/// @file
/// Writes the folder `tailor view` produces: `index.html` and `viewer.js` (the page, with
/// three.js bundled in), `data/scene.js` (faces once, clusters, per-frame statistics) and
/// `data/frame_NNNN.js` (one frame's positions, and its contacts, as little-endian
/// Float32 / Uint32 arrays in base64; the layout is in docs/viewer.md). Every data file is a classic script calling `tailorViewData.scene`
/// or `tailorViewData.frame`, so the page loads it with a <script> tag both from file://
/// (where Chromium allows no fetch of local files) and over HTTP.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "view/view_input.hpp"

namespace tailor::cli {

/// What write_view wrote.
struct ViewOutput {
  std::filesystem::path index_html;
  int frames = 0;
  std::uintmax_t bytes = 0;  ///< total size of the files written
};

/// Writes the data files of every frame of `input`, then the page, into `out` (created if
/// needed). The data is written first and index.html last (after removing a stale one),
/// so a run that stops on bad input leaves no page pointing at half the data. Throws
/// InputError naming the file on bad input (e.g. a coordinate beyond the float range) or
/// if a file cannot be written, and std::runtime_error if this build has no page assets.
ViewOutput write_view(const ViewInput& input, const std::filesystem::path& out);

/// Standard base64 (RFC 4648, with padding) of `bytes`.
std::string base64_encode(std::string_view bytes);

}  // namespace tailor::cli
