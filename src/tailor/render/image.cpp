/// @file
/// RGB images and PNG through libpng (memory buffers; errors as InputError).

#include "tailor/render/image.hpp"

#include <fmt/format.h>
#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstring>

#include "tailor/geometry/error.hpp"
#include "tailor/io/file_bytes.hpp"

namespace tailor {
namespace {

constexpr int kMaxSide = 1 << 14;

/// libpng reports errors through longjmp; the message is kept here first.
struct PngContext {
  std::string error;
  std::string* out = nullptr;  // writing
  std::string_view in;         // reading
  std::size_t offset = 0;
};

void on_error(png_structp png, png_const_charp message) {
  auto* context = static_cast<PngContext*>(png_get_error_ptr(png));
  context->error = message != nullptr ? message : "unknown libpng error";
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

void write_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* context = static_cast<PngContext*>(png_get_io_ptr(png));
  context->out->append(reinterpret_cast<const char*>(data), length);
}

void flush_bytes(png_structp) {}

void read_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* context = static_cast<PngContext*>(png_get_io_ptr(png));
  if (context->offset + length > context->in.size()) {
    png_error(png, "truncated PNG data");
  }
  std::memcpy(data, context->in.data() + context->offset, length);
  context->offset += length;
}

}  // namespace

Image::Image(int width, int height, Rgb fill) : m_width(width), m_height(height) {
  if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide) {
    throw InputError(
        fmt::format("image size {}×{} out of range (1 to {} per side)", width, height, kMaxSide));
  }
  m_pixels.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
}

std::int64_t Image::count(Rgb colour) const {
  return std::count(m_pixels.begin(), m_pixels.end(), colour);
}

Image Image::downsampled(int factor) const {
  if (factor <= 1) return *this;
  Image out(std::max(1, m_width / factor), std::max(1, m_height / factor));
  for (int y = 0; y < out.height(); ++y) {
    for (int x = 0; x < out.width(); ++x) {
      int r = 0, g = 0, b = 0, n = 0;
      for (int dy = 0; dy < factor; ++dy) {
        for (int dx = 0; dx < factor; ++dx) {
          const int sx = x * factor + dx, sy = y * factor + dy;
          if (sx >= m_width || sy >= m_height) continue;
          const Rgb& p = at(sx, sy);
          r += p.r;
          g += p.g;
          b += p.b;
          ++n;
        }
      }
      out.at(x, y) = {static_cast<std::uint8_t>((r + n / 2) / n),
                      static_cast<std::uint8_t>((g + n / 2) / n),
                      static_cast<std::uint8_t>((b + n / 2) / n)};
    }
  }
  return out;
}

void Image::blit(const Image& source, int x0, int y0) {
  for (int y = 0; y < source.height(); ++y) {
    const int ty = y0 + y;
    if (ty < 0 || ty >= m_height) continue;
    for (int x = 0; x < source.width(); ++x) {
      const int tx = x0 + x;
      if (tx >= 0 && tx < m_width) at(tx, ty) = source.at(x, y);
    }
  }
}

std::string encode_png(const Image& image) {
  if (image.width() <= 0 || image.height() <= 0) throw InputError("cannot encode an empty image");
  PngContext context;
  std::string bytes;
  context.out = &bytes;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &context, on_error, on_warning);
  if (png == nullptr) throw InputError("libpng: cannot create a writer");
  png_infop info = png_create_info_struct(png);
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height()));
  if (info == nullptr || setjmp(png_jmpbuf(png)) != 0) {
    png_destroy_write_struct(&png, &info);
    throw InputError("libpng: cannot encode the image: " + context.error);
  }
  png_set_write_fn(png, &context, write_bytes, flush_bytes);
  // Fast settings: these pictures are written every frame; size matters less than time.
  png_set_compression_level(png, 3);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width()),
               static_cast<png_uint_32>(image.height()), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  for (int y = 0; y < image.height(); ++y) {
    // libpng does not write through the row pointers.
    rows[static_cast<std::size_t>(y)] =
        reinterpret_cast<png_bytep>(const_cast<Rgb*>(&image.at(0, y)));
  }
  png_set_rows(png, info, rows.data());
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  return bytes;
}

Image decode_png(std::string_view bytes, const std::string& source) {
  if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0) {
    throw InputError(fmt::format("{}: not a PNG file", source));
  }
  PngContext context;
  context.in = bytes;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &context, on_error, on_warning);
  if (png == nullptr) throw InputError("libpng: cannot create a reader");
  png_infop info = png_create_info_struct(png);
  Image image;
  std::vector<png_bytep> rows;
  if (info == nullptr || setjmp(png_jmpbuf(png)) != 0) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw InputError(fmt::format("{}: bad PNG data: {}", source, context.error));
  }
  png_set_read_fn(png, &context, read_bytes);
  png_read_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  if (width == 0 || height == 0 || width > kMaxSide || height > kMaxSide) {
    png_error(png, "image size out of range");
  }
  // Any PNG to 8-bit RGB.
  png_set_strip_16(png);
  png_set_strip_alpha(png);
  png_set_palette_to_rgb(png);
  png_set_expand_gray_1_2_4_to_8(png);
  png_set_gray_to_rgb(png);
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) != 3 * static_cast<png_size_t>(width)) {
    png_error(png, "unsupported pixel format");
  }
  image = Image(static_cast<int>(width), static_cast<int>(height));
  rows.resize(height);
  for (png_uint_32 y = 0; y < height; ++y)
    rows[y] = reinterpret_cast<png_bytep>(&image.at(0, static_cast<int>(y)));
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return image;
}

void write_png(const std::filesystem::path& path, const Image& image) {
  write_file_atomically(path, encode_png(image));
}

Image read_png(const std::filesystem::path& path) {
  return decode_png(read_file_bytes(path), path.string());
}

}  // namespace tailor
