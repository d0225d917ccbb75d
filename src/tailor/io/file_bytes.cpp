/// @file
/// Whole-file reads and writes with errors that name the file.

#include "tailor/io/file_bytes.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>

#include "tailor/geometry/error.hpp"
#include "tailor/io/memory_budget.hpp"

namespace tailor {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

}  // namespace

std::string read_file_bytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(fmt::format("cannot open {}: it is a directory", path.string()));
  }
  FilePtr file(std::fopen(path.c_str(), "rb"));
  if (!file) {
    throw InputError(fmt::format("cannot open {}: {}", path.string(), std::strerror(errno)));
  }
  std::string bytes;
  const std::string what = fmt::format("reading {} into memory", path.string());
  if (const auto size = std::filesystem::file_size(path, ec); !ec) {
    check_memory_budget(static_cast<double>(size), what);
    bytes.reserve(size);
  }
  char buffer[1 << 16];
  // Read in chunks: works for pipes and files whose size changes, no size query needed.
  for (;;) {
    const std::size_t n = std::fread(buffer, 1, sizeof(buffer), file.get());
    if (bytes.size() + n > bytes.capacity()) {
      check_memory_budget(static_cast<double>(bytes.size() + n), what);
    }
    bytes.append(buffer, n);
    if (n < sizeof(buffer)) break;
  }
  if (std::ferror(file.get())) {
    throw InputError(fmt::format("cannot read {}: read error", path.string()));
  }
  return bytes;
}

void prepare_output_folder(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (!std::filesystem::is_directory(folder)) {
    throw InputError(fmt::format("cannot use {} as the output folder: {}", folder.string(),
                                 ec ? ec.message() : "it exists and is not a folder"));
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    throw InputError(fmt::format("cannot write into the output folder {}: {}", folder.string(),
                                 std::strerror(errno)));
  }
}

void write_file_bytes(const std::filesystem::path& path, std::string_view bytes) {
  FilePtr file(std::fopen(path.c_str(), "wb"));
  if (!file) {
    throw InputError(
        fmt::format("cannot open {} for writing: {}", path.string(), std::strerror(errno)));
  }
  if (std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size() ||
      std::fflush(file.get()) != 0) {
    throw InputError(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
  }
  if (std::fclose(file.release()) != 0) {
    throw InputError(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  write_file_bytes(temporary, bytes);
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    throw InputError(fmt::format("cannot rename '{}' to '{}': {}", temporary.string(),
                                 path.string(), error.message()));
  }
}

}  // namespace tailor
