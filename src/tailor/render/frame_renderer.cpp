/// @file
/// Frame pictures and contact sheets.

#include "tailor/render/frame_renderer.hpp"

#include <algorithm>
#include <string>

namespace tailor {

Camera frame_camera(const Vec3& lo, const Vec3& hi, const RenderSettings& settings) {
  return Camera::framing(lo, hi, settings.view, settings.up,
                         static_cast<double>(settings.width) / settings.height);
}

Image render_frame(const FrameView& view, const Camera& camera, const RenderSettings& settings) {
  const int ss = std::max(1, settings.supersample);
  Rasterizer raster(settings.width * ss, settings.height * ss, camera, settings.background);
  if (view.arm != nullptr && view.arm_faces != nullptr) {
    const auto skin = [&](Index) { return settings.arm; };
    raster.draw(*view.arm, *view.arm_faces, {skin, skin}, settings.shading);
  }
  if (view.cloth != nullptr && view.cloth_faces != nullptr) {
    std::vector<char> red(static_cast<std::size_t>(view.cloth_faces->rows()), 0);
    for (Index f : view.highlighted_faces) {
      if (f >= 0 && f < static_cast<Index>(red.size())) red[static_cast<std::size_t>(f)] = 1;
    }
    const auto outside = [&](Index f) {
      return red[static_cast<std::size_t>(f)] ? settings.candidate : settings.cloth_outside;
    };
    const auto inside = [&](Index f) {
      return red[static_cast<std::size_t>(f)] ? settings.candidate : settings.cloth_inside;
    };
    raster.draw(*view.cloth, *view.cloth_faces, {outside, inside}, settings.shading);
  }
  return raster.image().downsampled(ss);
}

ContactSheet::ContactSheet(int frames, int columns, int rows, int thumb_width)
    : m_columns(std::max(1, columns)), m_rows(std::max(1, rows)), m_thumb_width(thumb_width) {
  const int slots = m_columns * m_rows;
  const int count = std::min(slots, frames + 1);
  for (int i = 0; i < count; ++i) {
    // Evenly spaced from the first to the last frame, both included.
    const int frame =
        count == 1 ? 0 : static_cast<int>(static_cast<long>(i) * frames / (count - 1));
    if (m_frames.empty() || m_frames.back() != frame) m_frames.push_back(frame);
  }
  m_thumbs.resize(m_frames.size());
}

bool ContactSheet::wants(int frame) const {
  return std::binary_search(m_frames.begin(), m_frames.end(), frame);
}

void ContactSheet::add(int frame, const Image& picture) {
  const auto it = std::lower_bound(m_frames.begin(), m_frames.end(), frame);
  if (it == m_frames.end() || *it != frame) return;
  const int factor = std::max(1, picture.width() / std::max(1, m_thumb_width));
  m_thumbs[static_cast<std::size_t>(it - m_frames.begin())] = picture.downsampled(factor);
}

Image ContactSheet::compose() const {
  int tw = 1, th = 1;
  for (const Image& t : m_thumbs) {
    tw = std::max(tw, t.width());
    th = std::max(th, t.height());
  }
  const int gap = 4;
  const int used_rows = (static_cast<int>(m_frames.size()) + m_columns - 1) / m_columns;
  Image sheet(m_columns * (tw + gap) + gap, std::max(1, used_rows) * (th + gap) + gap,
              {255, 255, 255});
  for (std::size_t i = 0; i < m_frames.size(); ++i) {
    const int x = gap + static_cast<int>(i) % m_columns * (tw + gap);
    const int y = gap + static_cast<int>(i) / m_columns * (th + gap);
    if (m_thumbs[i].width() > 0) sheet.blit(m_thumbs[i], x, y);
    draw_number(sheet, m_frames[i], x + 4, y + 4, 2, {40, 40, 40});
  }
  return sheet;
}

void draw_number(Image& image, int number, int x, int y, int scale, Rgb colour) {
  // 3×5 glyphs, one row per 3-bit group (top row first, bit 2 = left column).
  static constexpr int kGlyphs[10][5] = {
      {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
      {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 2, 2, 2}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};
  const std::string digits = std::to_string(std::max(0, number));
  for (std::size_t i = 0; i < digits.size(); ++i) {
    const int g = digits[i] - '0';
    const int gx = x + static_cast<int>(i) * 4 * scale;
    for (int row = 0; row < 5; ++row) {
      for (int col = 0; col < 3; ++col) {
        if ((kGlyphs[g][row] >> (2 - col) & 1) == 0) continue;
        for (int dy = 0; dy < scale; ++dy) {
          for (int dx = 0; dx < scale; ++dx) {
            const int px = gx + col * scale + dx, py = y + row * scale + dy;
            if (px >= 0 && px < image.width() && py >= 0 && py < image.height())
              image.at(px, py) = colour;
          }
        }
      }
    }
  }
}

}  // namespace tailor
