#include "tailor/candidates/primitive_pair_generator.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>

#include "tailor/bvh/step_boxes.hpp"
#include "tailor/candidates/batch_pair_filters.hpp"

#include "tailor/candidates/step_separating_direction.hpp"
#include "tailor/candidates/triangle_plane_sides.hpp"

namespace tailor {
namespace {

// A moving point: its coordinates at t=0 and t=1 (rows of the row-major positions).
struct Corner {
  const double* t0;
  const double* t1;
};

Corner corner(const Positions& x0, const Positions& x1, Index v) {
  return {x0.data() + 3 * static_cast<std::ptrdiff_t>(v),
          x1.data() + 3 * static_cast<std::ptrdiff_t>(v)};
}

// Exact bounds of moving points in one frame (min and max of the inputs).
struct Bounds {
  double min[3], max[3];
};

// Boxes of moving points at the step's two ends.
struct Box {
  Bounds start, end;
};

Box point_box(Corner c) {
  Box box;
  for (int k = 0; k < 3; ++k) {
    box.start.min[k] = box.start.max[k] = c.t0[k];
    box.end.min[k] = box.end.max[k] = c.t1[k];
  }
  return box;
}

Bounds joined(const Bounds& a, const Bounds& b) {
  Bounds bounds;
  for (int k = 0; k < 3; ++k) {
    bounds.min[k] = std::min(a.min[k], b.min[k]);
    bounds.max[k] = std::max(a.max[k], b.max[k]);
  }
  return bounds;
}

Box joined(const Box& a, const Box& b) {
  return {joined(a.start, b.start), joined(a.end, b.end)};
}

// Whether two primitives may meet during the step (bvh/step_boxes.hpp, on exact bounds).
bool may_meet(const Box& a, const Box& b) {
  return may_meet_over_step(a.start, a.end, b.start, b.end);
}

bool contains(const Index* face, Index v) {
  return face[0] == v || face[1] == v || face[2] == v;
}

using ThreadOutput = PrimitivePairGenerator::ThreadOutput;
using FaceFeatures = FeatureAssignment::FaceFeatures;

// Appends a pair that every filter kept.
void keep(PairKind kind, Index first, Index second, ThreadOutput& out) {
  if (kind == PairKind::vertex_face) {
    ++out.counts.vf_after_projection;
    out.vertex_face.push_back({first, second});
  } else {
    ++out.counts.ee_after_projection;
    out.edge_edge.push_back({first, second});
  }
}

// Runs the filters on the pairs waiting in a batch and keeps the survivors.
void flush(PairKind kind, PairFilters filters, ThreadOutput& out) {
  PairBatch& batch = kind == PairKind::vertex_face ? out.vertex_face_batch : out.edge_edge_batch;
  if (batch.count == 0) return;
  std::array<PairVerdict, PairBatch::kCapacity> verdicts;
  pair_verdicts(kind, batch, filters, verdicts);
  std::int64_t& after_filter =
      kind == PairKind::vertex_face ? out.counts.vf_after_filter : out.counts.ee_after_filter;
  for (int i = 0; i < batch.count; ++i) {
    after_filter += verdicts[i] != PairVerdict::never_coplanar;  // no branch: a coin toss
    if (verdicts[i] == PairVerdict::may_touch)
      keep(kind, batch.first_id[i], batch.second_id[i], out);
  }
  batch.count = 0;
}

// The stages after feature assignment, for one step.
class Stages {
 public:
  Stages(const TriangleMesh& mesh, const FeatureAssignment& assignment, const Positions& x0,
         const Positions& x1, const LowLevelOptions& options)
      : m_mesh(mesh),
        m_assignment(assignment),
        m_x0(x0),
        m_x1(x1),
        m_options(options),
        m_filters{options.coplanarity_filter, options.projection_filter} {}

  Corner at(Index v) const { return corner(m_x0, m_x1, v); }

