/// @file
/// A bounded single-producer single-consumer ring of frames fed by a reader thread that
/// polls for room.

#include "tailor/io/frame_prefetch.hpp"

#include <fmt/format.h>
#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <chrono>

#include "tailor/geometry/error.hpp"
#include "tailor/geometry/stopwatch.hpp"

namespace tailor {
namespace {

/// The reader's pauses on a full ring: the first, doubled up to the longest. A ring of many
/// frames lasts many of them; a small one is refilled as soon as it gets half empty.
constexpr std::chrono::microseconds kFirstPause{50};
constexpr std::chrono::microseconds kLongestPause{2000};

/// Lets the calling thread run on spare time: when it wakes, the scheduler does not switch
/// it in at once ahead of the running thread (Linux SCHED_BATCH; elsewhere nothing).
void run_on_spare_time() {
#ifdef SCHED_BATCH
  const sched_param param{};
  pthread_setschedparam(pthread_self(), SCHED_BATCH, &param);
#endif
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
  if (m_read_ahead > 0) {
    m_ring.resize(m_read_ahead);
    m_reader = std::thread([this] { read_frames(); });
  }
}

FramePrefetcher::~FramePrefetcher() {
  if (!m_reader.joinable()) return;
  {
    const std::lock_guard lock(m_mutex);
    m_stop.store(true);
  }
  m_pause.notify_all();
  m_reader.join();
}

bool FramePrefetcher::wait_for_room(std::int64_t n) {
  const auto ring = static_cast<std::int64_t>(m_read_ahead);
  if (n - m_taken.load() < ring) return !m_stop.load();
  // Full: pause until the ring is at most half full (then refill it in one go), or next()
  // waits for a frame and there is room.
  auto pause = kFirstPause;
  std::unique_lock lock(m_mutex);
  for (;;) {
    if (m_stop.load()) return false;
    const std::int64_t queued = n - m_taken.load();
    if (queued <= ring / 2 || (m_hurry && queued < ring)) break;
    m_pause.wait_for(lock, pause);
    pause = std::min(2 * pause, kLongestPause);
  }
  m_hurry = false;
  return true;
}

void FramePrefetcher::read_frames() {
  run_on_spare_time();
  const auto ring = static_cast<std::int64_t>(m_read_ahead);
  for (std::int64_t n = 0; m_first + n <= m_last; ++n) {
    if (!wait_for_room(n)) return;
    try {
      m_ring[static_cast<std::size_t>(n % ring)] = m_frames.load(m_first + static_cast<Index>(n));
    } catch (...) {
      m_error = std::current_exception();
      m_failed.store(true);
      m_loaded.store(n + 1);
      m_loaded.notify_one();
      return;
    }
    m_loaded.store(n + 1);
    m_loaded.notify_one();
  }
}

std::optional<Positions> FramePrefetcher::next() {
  if (m_next > m_last) return std::nullopt;
  const auto start = SteadyClock::now();
  if (m_read_ahead == 0) {
    Positions frame = m_frames.load(m_next);  // throws without advancing
    ++m_next;
    m_wait_ms += milliseconds_since(start);
    return frame;
  }
  const std::int64_t n = m_next - m_first;
  std::int64_t loaded = m_loaded.load();
  if (loaded <= n) {  // the ring is empty: end the reader's pause, then wait
    {
      const std::lock_guard lock(m_mutex);
      m_hurry = true;
    }
    m_pause.notify_one();
    while (loaded <= n) {
      m_loaded.wait(loaded);
      loaded = m_loaded.load();
    }
  }
  if (m_failed.load() && n == loaded - 1) {  // the reader's error sits where frame n would
    m_wait_ms += milliseconds_since(start);
    std::rethrow_exception(m_error);
  }
  Positions frame = std::move(m_ring[static_cast<std::size_t>(n % m_read_ahead)]);
  m_taken.store(n + 1);
  ++m_next;
  m_wait_ms += milliseconds_since(start);
  return frame;
}

}  // namespace tailor
