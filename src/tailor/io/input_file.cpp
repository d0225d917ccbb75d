/// @file
/// Memory-mapped input files (POSIX mmap), with a bounded read for pipes and devices.

#include "tailor/io/input_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "tailor/geometry/error.hpp"
#include "tailor/io/memory_budget.hpp"

namespace tailor {
namespace {

/// Closes a file descriptor on every path out of the constructor.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

InputFile::InputFile(const std::filesystem::path& path) : m_path(path) {
  Descriptor file;
  file.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (file.fd < 0) {
    throw InputError(fmt::format("cannot open {}: {}", path.string(), std::strerror(errno)));
  }
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) {
    throw InputError(fmt::format("cannot open {}: {}", path.string(), std::strerror(errno)));
  }
  if (S_ISDIR(info.st_mode)) {
    throw InputError(fmt::format("cannot open {}: it is a directory", path.string()));
  }
  // A regular file of size 0 may be empty or a /proc file that stat cannot size: read it.
  if (S_ISREG(info.st_mode) && info.st_size > 0) {
    m_size = static_cast<std::size_t>(info.st_size);
    void* map = ::mmap(nullptr, m_size, PROT_READ, MAP_PRIVATE, file.fd, 0);
    if (map == MAP_FAILED) {
      throw InputError(fmt::format("cannot read {}: {}", path.string(), std::strerror(errno)));
    }
    ::madvise(map, m_size, MADV_SEQUENTIAL);  // parsers read front to back
    m_map = map;
    m_data = static_cast<const char*>(map);
    return;
  }
  // A pipe, a device or a /proc file: no size to check up front, so read in chunks within
  // the budget.
  char chunk[1 << 16];
  for (;;) {
    const ssize_t n = ::read(file.fd, chunk, sizeof(chunk));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      throw InputError(fmt::format("cannot read {}: {}", path.string(), std::strerror(errno)));
    }
    if (n == 0) break;
    check_memory_budget(static_cast<double>(m_buffer.size() + static_cast<std::size_t>(n)),
                        fmt::format("reading {} (not a regular file)", path.string()));
    m_buffer.append(chunk, static_cast<std::size_t>(n));
  }
  m_data = m_buffer.data();
  m_size = m_buffer.size();
}

InputFile::~InputFile() {
  if (m_map != nullptr) ::munmap(m_map, m_size);
}

}  // namespace tailor
