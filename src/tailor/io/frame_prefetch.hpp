#pragma once
/// @file
/// Frames of a FrameSequence read ahead on a second thread, so that reading (parsing OBJ/PLY
/// text, checking topology) overlaps the work done on earlier frames.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/io/frame_sequence.hpp"

namespace tailor {

/// Hands out frames `first..last` of a sequence in order. A reader thread loads them
/// (FrameSequence::load, so every frame is checked against the first one) and keeps at most
/// `read_ahead` loaded frames waiting, refilling once half of them were taken; with
/// `read_ahead == 0` there is no thread and next() loads each frame itself. An error while
/// reading a frame (an InputError naming the file) is thrown by the next() call that would
/// have returned that frame, after every earlier frame was handed out; the reader stops
/// there.
///
/// The frames pass through a ring without a lock, and next() does not wake the reader while
/// a frame is ready: the reader polls a full ring with growing pauses instead. On a machine
/// busy with other work, a thread that blocks, or wakes another one, can lose its core for
/// milliseconds, many steps of a small mesh; the thread calling next() (the detection)
/// only does so when it has to wait for a frame anyway.
class FramePrefetcher {
 public:
  /// Starts reading. `frames` must outlive the prefetcher. Throws InputError if the range
  /// is not within the sequence (`first <= last` both in `[0, num_frames)`) or
  /// `read_ahead` is negative.
  FramePrefetcher(const FrameSequence& frames, Index first, Index last, int read_ahead = 2);
  /// Stops the reader (it finishes the frame it is reading) and joins it.
  ~FramePrefetcher();
  FramePrefetcher(const FramePrefetcher&) = delete;
  FramePrefetcher& operator=(const FramePrefetcher&) = delete;

  /// The positions of the next frame, in order, waiting for the reader if it is behind;
  /// std::nullopt after the last frame. Rethrows the reader's error at the failing frame.
  std::optional<Positions> next();

  /// Index of the frame the next call to next() returns (`last + 1` when done).
  Index next_index() const { return m_next; }
  /// Milliseconds the calling thread has spent in next() waiting for frames (with no read
  /// ahead: reading them); the part of reading that did not overlap other work.
  double wait_ms() const { return m_wait_ms; }

 private:
  void read_frames();
  /// Waits until frame `n` (counted from `first`) has room in the ring; false to stop.
  bool wait_for_room(std::int64_t n);

  const FrameSequence& m_frames;
  const Index m_first, m_last;
  const std::size_t m_read_ahead;
  Index m_next;  // next frame handed out (consumer side only)
  double m_wait_ms = 0;

  // Frame m_first + n sits in m_ring[n % m_read_ahead] from m_loaded > n until m_taken > n.
  std::vector<Positions> m_ring;
  std::atomic<std::int64_t> m_loaded{0};  // frames loaded, + 1 once the reader failed
  std::atomic<std::int64_t> m_taken{0};   // frames handed out
  std::atomic<bool> m_failed{false};      // the reader stopped at an error
  std::exception_ptr m_error;             // that error (written before m_failed)
  std::atomic<bool> m_stop{false};        // the destructor asks the reader to stop

  std::mutex m_mutex;               // guards m_hurry; the reader's pauses wait on it
  std::condition_variable m_pause;  // ends a pause early: m_hurry or m_stop
  bool m_hurry = false;             // next() waits for a frame: read on at once
  std::thread m_reader;
};

}  // namespace tailor
