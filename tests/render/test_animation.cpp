/// @file
/// animation.mp4 through ffmpeg (installed by scripts/install-deps.sh): the frames come back
/// out of the MP4 in order and in their colours; a missing ffmpeg, a folder without frames
/// and frames ffmpeg cannot read are reported.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tailor/geometry/error.hpp"
#include "tailor/render/animation.hpp"
#include "tailor/render/image.hpp"

namespace tailor {
namespace {

namespace fs = std::filesystem;

/// A fresh folder under the system's temporary folder.
fs::path fresh_folder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

/// Frame f is a flat colour that changes from frame to frame (odd size: ffmpeg must pad).
Rgb frame_colour(int f) {
  return {static_cast<std::uint8_t>(40 + 50 * f), static_cast<std::uint8_t>(200 - 40 * f), 120};
}

TEST(Animation, TheMp4HoldsEveryFrameInOrder) {
  ASSERT_TRUE(ffmpeg_available()) << "scripts/install-deps.sh installs Debian's ffmpeg";
  const fs::path folder = fresh_folder("tailor_test_animation");
  for (int f = 0; f < 4; ++f)
    write_png(folder / ("render_000" + std::to_string(f) + ".png"), Image(65, 49, frame_colour(f)));
  const AnimationResult result = write_animation(folder, 10);
  ASSERT_TRUE(result.written) << result.reason;
  EXPECT_EQ(result.frames, 4);
  EXPECT_EQ(result.path, folder / "animation.mp4");
  EXPECT_FALSE(fs::exists(folder / "animation.mp4.part"));
  EXPECT_FALSE(fs::exists(folder / "animation.log"));
  std::ifstream mp4(result.path, std::ios::binary);
  std::string head(8, '\0');
  mp4.read(head.data(), 8);
  EXPECT_EQ(head.substr(4, 4), "ftyp");
  // Decoded again: four frames, each (after yuv420p and H.264) near its colour.
  const std::string decode = "ffmpeg -nostdin -loglevel error -i " + result.path.string() + " " +
                             (folder / "back_%04d.png").string();
  ASSERT_EQ(std::system(decode.c_str()), 0);
  for (int f = 0; f < 4; ++f) {
    const Image back = read_png(folder / ("back_000" + std::to_string(f + 1) + ".png"));
    ASSERT_EQ(back.width(), 64);  // even sizes for yuv420p
    const Rgb centre = back.at(32, 24), want = frame_colour(f);
    EXPECT_NEAR(centre.r, want.r, 8) << "frame " << f;
    EXPECT_NEAR(centre.g, want.g, 8) << "frame " << f;
    EXPECT_NEAR(centre.b, want.b, 8) << "frame " << f;
  }
  EXPECT_FALSE(fs::exists(folder / "back_0005.png"));
}

TEST(Animation, WithoutFfmpegNothingIsWrittenAndTheReasonSaysSo) {
  const fs::path folder = fresh_folder("tailor_test_animation_no_ffmpeg");
  write_png(folder / "render_0000.png", Image(8, 8, {1, 2, 3}));
  const std::string path = std::getenv("PATH") != nullptr ? std::getenv("PATH") : "";
  setenv("PATH", "/nonexistent", 1);
  const bool available = ffmpeg_available();
  AnimationResult result;
  EXPECT_NO_THROW(result = write_animation(folder));
  setenv("PATH", path.c_str(), 1);
  EXPECT_FALSE(available);
  EXPECT_FALSE(result.written);
  EXPECT_NE(result.reason.find("ffmpeg"), std::string::npos) << result.reason;
  EXPECT_FALSE(fs::exists(folder / "animation.mp4"));
}

TEST(Animation, BadFoldersAndFramesAreInputErrorsNamingTheFolder) {
  const fs::path empty = fresh_folder("tailor_test_animation_empty");
  try {
    write_animation(empty);
    FAIL() << "a folder without frames was animated";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(empty.string()), std::string::npos) << e.what();
  }
  const fs::path broken = fresh_folder("tailor_test_animation_broken");
  std::ofstream(broken / "render_0000.png") << "not a png";
  EXPECT_THROW(write_animation(broken, 0), InputError);
  if (!ffmpeg_available()) GTEST_SKIP() << "needs ffmpeg to fail on the frame";
  try {
    write_animation(broken);
    FAIL() << "ffmpeg encoded a frame that is not a PNG";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(broken.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(broken / "animation.mp4"));
  EXPECT_FALSE(fs::exists(broken / "animation.mp4.part"));
}

}  // namespace
}  // namespace tailor