  // Boxes for VF pair (v, f), the face's corners a, b, c (`p_box` and `face_box` are their
  // boxes at both ends of the step), then the filters. `off_plane`: the triangle filter proved that
  // p never meets the face's plane.
  void vertex_face(Index v, Index f, Corner p, Corner a, Corner b, Corner c, const Box& p_box,
                   const Box& face_box, bool off_plane, ThreadOutput& out) const {
    // Counted without branches; one branch for the pairs that go on (both are hard to
    // predict: about half the pairs pass the boxes).
    const bool boxes_meet = !m_options.primitive_boxes || may_meet(p_box, face_box);
    ++out.counts.vf_generated;
    out.counts.vf_after_boxes += boxes_meet;
    if (boxes_meet & !off_plane) submit(PairKind::vertex_face, v, f, {a, b, c, p}, out);
  }

  // The same for EE pair (e1, e2), e1 < e2, edges ab and cd. `off_plane`: the triangle
  // filter proved that one edge never meets the plane of the other's triangle.
  void edge_edge(Index e1, Index e2, Corner a, Corner b, Corner c, Corner d, const Box& box1,
                 const Box& box2, bool off_plane, ThreadOutput& out) const {
    const bool boxes_meet = !m_options.primitive_boxes || may_meet(box1, box2);
    ++out.counts.ee_generated;
    out.counts.ee_after_boxes += boxes_meet;
    if (boxes_meet & !off_plane) submit(PairKind::edge_edge, e1, e2, {a, b, c, d}, out);
  }

  // A VF pair by ids (the isolated set).
  void vertex_face(Index v, Index f, ThreadOutput& out) const {
    const FaceArray& faces = m_mesh.faces();
    const Corner p = at(v), a = at(faces(f, 0)), b = at(faces(f, 1)), c = at(faces(f, 2));
    vertex_face(v, f, p, a, b, c, point_box(p),
                joined(joined(point_box(a), point_box(b)), point_box(c)), false, out);
  }

  // An EE pair by ids, e1 < e2 (the isolated set).
  void edge_edge(Index e1, Index e2, ThreadOutput& out) const {
    const EdgeArray& edges = m_mesh.edges();
    const Corner a = at(edges(e1, 0)), b = at(edges(e1, 1));
    const Corner c = at(edges(e2, 0)), d = at(edges(e2, 1));
    edge_edge(e1, e2, a, b, c, d, joined(point_box(a), point_box(b)),
              joined(point_box(c), point_box(d)), false, out);
  }

