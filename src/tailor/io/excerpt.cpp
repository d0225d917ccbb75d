/// @file
/// Printable, length-capped quotes of input text.

#include "tailor/io/excerpt.hpp"

#include <fmt/format.h>

namespace tailor {

std::string excerpt(std::string_view text, std::size_t max_bytes) {
  std::string out;
  std::size_t used = 0;  // bytes of `text` shown
  for (; used < text.size(); ++used) {
    const auto c = static_cast<unsigned char>(text[used]);
    const bool printable = c >= 0x20 && c < 0x7f;
    const std::size_t width = printable ? 1 : 4;
    if (out.size() + width > max_bytes) break;
    if (printable) {
      out.push_back(static_cast<char>(c));
    } else {
      fmt::format_to(std::back_inserter(out), "\\x{:02x}", c);
    }
  }
  if (used < text.size()) fmt::format_to(std::back_inserter(out), "... ({} bytes)", text.size());
  return out;
}

}  // namespace tailor
