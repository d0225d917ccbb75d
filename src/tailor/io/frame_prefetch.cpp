/// @file
/// A bounded single-producer single-consumer queue of frames fed by a reader thread.

#include "tailor/io/frame_prefetch.hpp"

#include <fmt/format.h>

#include <chrono>

#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

FramePrefetcher::FramePrefetcher(const FrameSequence& frames, Index first, Index last,
                                 int read_ahead)
    : m_frames(frames),
      m_first(first),
      m_last(last),
      m_read_ahead(read_ahead < 0 ? 0 : static_cast<std::size_t>(read_ahead)),
      m_next(first) {
  if (first < 0 || last < first || last >= frames.num_frames()) {
    throw InputError(fmt::format("frames {} to {} are not within the sequence of {} frames ({})",
                                 first, last, frames.num_frames(), frames.path(0).string()));
  }
  if (read_ahead < 0) throw InputError(fmt::format("read ahead {} is negative", read_ahead));
  if (m_read_ahead > 0) m_reader = std::thread([this] { read_frames(); });
}

FramePrefetcher::~FramePrefetcher() {
  if (!m_reader.joinable()) return;
  {
    const std::lock_guard lock(m_mutex);
    m_stop = true;
  }
  m_changed.notify_all();
  m_reader.join();
}

void FramePrefetcher::read_frames() {
  for (Index i = m_first; i <= m_last; ++i) {
    {
      // Wait for room: at most m_read_ahead frames loaded and not yet taken.
      std::unique_lock lock(m_mutex);
      m_changed.wait(lock, [&] { return m_stop || m_ready.size() < m_read_ahead; });
      if (m_stop) return;
    }
    std::optional<Positions> frame;
    std::exception_ptr error;
    try {
      frame = m_frames.load(i);
    } catch (...) {
      error = std::current_exception();
    }
    {
      const std::lock_guard lock(m_mutex);
      if (error) {
        m_error = error;
      } else {
        m_ready.push_back(std::move(*frame));
      }
    }
    m_changed.notify_all();
    if (error) return;
  }
}

std::optional<Positions> FramePrefetcher::next() {
  if (m_next > m_last) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  if (m_read_ahead == 0) {
    Positions frame = m_frames.load(m_next);  // throws without advancing
    ++m_next;
    m_wait_ms += milliseconds_since(start);
    return frame;
  }
  std::unique_lock lock(m_mutex);
  m_changed.wait(lock, [&] { return !m_ready.empty() || m_error != nullptr; });
  if (m_ready.empty()) {
    m_wait_ms += milliseconds_since(start);
    std::rethrow_exception(m_error);
  }
  Positions frame = std::move(m_ready.front());
  m_ready.pop_front();
  ++m_next;
  lock.unlock();
  m_changed.notify_all();
  m_wait_ms += milliseconds_since(start);
  return frame;
}

}  // namespace tailor
