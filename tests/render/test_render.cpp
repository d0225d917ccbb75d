/// @file
/// Rendering: PNG round trips and bad PNG data, the silhouette of a known scene (pixel
/// counts against the pinhole projection), candidate faces in red, contact sheets, and
/// the `tailor render` command on a real simulation folder.

#include "support/run_cli.hpp"
#include "support/sanitized.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "tailor/geometry/error.hpp"
#include "tailor/render/run_renderer.hpp"
#include "tailor/sim/frame_writer.hpp"

namespace tailor {
namespace {

namespace fs = std::filesystem;

TEST(Image, PngRoundTripIsExact) {
  Image image(37, 21, {1, 2, 3});
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x)
      image.at(x, y) = {static_cast<std::uint8_t>(7 * x), static_cast<std::uint8_t>(11 * y),
                        static_cast<std::uint8_t>(x ^ y)};
  }
  const Image back = decode_png(encode_png(image), "memory");
  ASSERT_EQ(back.width(), 37);
  ASSERT_EQ(back.height(), 21);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) EXPECT_EQ(back.at(x, y), image.at(x, y));
  }
}

TEST(Image, BadPngDataIsAnInputErrorNamingTheSource) {
  EXPECT_THROW(decode_png("not a png at all", "junk.png"), InputError);
  const std::string png = encode_png(Image(8, 8, {9, 9, 9}));
  try {
    decode_png(png.substr(0, png.size() / 2), "half.png");
    FAIL() << "a truncated PNG decoded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("half.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_png("/nonexistent/picture.png"), InputError);
  EXPECT_THROW(Image(0, 5), InputError);
}

TEST(Image, DownsampleAveragesBlocks) {
  Image image(4, 2, {0, 0, 0});
  image.at(0, 0) = {200, 100, 40};
  image.at(1, 1) = {200, 100, 40};
  const Image half = image.downsampled(2);
  ASSERT_EQ(half.width(), 2);
  ASSERT_EQ(half.height(), 1);
  EXPECT_EQ(half.at(0, 0), (Rgb{100, 50, 20}));
  EXPECT_EQ(half.at(1, 0), (Rgb{0, 0, 0}));
}

/// A square of side `side` facing +z at z = 0, centred on the origin, as two triangles.
void square(double side, Positions& x, FaceArray& f) {
  const double h = 0.5 * side;
  x.resize(4, 3);
  x << -h, -h, 0, h, -h, 0, h, h, 0, -h, h, 0;
  f.resize(2, 3);
  f << 0, 1, 2, 0, 2, 3;
}

TEST(Rasterizer, SquareSilhouetteMatchesThePinholeProjection) {
  // Camera on the +z axis at distance d looking at the origin: a square of side s covers
  // (f s / d)² pixels with f = (H / 2) / tan(fov / 2).
  const int width = 400, height = 300;
  Camera camera;
  camera.eye = Vec3(0, 0, 2);
  camera.fov_y_deg = 40;
  Positions x;
  FaceArray faces;
  square(0.5, x, faces);
  Rasterizer raster(width, height, camera, {255, 255, 255});
  const auto red = [](Index) { return Rgb{200, 0, 0}; };
  raster.draw(x, faces, {red, red});
  const double focal = 0.5 * height / std::tan(20 * std::numbers::pi / 180);
  const double side = focal * 0.5 / 2.0;
  const std::int64_t background = raster.image().count({255, 255, 255});
  const std::int64_t covered = std::int64_t{width} * height - background;
  EXPECT_NEAR(static_cast<double>(covered), side * side, 4 * side + 4);  // ± one pixel ring
  // Flat shading: every covered pixel has the same colour.
  const Rgb centre = raster.image().at(width / 2, height / 2);
  EXPECT_NE(centre, (Rgb{255, 255, 255}));
  EXPECT_EQ(raster.image().count(centre), covered);
}

TEST(Rasterizer, NearerTriangleHidesFartherOneAndBackFacesUseTheBackColour) {
  Camera camera;
  camera.eye = Vec3(0, 0, 2);
  Positions near_square, far_square;
  FaceArray faces;
  square(0.4, near_square, faces);
  square(0.8, far_square, faces);
  far_square.col(2).setConstant(-0.5);
  Rasterizer raster(200, 200, camera, {255, 255, 255});
  const auto green = [](Index) { return Rgb{0, 200, 0}; };
  const auto blue = [](Index) { return Rgb{0, 0, 200}; };
  raster.draw(near_square, faces, {green, green});
  raster.draw(far_square, faces, {blue, blue});  // drawn later, but farther
  const Rgb centre = raster.image().at(100, 100);
  EXPECT_GT(centre.g, 0);
  EXPECT_EQ(centre.b, 0);
  // Seen from behind, a square uses its back colour.
  camera.eye = Vec3(0, 0, -2);
  Rasterizer behind(200, 200, camera, {255, 255, 255});
  behind.draw(near_square, faces, {green, blue});
  EXPECT_GT(behind.image().at(100, 100).b, 0);
  EXPECT_EQ(behind.image().at(100, 100).g, 0);
}