  // Stage 1 and the rest: the feature pairs CTP (f, g) owes. Which ones it owes is
  // settled first from topology alone (most CTPs owe few of their 15 pairs, some none);
  // only then are the six corners read, once, their boxes shared by the owed pairs.
  // `sides`: the triangle filter's corner sides (none known when it is off).
  void expand(Index f, Index g, TrianglePairSides sides, ThreadOutput& out) const {
    const FaceFeatures* record[2] = {&m_assignment.face_features(f),
                                     &m_assignment.face_features(g)};
    const Index face[2][3] = {
        {record[0]->corners[0], record[0]->corners[1], record[0]->corners[2]},
        {record[1]->corners[0], record[1]->corners[1], record[1]->corners[2]}};
    bool disjoint = true;
    for (int k = 0; k < 3; ++k) disjoint &= !contains(face[1], face[0][k]);
    const auto& edges_f = record[0]->edges;
    const auto& edges_g = record[1]->edges;
    unsigned vf_owed = 0, ee_owed = 0;
    if (disjoint && m_options.feature_assignment && m_options.adjacency_culling) {
      owed_when_disjoint(f, g, record, face, vf_owed, ee_owed);
    } else {
      vf_owed = owed_vertex_faces(f, g, record, face, disjoint);
      ee_owed = owed_edge_edges(f, g, record, face, disjoint);
    }
    if ((vf_owed | ee_owed) == 0) return;

    Corner corners[2][3];
    Box corner_boxes[2][3], face_boxes[2];
    for (int s = 0; s < 2; ++s) {
      for (int k = 0; k < 3; ++k) {
        corners[s][k] = at(face[s][k]);
        corner_boxes[s][k] = point_box(corners[s][k]);
      }
      face_boxes[s] = joined(joined(corner_boxes[s][0], corner_boxes[s][1]), corner_boxes[s][2]);
    }
    const Index ids[2] = {f, g};
    for (unsigned bits = vf_owed; bits != 0; bits &= bits - 1) {
      const int slot = std::countr_zero(bits);  // 3 s + k: corner k of side s
      const int s = slot / 3, k = slot % 3, o = 1 - s;
      const int bit =
          s == 0 ? TrianglePairSides::first_corner(k) : TrianglePairSides::second_corner(k);
      vertex_face(face[s][k], ids[o], corners[s][k], corners[o][0], corners[o][1], corners[o][2],
                  corner_boxes[s][k], face_boxes[o], sides.corner_off_plane(bit), out);
    }
    for (unsigned bits = ee_owed; bits != 0; bits &= bits - 1) {
      const int slot = std::countr_zero(bits);  // 3 i + j: edge i of f, edge j of g
      const int i = slot / 3, j = slot % 3;
      const Index ef = edges_f[i], eg = edges_g[j];
      // Edge i of a face joins its corners i and i+1.
      const int i1 = (i + 1) % 3, j1 = (j + 1) % 3;
      const bool off_plane = sides.segment_off_plane(TrianglePairSides::first_corner(i),
                                                     TrianglePairSides::first_corner(i1)) ||
                             sides.segment_off_plane(TrianglePairSides::second_corner(j),
                                                     TrianglePairSides::second_corner(j1));
      const Box box_f = joined(corner_boxes[0][i], corner_boxes[0][i1]);
      const Box box_g = joined(corner_boxes[1][j], corner_boxes[1][j1]);
      // Orient each edge as stored (a < b) and order the pair by edge id, so that a pair
      // reaches the filters with the same coordinates whichever CTP owes it. Selected, not
      // branched on: each choice is a coin toss for the branch predictor.
      const int f_low = face[0][i] < face[0][i1] ? i : i1, f_high = i + i1 - f_low;
      const int g_low = face[1][j] < face[1][j1] ? j : j1, g_high = j + j1 - g_low;
      const bool f_first = ef < eg;
      const int s1 = f_first ? 0 : 1;
      const int low1 = f_first ? f_low : g_low, high1 = f_first ? f_high : g_high;
      const int low2 = f_first ? g_low : f_low, high2 = f_first ? g_high : f_high;
      edge_edge(std::min(ef, eg), std::max(ef, eg), corners[s1][low1], corners[s1][high1],
                corners[1 - s1][low2], corners[1 - s1][high2], f_first ? box_f : box_g,
                f_first ? box_g : box_f, off_plane, out);
    }
  }

 private:
  // The pairs that passed the boxes and the triangle filter wait for the filters in a
  // batch (the points a, b, c, d of batch_pair_filters.hpp).
  void submit(PairKind kind, Index first, Index second, const std::array<Corner, 4>& points,
              ThreadOutput& out) const {
    if (!m_filters.coplanarity && !m_filters.projection) {
      ++(kind == PairKind::vertex_face ? out.counts.vf_after_filter : out.counts.ee_after_filter);
      keep(kind, first, second, out);
      return;
    }
    PairBatch& batch = kind == PairKind::vertex_face ? out.vertex_face_batch : out.edge_edge_batch;
    batch.add(first, second, {points[0].t0, points[1].t0, points[2].t0, points[3].t0},
              {points[0].t1, points[1].t1, points[2].t1, points[3].t1});
    if (batch.full()) flush(kind, m_filters, out);
  }

