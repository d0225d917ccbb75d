/// @file
/// SequenceChecker on generated sequences with known answers: every step equals brute force,
/// every frame's static verdict is the known one, obstacles, ranges, bad frames.

#include <gtest/gtest.h>

#include <array>
#include <tuple>

#include "io/io_test_support.hpp"
#include "support/sanitized.hpp"
#include "support/sequence_files.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/sequence_check.hpp"
#include "tailor/mesh/procedural_meshes.hpp"
#include "tailor/mesh/procedural_sequences.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;
using test::TempDir;
using testing::sanitized;
using testing::write_sequence;

// ---- An independent oracle for the generator: the strip is an extruded profile, so it
// intersects itself exactly when its profile polyline does.

using Point2 = std::array<double, 2>;

double orient(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

bool within_box(const Point2& a, const Point2& b, const Point2& p) {
  return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

/// Closed segments ab and cd meet (touching counts).
bool segments_meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double d1 = orient(c, d, a), d2 = orient(c, d, b);
  const double d3 = orient(a, b, c), d4 = orient(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  return (d1 == 0 && within_box(c, d, a)) || (d2 == 0 && within_box(c, d, b)) ||
         (d3 == 0 && within_box(a, b, c)) || (d4 == 0 && within_box(a, b, d));
}

/// True when the profile (the first row of the strip's vertices) crosses or touches itself.
bool profile_self_intersects(const Positions& x, int cells_along) {
  std::vector<Point2> p;
  for (int i = 0; i <= cells_along; ++i) p.push_back({x(i, 0), x(i, 2)});
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    for (std::size_t j = i + 2; j + 1 < p.size(); ++j) {
      if (segments_meet(p[i], p[i + 1], p[j], p[j + 1])) return true;
    }
  }
  return false;
}

/// A small falling fold, jittered so that the exact CCD's fast path decides most pairs.
FallingFoldOptions small_fold(int piercing_frame = -1, double jitter = 1e-3) {
  FallingFoldOptions o;
  o.cells_along = 32;
  o.cells_across = sanitized() ? 2 : 4;
  o.frames = sanitized() ? 8 : 10;
  o.piercing_frame = piercing_frame;
  o.jitter = jitter;
  return o;
}

TEST(FallingFold, KnownAnswerHoldsByAnIndependentOracle) {
  for (int piercing : {-1, 6, 7}) {
    const FallingFoldOptions o = small_fold(piercing, 0.0);
    const ProceduralSequence s = make_falling_fold(o);
    // The jittered frames stay within jitter · h of these, per coordinate.
    const ProceduralSequence jittered = make_falling_fold(small_fold(piercing, 0.01));
    EXPECT_EQ(jittered.intersecting, s.intersecting);
    for (std::size_t k = 0; k < s.frames.size(); ++k) {
      const double moved = (jittered.frames[k] - s.frames[k]).cwiseAbs().maxCoeff();
      EXPECT_GT(moved, 0.0);
      EXPECT_LE(moved, 0.01 / o.cells_along);
    }
    ASSERT_EQ(static_cast<int>(s.frames.size()), o.frames);
    ASSERT_EQ(s.intersecting.size(), s.frames.size());
    const int row = o.cells_along + 1;
    for (int k = 0; k < o.frames; ++k) {
      const Positions& x = s.frames[static_cast<std::size_t>(k)];
      // An extrusion along y: every row repeats the first row's profile.
      for (Eigen::Index v = 0; v < x.rows(); ++v) {
        ASSERT_EQ(x(v, 0), x(v % row, 0));
        ASSERT_EQ(x(v, 2), x(v % row, 2));
      }
      EXPECT_EQ(profile_self_intersects(x, o.cells_along), s.intersecting[k])
          << "frame " << k << ", piercing frame " << piercing;
      EXPECT_EQ(s.intersecting[k], k == piercing);
    }
  }
  EXPECT_THROW(make_falling_fold({.cells_along = 32, .frames = 10, .piercing_frame = 1}),
               std::invalid_argument);  // the free layer is too short to dent
  EXPECT_THROW(make_falling_fold({.frames = 1}), std::invalid_argument);
  EXPECT_THROW(make_falling_fold({.jitter = 0.02}), std::invalid_argument);
}

// ---- The checker against brute force and the known answers.

using VfKey = std::tuple<Index, Index, double>;
using EeKey = std::tuple<Index, Index, Index, Index, double>;

std::vector<VfKey> vf_keys(const CollisionSet& c) {
  std::vector<VfKey> keys;
  for (const auto& x : c.vertex_face) keys.emplace_back(x.vertex, x.face, x.toi);
  return keys;
}

std::vector<EeKey> ee_keys(const CollisionSet& c) {
  std::vector<EeKey> keys;
  for (const auto& x : c.edge_edge) keys.emplace_back(x.a0, x.a1, x.b0, x.b1, x.toi);
  return keys;
}

/// Runs the checker over the whole sequence and compares everything with the oracles.
void expect_known_answers(const ProceduralSequence& s, const std::filesystem::path& folder,
                          int read_ahead) {
  SequenceCheckOptions options;
  options.read_ahead = read_ahead;
  SequenceChecker checker(FrameSequence(folder), std::nullopt, options);
  const TriangleMesh mesh(static_cast<Index>(s.frames[0].rows()), s.faces);
  EXPECT_EQ(checker.num_steps(), static_cast<Index>(s.frames.size()) - 1);
  EXPECT_EQ(checker.first_frame_check().frame, 0);
  EXPECT_TRUE(checker.first_frame_check().checked);
  EXPECT_EQ(checker.first_frame_check().intersection_free(), !s.intersecting[0]);
  Index expected_step = 0;
  Index steps_with_contacts = 0;
  FrameCheck previous_end = checker.first_frame_check();
  while (std::optional<StepCheck> step = checker.next_step()) {
    const Index k = step->step;
    ASSERT_EQ(k, expected_step++);
    const CollisionSet truth = brute_force_self_collisions(mesh, s.frames[k], s.frames[k + 1]);
    EXPECT_EQ(vf_keys(step->collisions), vf_keys(truth)) << "step " << k;
    EXPECT_EQ(ee_keys(step->collisions), ee_keys(truth)) << "step " << k;
    EXPECT_EQ(step->stats.vf_colliding + step->stats.ee_colliding,
              static_cast<std::int64_t>(truth.size()));
    steps_with_contacts += truth.size() > 0 ? 1 : 0;
    EXPECT_EQ(step->start.frame, k);
    EXPECT_EQ(step->start.file, previous_end.file);
    EXPECT_EQ(step->end.frame, k + 1);
    EXPECT_EQ(step->end.file, checker.frames().path(k + 1));
    EXPECT_TRUE(step->end.checked);
    EXPECT_EQ(step->end.intersection_free(), !s.intersecting[k + 1]) << "frame " << k + 1;
    EXPECT_EQ(step->end.intersections.obstacle_intersections, 0);
    previous_end = step->end;
  }
  EXPECT_EQ(expected_step, checker.num_steps());
  const SequenceSummary& summary = checker.summary();
  EXPECT_EQ(summary.frames, static_cast<Index>(s.frames.size()));
  EXPECT_EQ(summary.steps, checker.num_steps());
  EXPECT_EQ(summary.steps_with_contacts, steps_with_contacts);
  std::vector<Index> intersecting;
  for (std::size_t k = 0; k < s.frames.size(); ++k) {
    if (s.intersecting[k]) intersecting.push_back(static_cast<Index>(k));
  }
  EXPECT_EQ(summary.intersecting_frames, intersecting);
  EXPECT_EQ(summary.frames_with_intersections, static_cast<Index>(intersecting.size()));
  EXPECT_EQ(summary.first_intersecting_frame, intersecting.empty() ? -1 : intersecting.front());
  EXPECT_EQ(summary.intersection_free(), intersecting.empty());
}

TEST(SequenceCheck, FallingFoldEveryStepEqualsBruteForce) {
  TempDir dir;
  const ProceduralSequence s = make_falling_fold(small_fold());
  write_sequence(dir.path(), s, "fold_{}.ply");
  for (int read_ahead : {0, 2, SequenceCheckOptions::kAutoReadAhead}) {
    expect_known_answers(s, dir.path(), read_ahead);
  }
}

TEST(SequenceCheck, ExactlyDegenerateFoldEqualsBruteForce) {
  // No jitter: coplanar and parallel pairs everywhere, decided on the exact path (slow, so
  // a short and narrow sequence).
  TempDir dir;
  FallingFoldOptions o = small_fold(-1, 0.0);
  o.cells_along = sanitized() ? 16 : 24;
  o.cells_across = 1;
  o.frames = sanitized() ? 3 : 5;
  const ProceduralSequence s = make_falling_fold(o);
  write_sequence(dir.path(), s, "fold_{}.ply");
  expect_known_answers(s, dir.path(), 2);
}

TEST(SequenceCheck, PiercingFrameIsTheOnlyIntersectingFrame) {
  TempDir dir;
  const int piercing = 6;
  const ProceduralSequence s = make_falling_fold(small_fold(piercing));
  write_sequence(dir.path(), s, "fold_{:03d}.obj");
  for (int read_ahead : {0, 3}) expect_known_answers(s, dir.path(), read_ahead);

  // The steps into and out of the piercing frame carry the dent through the bottom layer.
  SequenceChecker checker{FrameSequence(dir.path())};
  while (std::optional<StepCheck> step = checker.next_step()) {
    if (step->step == piercing - 1 || step->step == piercing) {
      EXPECT_TRUE(step->has_contacts()) << "step " << step->step;
      ASSERT_TRUE(step->earliest_toi().has_value());
      EXPECT_GE(*step->earliest_toi(), 0.0);
      EXPECT_LE(*step->earliest_toi(), 1.0);
    }
  }
  const SequenceSummary& summary = checker.summary();
  EXPECT_GE(summary.steps_with_contacts, 2);
  EXPECT_LE(summary.first_contact_step, piercing - 1);
  EXPECT_GT(summary.vf_collisions + summary.ee_collisions, 0);
  ASSERT_TRUE(summary.earliest_toi.has_value());
  EXPECT_GE(summary.earliest_toi_step, 0);
}

TEST(SequenceCheck, RangeOfFrames) {
  TempDir dir;
  const ProceduralSequence s = make_falling_fold(small_fold(7));
  write_sequence(dir.path(), s, "fold_{}.ply");
  SequenceCheckOptions options;
  options.first_frame = 2;
  options.last_frame = 5;  // stops before the piercing frame
  SequenceChecker checker(FrameSequence(dir.path()), std::nullopt, options);
  EXPECT_EQ(checker.first_frame(), 2);
  EXPECT_EQ(checker.last_frame(), 5);
  EXPECT_EQ(checker.num_steps(), 3);
  EXPECT_EQ(checker.first_frame_check().frame, 2);
  std::vector<Index> steps;
  while (std::optional<StepCheck> step = checker.next_step()) steps.push_back(step->step);
  EXPECT_EQ(steps, (std::vector<Index>{2, 3, 4}));
  EXPECT_EQ(checker.summary().frames, 4);
  EXPECT_TRUE(checker.summary().intersection_free());

  for (const auto& [first, last] : {std::pair{0, 10}, std::pair{4, 3}, std::pair{-2, 3}}) {
    SequenceCheckOptions bad;
    bad.first_frame = first;
    bad.last_frame = last;
    expect_contains(
        input_error_message([&] { SequenceChecker(FrameSequence(dir.path()), std::nullopt, bad); }),
        {"not within the sequence", "fold_0.ply", "numbered from 0"});
  }
}

/// A flat square obstacle under the strip, at height z.
MeshData floor_at(double z) {
  MeshData floor = make_grid(4, 4, 1.4, 0.6);
  floor.vertices.col(0).array() -= 0.2;
  floor.vertices.col(1).array() -= 0.1;
  floor.vertices.col(2).setConstant(z);
  return floor;
}

TEST(SequenceCheck, ObstacleStillOrMovingWithTheFrames) {
  TempDir dir;
  const ProceduralSequence s = make_falling_fold(small_fold());
  const std::filesystem::path cloth = dir / "cloth";
  const std::filesystem::path still = dir / "still";
  const std::filesystem::path moving = dir / "moving";
  for (const auto& folder : {cloth, still, moving}) std::filesystem::create_directories(folder);
  write_sequence(cloth, s, "c_{}.ply");
  const MeshData below = floor_at(-0.01), raised = floor_at(0.01);  // raised cuts the fold
  write_mesh(still / "floor.obj", below.vertices, below.faces);
  const int raised_frame = 3;
  for (std::size_t k = 0; k < s.frames.size(); ++k) {
    const MeshData& floor = static_cast<int>(k) == raised_frame ? raised : below;
    write_mesh(moving / fmt::format("floor_{}.obj", k), floor.vertices, floor.faces);
  }

  SequenceChecker with_still(FrameSequence{cloth}, FrameSequence{still});
  ASSERT_NE(with_still.obstacle(), nullptr);
  while (std::optional<StepCheck> step = with_still.next_step()) {
    EXPECT_EQ(step->end.intersections.obstacle_intersections, 0);
  }
  EXPECT_TRUE(with_still.summary().intersection_free());

  SequenceChecker with_moving(FrameSequence{cloth}, FrameSequence{moving});
  while (std::optional<StepCheck> step = with_moving.next_step()) {
    EXPECT_EQ(step->end.intersections.self_intersections, 0);
    EXPECT_EQ(step->end.intersections.obstacle_intersections > 0, step->end.frame == raised_frame)
        << "frame " << step->end.frame;
    EXPECT_EQ(step->end.intersection_free(), step->end.frame != raised_frame);
  }
  EXPECT_EQ(with_moving.summary().intersecting_frames, (std::vector<Index>{raised_frame}));

  std::filesystem::remove(moving / "floor_5.obj");  // one frame short
  expect_contains(
      input_error_message([&] { SequenceChecker(FrameSequence{cloth}, FrameSequence{moving}); }),
      {fmt::format("obstacle has {} frames", s.frames.size() - 1), "floor_0.obj",
       fmt::format("sequence has {}", s.frames.size())});
}

TEST(SequenceCheck, ObstacleFramesAreReadOnlyForTheFrameCheck) {
  TempDir dir;
  const ProceduralSequence s = make_falling_fold(small_fold(6));
  const std::filesystem::path cloth = dir / "cloth";
  const std::filesystem::path floor = dir / "floor";
  for (const auto& folder : {cloth, floor}) std::filesystem::create_directories(folder);
  write_sequence(cloth, s, "c_{}.ply");
  const MeshData below = floor_at(-0.01);
  for (std::size_t k = 0; k < s.frames.size(); ++k) {
    write_mesh(floor / fmt::format("floor_{}.obj", k), below.vertices, below.faces);
  }
  test::write_bytes(floor / "floor_3.obj", "not an obj file\n");

  // Without the static check nothing looks at the obstacle: its frames are not read.
  SequenceCheckOptions steps_only;
  steps_only.check_frames = false;
  const SequenceSummary summary =
      check_sequence(FrameSequence{cloth}, FrameSequence{floor}, steps_only, nullptr);
  EXPECT_EQ(summary.steps, static_cast<Index>(s.frames.size()) - 1);

  SequenceChecker checked(FrameSequence{cloth}, FrameSequence{floor});
  expect_contains(input_error_message([&] {
                    while (checked.next_step()) {
                    }
                  }),
                  {"floor_3.obj", "unknown statement"});
  EXPECT_EQ(checked.summary().steps, 2);
}

TEST(SequenceCheck, MismatchedFrameStopsThereNamingIt) {
  TempDir dir;
  ProceduralSequence s = make_falling_fold(small_fold());
  s.frames.resize(7);
  const auto paths = write_sequence(dir.path(), s, "fold_{}.obj");
  FaceArray flipped = s.faces;
  flipped.row(3) << s.faces(3, 0), s.faces(3, 2), s.faces(3, 1);
  write_mesh(paths[4], s.frames[4], flipped);
  for (int read_ahead : {0, 2, SequenceCheckOptions::kAutoReadAhead}) {
    SequenceCheckOptions options;
    options.read_ahead = read_ahead;
    SequenceChecker checker(FrameSequence(dir.path()), std::nullopt, options);
    std::vector<Index> steps;
    for (int i = 0; i < 3; ++i) {
      const std::optional<StepCheck> step = checker.next_step();
      ASSERT_TRUE(step.has_value());
      steps.push_back(step->step);
    }
    EXPECT_EQ(steps, (std::vector<Index>{0, 1, 2}));
    for (int attempt = 0; attempt < 2; ++attempt) {
      expect_contains(input_error_message([&] { checker.next_step(); }),
                      {"fold_4.obj", "faces differ", "fold_0.obj", "face 3"});
    }
    EXPECT_EQ(checker.summary().steps, 3);
  }
}

TEST(SequenceCheck, CallbackStopsEarlyAndFrameChecksCanBeOff) {
  TempDir dir;
  const ProceduralSequence s = make_falling_fold(small_fold(6));
  write_sequence(dir.path(), s, "fold_{}.ply");
  std::vector<Index> seen;
  const SequenceSummary summary =
      check_sequence(FrameSequence(dir.path()), std::nullopt, {}, [&](const StepCheck& step) {
        seen.push_back(step.step);
        return seen.size() < 2;
      });
  EXPECT_EQ(seen, (std::vector<Index>{0, 1}));
  EXPECT_EQ(summary.steps, 2);
  EXPECT_EQ(summary.frames, 3);

  SequenceCheckOptions steps_only;
  steps_only.check_frames = false;
  const SequenceSummary unchecked = check_sequence(FrameSequence(dir.path()), std::nullopt,
                                                   steps_only, [](const StepCheck& step) {
                                                     EXPECT_FALSE(step.end.checked);
                                                     EXPECT_TRUE(step.end.intersection_free());
                                                     return true;
                                                   });
  EXPECT_EQ(unchecked.steps, static_cast<Index>(s.frames.size()) - 1);
  EXPECT_EQ(unchecked.frames_with_intersections, 0);  // frame 6 was not checked
  EXPECT_GT(unchecked.steps_with_contacts, 0);        // the steps still were
}

}  // namespace
}  // namespace tailor
