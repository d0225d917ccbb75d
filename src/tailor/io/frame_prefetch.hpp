#pragma once
/// @file
/// Frames of a FrameSequence read ahead on a second thread, so that reading (parsing OBJ/PLY
/// text, checking topology) overlaps the work done on earlier frames.

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "tailor/geometry/types.hpp"
#include "tailor/io/frame_sequence.hpp"

namespace tailor {

/// Hands out frames `first..last` of a sequence in order. A reader thread loads them
/// (FrameSequence::load, so every frame is checked against the first one) and keeps at most
/// `read_ahead` loaded frames waiting; with `read_ahead == 0` there is no thread and next()
/// loads each frame itself. An error while reading a frame (an InputError naming the file)
/// is thrown by the next() call that would have returned that frame, after every earlier
/// frame was handed out; the reader stops there.
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

  const FrameSequence& m_frames;
  const Index m_first, m_last;
  const std::size_t m_read_ahead;
  Index m_next;  // next frame handed out (consumer side only)
  double m_wait_ms = 0;

  std::mutex m_mutex;
  std::condition_variable m_changed;  // a frame was queued or taken, or stop was asked
  std::deque<Positions> m_ready;      // loaded frames m_next, m_next + 1, ...
  std::exception_ptr m_error;         // the reader's error, after the frames in m_ready
  bool m_stop = false;
  std::thread m_reader;
};

}  // namespace tailor
