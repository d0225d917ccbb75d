#pragma once
/// @file
/// An animation of a rendered run that a person can open directly: the frames
/// `render_0000.png`, `render_0001.png`, ... encoded as an H.264 MP4 (yuv420p, which every
/// browser and player opens) by Debian's `ffmpeg`, run as a child process.

#include <filesystem>
#include <string>

namespace tailor {

/// What write_animation did.
struct AnimationResult {
  bool written = false;        ///< whether the MP4 was written
  std::filesystem::path path;  ///< the MP4 (when written)
  int frames = 0;              ///< frames encoded
  std::string reason;          ///< why nothing was written (when not)
};

/// Whether an executable `ffmpeg` is on the PATH.
bool ffmpeg_available();

/// Encodes `<prefix>_0000.png`, `<prefix>_0001.png`, ... (consecutive from 0) of `directory`
/// into `directory`/animation.mp4 at `fps` frames per second, atomically (written under
/// another name, then renamed). When ffmpeg is not installed nothing is written and the
/// result says why: the frames are still there. Throws InputError naming the folder when
/// it holds no `<prefix>_0000.png` or `fps` is not in (0, 1000], and naming ffmpeg's last
/// message when ffmpeg fails.
AnimationResult write_animation(const std::filesystem::path& directory, double fps = 30,
                                const std::string& prefix = "render");

}  // namespace tailor