  // owed_vertex_faces and owed_edge_edges in the common case (feature assignment with
  // adjacency culling, f and g sharing no vertex), without a branch per pair: the owned
  // features, and those whose owner shares a vertex with the other face, for which the
  // first vertex-disjoint face (pair) decides, as in owes_vertex_face / owes_edge_edge.
  void owed_when_disjoint(Index f, Index g, const FaceFeatures* const (&record)[2],
                          const Index (&face)[2][3], unsigned& vf_owed, unsigned& ee_owed) const {
    const auto holds = [](const Index* to_face, Index x) {
      return static_cast<unsigned>((to_face[0] == x) | (to_face[1] == x) | (to_face[2] == x));
    };
    const Index ids[2] = {f, g};
    unsigned vf_touching = 0;
    for (int s = 0; s < 2; ++s) {
      for (int k = 0; k < 3; ++k) {
        const auto& others = record[s]->corner_owner_others[k];
        vf_touching |= (holds(face[1 - s], others[0]) | holds(face[1 - s], others[1]))
                       << (3 * s + k);
      }
    }
    vf_owed = (record[0]->owned & 7u) | ((record[1]->owned & 7u) << 3);
    for (unsigned bits = vf_touching & ~vf_owed; bits != 0; bits &= bits - 1) {
      const int slot = std::countr_zero(bits), s = slot / 3, k = slot % 3;
      if (first_face_disjoint_from(m_mesh, face[s][k], ids[1 - s]) == ids[s]) {
        vf_owed |= 1u << slot;
      }
    }
    unsigned ee_touching = 0;
    ee_owed = 0;
    const unsigned edges_f = record[0]->owned >> 3, edges_g = record[1]->owned >> 3;
    for (int i = 0; i < 3; ++i) {
      const Index r1 = record[0]->edge_owner_opposite[i];
      const Index p1 = face[0][i], q1 = face[0][(i + 1) % 3];
      for (int j = 0; j < 3; ++j) {
        const Index r2 = record[1]->edge_owner_opposite[j];
        const Index p2 = face[1][j], q2 = face[1][(j + 1) % 3];
        const unsigned bit = 3 * i + j;
        ee_owed |= ((edges_f >> i) & (edges_g >> j) & 1u) << bit;
        ee_touching |=
            static_cast<unsigned>((r1 == p2) | (r1 == q2) | (r1 == r2) | (r2 == p1) | (r2 == q1))
            << bit;
      }
    }
    for (unsigned bits = ee_touching & ~ee_owed; bits != 0; bits &= bits - 1) {
      const int slot = std::countr_zero(bits), i = slot / 3, j = slot % 3;
      const Index ef = record[0]->edges[i], eg = record[1]->edges[j];
      const auto expected = ef < eg ? std::pair{f, g} : std::pair{g, f};
      if (first_disjoint_face_pair(m_mesh, std::min(ef, eg), std::max(ef, eg)) == expected) {
        ee_owed |= 1u << slot;
      }
    }
  }

  // Bit 3 s + k: the CTP owes the VF pair (corner k of side s, the other side's face).
  unsigned owed_vertex_faces(Index f, Index g, const FaceFeatures* const (&record)[2],
                             const Index (&face)[2][3], bool disjoint) const {
    const Index ids[2] = {f, g};
    unsigned owed = 0;
    for (int s = 0; s < 2; ++s) {
      const int o = 1 - s;
      for (int k = 0; k < 3; ++k) {
        if (!disjoint && contains(face[o], face[s][k])) continue;
        if (owes_vertex_face(ids[s], *record[s], k, ids[o], face[o], disjoint)) {
          owed |= 1u << (3 * s + k);
        }
      }
    }
    return owed;
  }

  // Bit 3 i + j: the CTP owes the EE pair (edge i of f, edge j of g).
  unsigned owed_edge_edges(Index f, Index g, const FaceFeatures* const (&record)[2],
                           const Index (&face)[2][3], bool disjoint) const {
    unsigned owed = 0;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        if (!disjoint && m_mesh.edges_share_vertex(record[0]->edges[i], record[1]->edges[j])) {
          continue;
        }
        if (owes_edge_edge(f, *record[0], i, face[0], g, *record[1], j, face[1], disjoint)) {
          owed |= 1u << (3 * i + j);
        }
      }
    }
    return owed;
  }