/// A roof along the y axis seen from +z: ridge at x = 0, each side sloping down by
/// `tilt_deg` (four faces of equal area, facing the camera).
void lit_roof(double tilt_deg, Positions& x, FaceArray& f) {
  const double drop = 0.5 * std::tan(tilt_deg * std::numbers::pi / 180.0);
  x.resize(6, 3);
  x << -0.5, -0.5, -drop, -0.5, 0.5, -drop, 0, -0.5, 0, 0, 0.5, 0, 0.5, -0.5, -drop, 0.5, 0.5,
      -drop;
  f.resize(4, 3);
  f << 0, 2, 3, 0, 3, 1, 2, 4, 5, 2, 5, 3;
}

/// The roof drawn in grey {200, 200, 200} at 200 × 200 pixels, one sample per pixel.
Rasterizer draw_roof(double tilt_deg, Shading shading) {
  Camera camera;
  camera.eye = Vec3(0, 0, 3);
  Positions x;
  FaceArray faces;
  lit_roof(tilt_deg, x, faces);
  Rasterizer raster(200, 200, camera, {255, 255, 255});
  const auto grey = [](Index) { return Rgb{200, 200, 200}; };
  ShadingOptions options;
  options.shading = shading;
  raster.draw(x, faces, {grey, grey}, options);
  return raster;
}

/// The grey a pixel whose unit normal is `n` gets.
int expected_grey(const Rasterizer& raster, const Vec3& n) {
  return static_cast<int>(std::lround(
      200 * (Rasterizer::kAmbient + Rasterizer::kDiffuse * std::max(0.0, n.dot(raster.light())))));
}

TEST(Rasterizer, SmoothShadingIsContinuousAcrossAGentleFoldWhereFlatShadingSteps) {
  const double tilt = 15 * std::numbers::pi / 180;
  const Vec3 left(-std::sin(tilt), 0, std::cos(tilt)), right(std::sin(tilt), 0, std::cos(tilt));
  const Rasterizer flat = draw_roof(15, Shading::flat);
  const Rasterizer smooth = draw_roof(15, Shading::smooth);
  // The ridge is the line between pixel columns 99 and 100; row 100 is halfway along it,
  // where ridge vertices 2 (left + 2 right) and 3 (2 left + right) average to +z.
  const int row = 100;
  EXPECT_NEAR(flat.image().at(90, row).r, expected_grey(flat, left), 1);
  EXPECT_NEAR(flat.image().at(110, row).r, expected_grey(flat, right), 1);
  const int step = std::abs(expected_grey(flat, left) - expected_grey(flat, right));
  ASSERT_GE(step, 10);  // the light tells the sides apart
  EXPECT_GE(std::abs(flat.image().at(99, row).r - flat.image().at(100, row).r), step - 1);
  EXPECT_NEAR(smooth.image().at(99, row).r, expected_grey(smooth, Vec3::UnitZ()), 1);
  EXPECT_NEAR(smooth.image().at(100, row).r, expected_grey(smooth, Vec3::UnitZ()), 1);
  // Along the row, neighbouring pixels differ by at most one level: no seam anywhere.
  int largest_jump = 0;
  for (int x = 60; x < 140; ++x) {
    largest_jump = std::max(
        largest_jump, std::abs(smooth.image().at(x + 1, row).r - smooth.image().at(x, row).r));
  }
  EXPECT_LE(largest_jump, 1);
}

TEST(Rasterizer, SmoothShadingKeepsAFoldSharperThanTheCreaseAngle) {
  // Sides 100 degrees apart (crease angle 60): smooth shading draws exactly what flat does.
  const Rasterizer flat = draw_roof(50, Shading::flat);
  const Rasterizer smooth = draw_roof(50, Shading::smooth);
  std::int64_t differing = 0;
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 200; ++x) differing += !(flat.image().at(x, y) == smooth.image().at(x, y));
  }
  EXPECT_EQ(differing, 0);
  EXPECT_GE(std::abs(smooth.image().at(99, 100).r - smooth.image().at(100, 100).r), 10);
}

TEST(FrameRenderer, HighlightedFacesAreRed) {
  Positions x;
  FaceArray faces;
  square(0.5, x, faces);
  RenderSettings settings;
  settings.width = 160;
  settings.height = 120;
  settings.supersample = 1;
  const Camera camera = frame_camera(Vec3(-0.25, -0.25, 0), Vec3(0.25, 0.25, 0), settings);
  FrameView view;
  view.cloth = &x;
  view.cloth_faces = &faces;
  const Image plain = render_frame(view, camera, settings);
  view.highlighted_faces = {1, 99};  // 99 is out of range: ignored
  const Image marked = render_frame(view, camera, settings);
  // Red pixels: red channel well above the others (shading scales all three alike).
  const auto reddish = [](const Image& im) {
    std::int64_t n = 0;
    for (int y = 0; y < im.height(); ++y) {
      for (int x = 0; x < im.width(); ++x) {
        const Rgb p = im.at(x, y);
        n += p.r > 2 * p.g + 10 && p.r > 2 * p.b + 10;
      }
    }
    return n;
  };
  EXPECT_EQ(reddish(plain), 0);
  // One of two equal triangles: about half the square.
  const std::int64_t covered =
      std::int64_t{settings.width} * settings.height - plain.count(settings.background);
  EXPECT_NEAR(static_cast<double>(reddish(marked)), 0.5 * covered, 0.1 * covered);
}

