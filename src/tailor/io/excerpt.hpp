#pragma once
/// @file
/// Short, printable quotes of input text for error messages: a hostile file can hold a
/// "token" of gigabytes or of control bytes, and a message must stay one short line.

#include <cstddef>
#include <string>
#include <string_view>

namespace tailor {

/// Longest quote of an input token in a message, in output bytes.
inline constexpr std::size_t kExcerptBytes = 40;

/// `text` made printable and short: printable ASCII is kept, every other byte is shown
/// as `\xHH`, and the result is cut to at most `max_bytes` bytes followed by "..." (and
/// the original length) when the input did not fit. Runs in time O(max_bytes), whatever
/// the length of `text`.
std::string excerpt(std::string_view text, std::size_t max_bytes = kExcerptBytes);

}  // namespace tailor