  // Whether CTP (from, to) is the representative of VF pair (corner k of `from`, `to`).
  bool owes_vertex_face(Index from, const FaceFeatures& from_record, int k, Index to,
                        const Index* to_face, bool disjoint) const {
    if (!m_options.feature_assignment) return true;
    const Index v = from_record.corners[k];
    if (!disjoint)
      return m_assignment.vf_representative(v, to, m_options.adjacency_culling) == from;
    if ((from_record.owned >> k) & 1) return true;   // owner(v) = from, disjoint from `to`
    if (!m_options.adjacency_culling) return false;  // the representative is owner(v)
    // owner(v) shares a vertex with `to` only through its other corners (v is not in `to`);
    // otherwise the representative is owner(v) != from.
    const auto& others = from_record.corner_owner_others[k];
    if (!contains(to_face, others[0]) && !contains(to_face, others[1])) return false;
    return first_face_disjoint_from(m_mesh, v, to) == from;
  }

  // Whether CTP (f, g) is the representative of EE pair (edge i of f, edge j of g).
  bool owes_edge_edge(Index f, const FaceFeatures& record_f, int i, const Index* face_f, Index g,
                      const FaceFeatures& record_g, int j, const Index* face_g,
                      bool disjoint) const {
    if (!m_options.feature_assignment) return true;
    const Index ef = record_f.edges[i], eg = record_g.edges[j];
    const Index lo = std::min(ef, eg), hi = std::max(ef, eg);
    const auto expected = ef < eg ? std::pair{f, g} : std::pair{g, f};
    if (!disjoint) {
      return m_assignment.ee_representative(lo, hi, m_options.adjacency_culling) == expected;
    }
    if ((record_f.owned >> (3 + i)) & (record_g.owned >> (3 + j)) & 1) return true;
    if (!m_options.adjacency_culling) return false;  // the representative is the owners
    // The owners {p1, q1, r1} ⊃ ef and {p2, q2, r2} ⊃ eg: f and g share no vertex, so
    // they can only share r1 or r2.
    const Index r1 = record_f.edge_owner_opposite[i], r2 = record_g.edge_owner_opposite[j];
    const Index p1 = face_f[i], q1 = face_f[(i + 1) % 3], p2 = face_g[j], q2 = face_g[(j + 1) % 3];
    if (r1 != p2 && r1 != q2 && r1 != r2 && r2 != p1 && r2 != q1) return false;
    return first_disjoint_face_pair(m_mesh, lo, hi) == expected;
  }

  const TriangleMesh& m_mesh;
  const FeatureAssignment& m_assignment;
  const Positions& m_x0;
  const Positions& m_x1;
  const LowLevelOptions& m_options;
  const PairFilters m_filters;
};

}  // namespace

LowLevelCounts& LowLevelCounts::operator+=(const LowLevelCounts& other) {
  triangle_pairs_separated += other.triangle_pairs_separated;
  triangle_pairs_apart += other.triangle_pairs_apart;
  vf_generated += other.vf_generated;
  ee_generated += other.ee_generated;
  vf_after_boxes += other.vf_after_boxes;
  ee_after_boxes += other.ee_after_boxes;
  vf_after_filter += other.vf_after_filter;
  ee_after_filter += other.ee_after_filter;
  vf_after_projection += other.vf_after_projection;
  ee_after_projection += other.ee_after_projection;
  return *this;
}

PrimitivePairGenerator::PrimitivePairGenerator(const TriangleMesh& mesh)
    : m_mesh(&mesh), m_assignment(mesh) {}

void PrimitivePairGenerator::begin_step() {
  for (ThreadOutput& out : m_outputs) {
    out.vertex_face.clear();
    out.edge_edge.clear();
    out.counts = {};
  }
}

void PrimitivePairGenerator::clear_pairs() {
  for (ThreadOutput& out : m_outputs) {
    out.vertex_face.clear();
    out.edge_edge.clear();
  }
}

void PrimitivePairGenerator::prefetch_ahead(std::span<const TrianglePair> ctps, std::size_t first,
                                            std::size_t end) const {
  // CTPs come in traversal order, their faces in no order of memory: the records of a
  // chunk's faces are fetched while the triangle filter runs on it.
  for (std::size_t i = first; i < std::min(end, first + kChunk); ++i) {
    __builtin_prefetch(&m_assignment.face_features(ctps[i].first));
    __builtin_prefetch(&m_assignment.face_features(ctps[i].second));
  }
}