TEST(ContactSheet, ShowsEvenlySpacedFramesWithFirstAndLast) {
  const ContactSheet sheet(80, 4, 3, 100);
  ASSERT_EQ(sheet.frames().size(), 12u);
  EXPECT_EQ(sheet.frames().front(), 0);
  EXPECT_EQ(sheet.frames().back(), 80);
  EXPECT_TRUE(sheet.wants(80));
  EXPECT_FALSE(sheet.wants(1));
  const ContactSheet few(2, 4, 3, 100);
  EXPECT_EQ(few.frames(), (std::vector<int>{0, 1, 2}));
  ContactSheet one(0, 4, 3, 50);
  one.add(0, Image(100, 80, {10, 20, 30}));
  const Image composed = one.compose();
  EXPECT_GT(composed.count({10, 20, 30}), 40 * 30);  // the thumbnail, minus its label
}

/// Runs the CLI, its output discarded; returns its exit code.
int run_cli(const std::vector<std::string>& args) {
  return testing::run_cli_quietly(args, 0, testing::Stderr::kDiscard);
}

TEST(RenderCommand, RendersASimulationFolder) {
  const fs::path out = fs::temp_directory_path() / "tailor_test_render";
  fs::remove_all(out);
  ASSERT_EQ(run_cli({"simulate", "--frames", "2", "--rings", "9", "--segments", "12", "--out",
                     out.string(), "--threads", "1"}),
            0);
  fs::remove(out / "contact_sheet.png");
  ASSERT_EQ(run_cli({"render", out.string(), "--width", "160", "--height", "120"}), 0);
  for (int f = 0; f <= 2; ++f) {
    const Image picture = read_png(out / frame_file_name("render", f, ".png"));
    EXPECT_EQ(picture.width(), 160);
    EXPECT_EQ(picture.height(), 120);
    // Something was drawn on the background.
    EXPECT_LT(picture.count(RenderSettings{}.background), 160 * 120);
  }
  EXPECT_NO_THROW(read_png(out / "contact_sheet.png"));
  EXPECT_GT(fs::file_size(out / "animation.mp4"), 0u);  // test_animation checks its frames
  fs::remove(out / "animation.mp4");
  ASSERT_EQ(run_cli({"render", out.string(), "--width", "160", "--height", "120", "--flat",
                     "--no-animation"}),
            0);
  EXPECT_FALSE(fs::exists(out / "animation.mp4"));
  // Into another folder, the sheet only.
  const fs::path elsewhere = out / "pictures";
  ASSERT_EQ(run_cli({"render", out.string(), "--out", elsewhere.string(), "--sheet-only"}), 0);
  EXPECT_TRUE(fs::exists(elsewhere / "contact_sheet.png"));
  EXPECT_FALSE(fs::exists(elsewhere / frame_file_name("render", 0, ".png")));
}

TEST(RenderCommand, BadInputExitsWithCode2) {
  EXPECT_EQ(run_cli({"render", "/nonexistent/folder"}), 2);
  const fs::path empty = fs::temp_directory_path() / "tailor_test_render_empty";
  fs::remove_all(empty);
  fs::create_directories(empty);
  EXPECT_EQ(run_cli({"render", empty.string()}), 2);
  // A folder whose contact file is malformed or names a face that does not exist.
  const fs::path out = fs::temp_directory_path() / "tailor_test_render_bad";
  fs::remove_all(out);
  ASSERT_EQ(run_cli({"simulate", "--frames", "1", "--rings", "9", "--segments", "12", "--out",
                     out.string(), "--threads", "1"}),
            0);
  std::ofstream(out / frame_file_name("contacts", 1, ".json")) << "{\"candidate_triangles\": [1,";
  EXPECT_EQ(run_cli({"render", out.string()}), 2);
  std::ofstream(out / frame_file_name("contacts", 1, ".json"))
      << "{\"candidate_triangles\": [9999]}";
  EXPECT_EQ(run_cli({"render", out.string()}), 2);
  EXPECT_THROW(read_candidate_triangles(out / frame_file_name("contacts", 1, ".json"), 192),
               InputError);
  EXPECT_EQ(run_cli({"render", out.string(), "--width", "5"}), 2);
}

}  // namespace
}  // namespace tailor
