/// @file
/// FramePrefetcher: frames in order from a reader thread, errors at the failing frame, early
/// shutdown.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <random>
#include <thread>
#include <vector>

#include "io_test_support.hpp"
#include "tailor/io/frame_prefetch.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;
using test::TempDir;

/// A two-triangle frame whose positions depend on `i`, with `extra` unused vertices.
MeshData numbered_frame(int i, Index extra = 0) {
  MeshData m;
  m.vertices.resize(4 + extra, 3);
  for (Index v = 0; v < m.vertices.rows(); ++v) m.vertices.row(v) << v + i, 0.5 * i, -v;
  m.faces.resize(2, 3);
  m.faces << 0, 1, 2, 0, 2, 3;
  return m;
}

/// Writes frames 0..count-1 as DIR/NN.ply; `bad_frame` (if any) gets two extra vertices.
void write_frames(const TempDir& dir, int count, int bad_frame = -1) {
  for (int i = 0; i < count; ++i) {
    const MeshData m = numbered_frame(i, i == bad_frame ? 2 : 0);
    write_mesh(dir / fmt::format("{:02d}.ply", i), m.vertices, m.faces);
  }
}

TEST(FramePrefetch, HandsOutEveryFrameInOrder) {
  TempDir dir;
  write_frames(dir, 9);
  const FrameSequence frames(dir.path());
  for (int read_ahead : {0, 1, 2, 5, 20}) {
    for (const auto& [first, last] : {std::pair{0, 8}, std::pair{3, 6}, std::pair{8, 8}}) {
      FramePrefetcher prefetcher(frames, first, last, read_ahead);
      for (Index i = first; i <= last; ++i) {
        ASSERT_EQ(prefetcher.next_index(), i);
        const std::optional<Positions> x = prefetcher.next();
        ASSERT_TRUE(x.has_value()) << "frame " << i << ", read ahead " << read_ahead;
        EXPECT_EQ(*x, numbered_frame(i).vertices) << "frame " << i << ", read ahead " << read_ahead;
      }
      EXPECT_FALSE(prefetcher.next().has_value());
      EXPECT_FALSE(prefetcher.next().has_value());
      EXPECT_EQ(prefetcher.next_index(), last + 1);
      EXPECT_GE(prefetcher.wait_ms(), 0.0);
    }
  }
}

TEST(FramePrefetch, EveryFrameIntactWhateverThePaceOfTheConsumer) {
  // The consumer takes frames in bursts and pauses, so the ring runs full, half empty and
  // empty while the reader reads, pauses or is hurried: no frame may be lost, repeated or
  // overwritten before it was taken.
  TempDir dir;
  constexpr int kFrames = 60;
  write_frames(dir, kFrames);
  const FrameSequence frames(dir.path());
  std::mt19937 rng(18);
  for (int read_ahead : {1, 2, 3, 4, 7, 64}) {
    for (int round = 0; round < 2; ++round) {
      FramePrefetcher prefetcher(frames, 0, kFrames - 1, read_ahead);
      for (Index i = 0; i < kFrames; ++i) {
        const std::optional<Positions> x = prefetcher.next();
        ASSERT_TRUE(x.has_value()) << "frame " << i << ", read ahead " << read_ahead;
        ASSERT_EQ(*x, numbered_frame(i).vertices) << "frame " << i << ", read ahead " << read_ahead;
        const int pace = std::uniform_int_distribution<int>(0, 9)(rng);
        if (pace >= 7) {
          std::this_thread::sleep_for(std::chrono::microseconds(pace == 9 ? 3000 : 200));
        }
      }
      EXPECT_FALSE(prefetcher.next().has_value());
    }
  }
}

TEST(FramePrefetch, ErrorComesAtTheFailingFrameAfterEveryEarlierOne) {
  TempDir dir;
  write_frames(dir, 8, 5);
  const FrameSequence frames(dir.path());
  for (int read_ahead : {0, 1, 3, 10}) {
    FramePrefetcher prefetcher(frames, 1, 7, read_ahead);
    for (Index i = 1; i < 5; ++i) {
      const std::optional<Positions> x = prefetcher.next();
      ASSERT_TRUE(x.has_value());
      EXPECT_EQ(*x, numbered_frame(i).vertices);
    }
    for (int attempt = 0; attempt < 2; ++attempt) {
      expect_contains(input_error_message([&] { prefetcher.next(); }),
                      {"05.ply", "6 vertices", "00.ply", "has 4"});
    }
    EXPECT_EQ(prefetcher.next_index(), 5);
  }
}

TEST(FramePrefetch, MissingFileIsAnErrorNamingIt) {
  TempDir dir;
  write_frames(dir, 4);
  const FrameSequence frames(dir.path());
  std::filesystem::remove(dir / "02.ply");
  FramePrefetcher prefetcher(frames, 0, 3, 2);
  ASSERT_TRUE(prefetcher.next().has_value());
  ASSERT_TRUE(prefetcher.next().has_value());
  expect_contains(input_error_message([&] { prefetcher.next(); }), {"02.ply"});
}

TEST(FramePrefetch, StopsEarlyWithoutReadingTheRest) {
  TempDir dir;
  write_frames(dir, 40);
  const FrameSequence frames(dir.path());
  for (int read_ahead : {1, 4}) {
    FramePrefetcher prefetcher(frames, 0, 39, read_ahead);
    ASSERT_TRUE(prefetcher.next().has_value());
    // The destructor must stop the reader, which is blocked on a full queue.
  }
  {
    FramePrefetcher untouched(frames, 0, 39, 2);  // destroyed before any next()
  }
  SUCCEED();
}

TEST(FramePrefetch, RangeOutsideTheSequenceIsAnError) {
  TempDir dir;
  write_frames(dir, 3);
  const FrameSequence frames(dir.path());
  for (const auto& [first, last] : {std::pair{-1, 2}, std::pair{2, 1}, std::pair{0, 3}}) {
    expect_contains(input_error_message([&] { FramePrefetcher(frames, first, last); }),
                    {"not within the sequence of 3 frames", "00.ply"});
  }
  expect_contains(input_error_message([&] { FramePrefetcher(frames, 0, 2, -1); }), {"negative"});
}

}  // namespace
}  // namespace tailor