void PrimitivePairGenerator::add_triangle_pairs(std::span<const TrianglePair> ctps,
                                                const Positions& x0, const Positions& x1,
                                                const LowLevelOptions& options) {
  const Stages stages(*m_mesh, m_assignment, x0, x1, options);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ctps.size(), 512), [&](const auto& r) {
    ThreadOutput& local = m_outputs.local();
    std::array<TrianglePairSides, kChunk> sides{};
    for (std::size_t first = r.begin(); first < r.end(); first += kChunk) {
      const std::size_t count = std::min(kChunk, r.end() - first);
      const std::span<const TrianglePair> chunk = ctps.subspan(first, count);
      prefetch_ahead(ctps, first, r.end());
      if (options.triangle_filter) {
        triangle_pair_sides(m_mesh->faces(), x0, x1, chunk, std::span(sides.data(), count));
      }
      if (options.direction_filter) {
        mark_pairs_apart(m_mesh->faces(), x0, x1, chunk, std::span(sides.data(), count));
      }
      // The CTPs the filters kept, listed without a branch per CTP (about three in four
      // are dropped, in no predictable order), then expanded.
      std::array<std::uint8_t, kChunk> kept;
      std::size_t num_kept = 0, num_apart = 0;
      for (std::size_t i = 0; i < count; ++i) {
        kept[num_kept] = static_cast<std::uint8_t>(i);
        num_kept += !sides[i].separated();
        num_apart += sides[i].apart;
      }
      local.counts.triangle_pairs_separated +=
          static_cast<std::int64_t>(count - num_kept - num_apart);
      local.counts.triangle_pairs_apart += static_cast<std::int64_t>(num_apart);
      for (std::size_t k = 0; k < num_kept; ++k) {
        const std::size_t i = kept[k];
        stages.expand(chunk[i].first, chunk[i].second, sides[i], local);
      }
    }
  });
  flush_batches(options);
}

void PrimitivePairGenerator::add_isolated(const IsolatedSet& isolated, const Positions& x0,
                                          const Positions& x1, const LowLevelOptions& options) {
  const Stages stages(*m_mesh, m_assignment, x0, x1, options);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, isolated.vertex_face.size(), 1024), [&](const auto& r) {
        ThreadOutput& local = m_outputs.local();
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
          stages.vertex_face(isolated.vertex_face[i].vertex, isolated.vertex_face[i].face, local);
        }
      });
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, isolated.edge_edge.size(), 1024), [&](const auto& r) {
        ThreadOutput& local = m_outputs.local();
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
          stages.edge_edge(isolated.edge_edge[i].edge_a, isolated.edge_edge[i].edge_b, local);
        }
      });
  flush_batches(options);
}

void PrimitivePairGenerator::flush_batches(const LowLevelOptions& options) {
  const PairFilters filters{options.coplanarity_filter, options.projection_filter};
  for (ThreadOutput& out : m_outputs) {
    flush(PairKind::vertex_face, filters, out);
    flush(PairKind::edge_edge, filters, out);
  }
}

std::vector<std::span<const VertexFacePair>> PrimitivePairGenerator::vertex_face_blocks() const {
  std::vector<std::span<const VertexFacePair>> blocks;
  for (const ThreadOutput& out : m_outputs) {
    if (!out.vertex_face.empty()) blocks.emplace_back(out.vertex_face);
  }
  return blocks;
}

std::vector<std::span<const EdgeEdgePair>> PrimitivePairGenerator::edge_edge_blocks() const {
  std::vector<std::span<const EdgeEdgePair>> blocks;
  for (const ThreadOutput& out : m_outputs) {
    if (!out.edge_edge.empty()) blocks.emplace_back(out.edge_edge);
  }
  return blocks;
}

LowLevelCounts PrimitivePairGenerator::counts() const {
  LowLevelCounts total;
  for (const ThreadOutput& out : m_outputs) total += out.counts;
  return total;
}

}  // namespace tailor
