#pragma once
/// @file
/// Small allocation-free helpers for parsing numbers out of text (OBJ and ASCII PLY).

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>

namespace tailor::text_scan {

/// True for the blanks that separate tokens on one line.
inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// Skips blanks at the front of `s`.
inline void skip_blanks(std::string_view& s) {
  std::size_t i = 0;
  while (i < s.size() && is_blank(s[i])) ++i;
  s.remove_prefix(i);
}

/// Removes and returns the next blank-separated token of `s` (empty at the end).
inline std::string_view next_token(std::string_view& s) {
  skip_blanks(s);
  std::size_t i = 0;
  while (i < s.size() && !is_blank(s[i])) ++i;
  const std::string_view token = s.substr(0, i);
  s.remove_prefix(i);
  return token;
}

/// Removes one leading '+' from `token`; false if a second sign follows it ("+-1").
inline bool strip_plus(std::string_view& token) {
  if (token.empty() || token.front() != '+') return true;
  token.remove_prefix(1);
  return token.empty() || (token.front() != '-' && token.front() != '+');
}

/// Parses the whole token as a double: what std::from_chars accepts (decimal, no hex), with
/// one optional leading '+'. False if it is not a number. Out of range values get the IEEE
/// result (infinity, or 0 or a subnormal below the smallest); non-finite values ("nan",
/// "inf", "1e999") parse successfully, callers check std::isfinite.
inline bool parse_double(std::string_view token, double& value) {
  if (!strip_plus(token) || token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec == std::errc::result_out_of_range && end == token.data() + token.size()) {
    // Rare: let strtod give the IEEE result (infinity on overflow, 0 or subnormal below).
    value = std::strtod(std::string(token).c_str(), nullptr);
    return true;
  }
  return ec == std::errc() && end == token.data() + token.size();
}

/// Parses the whole token as a signed integer (one optional leading '+').
inline bool parse_int(std::string_view token, std::int64_t& value) {
  if (!strip_plus(token) || token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

}  // namespace tailor::text_scan
