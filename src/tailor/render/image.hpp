#pragma once
/// @file
/// An 8-bit RGB image and its PNG encoding (libpng).

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace tailor {

/// One pixel.
struct Rgb {
  ///@{
  /// Red, green and blue, 0-255 (sRGB as written to the PNG).
  std::uint8_t r = 0, g = 0, b = 0;
  ///@}
  /// Equal channels.
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

/// A row-major RGB image, (0, 0) at the top left.
class Image {
 public:
  Image() = default;
  /// A `width` × `height` image filled with `fill`. Throws InputError on a size ≤ 0 or
  /// over 2^14 per side.
  Image(int width, int height, Rgb fill = {});

  /// Width in pixels.
  int width() const { return m_width; }
  /// Height in pixels.
  int height() const { return m_height; }
  /// Pixel (x, y); no bounds check.
  Rgb& at(int x, int y) { return m_pixels[static_cast<std::size_t>(y) * m_width + x]; }
  /// Pixel (x, y), read only; no bounds check.
  const Rgb& at(int x, int y) const { return m_pixels[static_cast<std::size_t>(y) * m_width + x]; }
  /// Number of pixels equal to `colour`.
  std::int64_t count(Rgb colour) const;

  /// The image shrunk by an integer `factor` (mean of each factor × factor block).
  Image downsampled(int factor) const;
  /// Copies `source` with its top left at (x, y), clipped to this image.
  void blit(const Image& source, int x, int y);

 private:
  int m_width = 0, m_height = 0;
  std::vector<Rgb> m_pixels;
};

/// The image as PNG bytes (8-bit RGB).
std::string encode_png(const Image& image);
/// Decodes PNG bytes (any bit depth and colour type, converted to 8-bit RGB). `source`
/// names the data in errors. Throws InputError on anything that is not a valid PNG.
Image decode_png(std::string_view bytes, const std::string& source);

/// Writes `image` as a PNG file, atomically. Throws InputError naming the path on failure.
void write_png(const std::filesystem::path& path, const Image& image);
/// Reads a PNG file. Throws InputError naming the path if it is missing or not a PNG.
Image read_png(const std::filesystem::path& path);

}  // namespace tailor
