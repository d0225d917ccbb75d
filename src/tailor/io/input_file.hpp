#pragma once
/// @file
/// The bytes of an input file, without reading it into memory first.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace tailor {

/// A read-only view of a whole input file. A regular file is memory-mapped: opening a
/// multi-gigabyte file costs no memory, and a parser that stops at the first bad byte
/// touches only the pages it looked at. Anything else (a pipe, a character device) is
/// read into memory up to the memory budget (memory_budget.hpp), then refused.
///
/// Caveat of mapping: if another process truncates the file while it is being parsed,
/// reading past the new end raises SIGBUS; do not rewrite input files in place while a
/// command reads them (tailor's writers replace files atomically).
class InputFile {
 public:
  /// Opens the file. Throws InputError naming the path if it is missing, a directory or
  /// unreadable, or if a non-regular file exceeds the memory budget.
  explicit InputFile(const std::filesystem::path& path);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// The file's bytes; valid as long as this object lives.
  std::string_view bytes() const { return {m_data, m_size}; }
  /// The file's size in bytes.
  std::size_t size() const { return m_size; }
  /// The path it was opened with.
  const std::filesystem::path& path() const { return m_path; }

 private:
  std::filesystem::path m_path;
  const char* m_data = "";
  std::size_t m_size = 0;
  void* m_map = nullptr;  // the mapping (regular files), or nullptr
  std::string m_buffer;   // the bytes of a non-regular file
};

}  // namespace tailor
