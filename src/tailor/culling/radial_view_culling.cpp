#include "tailor/culling/radial_view_culling.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <optional>

#include "tailor/culling/moving_plane.hpp"
#include "tailor/culling/winding_number.hpp"
#include "tailor/geometry/coplanarity_sign.hpp"

namespace tailor {
namespace {

// Faces and blocking triangles are grouped this many at a time under one bounding view
// cone, so that most group pairs are found disjoint without testing their members.
constexpr int kGroup = 8;

// Whether the swept box of `points` (positions at t = 0 and t = 1) and the swept box of
// the observer are disjoint (exact: min/max of the given doubles).
bool swept_boxes_disjoint(const std::array<Vec3, 6>& points, const Vec3& o0, const Vec3& o1) {
  for (int axis = 0; axis < 3; ++axis) {
    double lo = points[0][axis], hi = lo;
    for (const Vec3& p : points) {
      lo = std::min(lo, p[axis]);
      hi = std::max(hi, p[axis]);
    }
    if (std::max(o0[axis], o1[axis]) < lo || std::min(o0[axis], o1[axis]) > hi) return true;
  }
  return false;
}

// A ghost triangle (w, u, centre) of a loop edge u -> w, closing a cluster's hole, with
// its raw sign against the observer over the step.
struct Ghost {
  Index u, w;
  Vec3 centre0, centre1;
  signed char raw;
};

std::vector<Ghost> ghost_triangles(const std::vector<std::vector<Index>>& loops,
                                   const Positions& x0, const Positions& x1, const Vec3& o0,
                                   const Vec3& o1) {
  std::vector<Ghost> ghosts;
  for (const auto& loop : loops) {
    const Vec3 centre0 = loop_centroid(x0, loop), centre1 = loop_centroid(x1, loop);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Index u = loop[i], w = loop[(i + 1) % loop.size()];
      const auto raw = static_cast<signed char>(coplanarity_sign(
          {x0.row(w), x0.row(u), centre0, o0}, {x1.row(w), x1.row(u), centre1, o1}));
      ghosts.push_back({u, w, centre0, centre1, raw});
    }
  }
  return ghosts;
}

std::array<Vec3, 6> ghost_corners(const Ghost& g, const Positions& x0, const Positions& x1) {
  return {x0.row(g.w), x0.row(g.u), g.centre0, x1.row(g.w), x1.row(g.u), g.centre1};
}

std::array<Vec3, 6> swept_corners(const TriangleMesh& mesh, Index f, const Positions& x0,
                                  const Positions& x1) {
  const auto v = mesh.faces().row(f);
  return {x0.row(v[0]), x0.row(v[1]), x0.row(v[2]), x1.row(v[0]), x1.row(v[1]), x1.row(v[2])};
}

// Rule (1) of the header: which raw sign means "seen" (+1 or -1), or 0 when the observer
// may be on a triangle during the step or the winding number at t = 0 is not ±1.
int seeing_sign(const TriangleMesh& mesh, const std::vector<Index>& faces,
                const std::vector<signed char>& face_raw, const std::vector<Ghost>& ghosts,
                const Positions& x0, const Positions& x1, const Vec3& o0, const Vec3& o1) {
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (face_raw[i] == 0 && !swept_boxes_disjoint(swept_corners(mesh, faces[i], x0, x1), o0, o1)) {
      return 0;
    }
  }
  for (const Ghost& g : ghosts) {
    if (g.raw == 0 && !swept_boxes_disjoint(ghost_corners(g, x0, x1), o0, o1)) return 0;
  }
  std::vector<TriangleCorners> surface;
  surface.reserve(faces.size() + ghosts.size());
  for (Index f : faces) {
    const auto v = mesh.faces().row(f);
    surface.push_back({x0.row(v[0]), x0.row(v[1]), x0.row(v[2])});
  }
  for (const Ghost& g : ghosts) surface.push_back({x0.row(g.w), x0.row(g.u), g.centre0});
  const std::optional<int> winding = winding_number(surface, o0);
  // Behind an outward face det(b-a, c-a, o-a) < 0: with winding +1, "positive" is a
  // negative raw sign; with winding -1 the cluster is oriented inward and it is the
  // other way round.
  return winding == 1 ? -1 : winding == -1 ? 1 : 0;
}

}  // namespace

RadialViewCulling::RadialViewCulling(const TriangleMesh& mesh, const Positions& x_build,
                                     std::vector<std::vector<Index>> section_loops)
    : m_clusters(mesh, x_build, std::move(section_loops)) {
  const Index n = m_clusters.num_clusters();
  m_state.resize(static_cast<std::size_t>(n));
  m_slot.resize(static_cast<std::size_t>(n));
  m_cluster_vertices.resize(static_cast<std::size_t>(n));
  m_local_faces.resize(static_cast<std::size_t>(n));
  for (Index c = 0; c < n; ++c) {
    if (!m_clusters.usable(c)) continue;
    m_usable |= std::uint64_t{1} << c;
    const auto& faces = m_clusters.faces(c);
    m_slot[c].assign(static_cast<std::size_t>(mesh.num_faces()), -1);
    for (std::size_t i = 0; i < faces.size(); ++i) m_slot[c][faces[i]] = static_cast<Index>(i);
  }
}

void RadialViewCulling::build_local_faces(Index c) {
  const FaceArray& all_faces = m_clusters.mesh().faces();
  const auto& faces = m_clusters.faces(c);
  std::vector<Index>& vertices = m_cluster_vertices[c];
  vertices.clear();
  vertices.reserve(3 * faces.size());
  for (Index f : faces) {
    for (int k = 0; k < 3; ++k) vertices.push_back(all_faces(f, k));
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  vertices.shrink_to_fit();
  std::vector<std::array<Index, 3>>& local = m_local_faces[c];
  local.resize(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      local[i][k] = static_cast<Index>(
          std::lower_bound(vertices.begin(), vertices.end(), all_faces(faces[i], k)) -
          vertices.begin());
    }
  }
}

RadialViewCounts RadialViewCulling::classify(const Positions& x0, const Positions& x1,
                                             bool find_clean) {
  begin_step(x0, x1, find_clean);
  return classify_wanted(true);
}

void RadialViewCulling::begin_step(const Positions& x0, const Positions& x1, bool find_clean) {
  m_x0 = &x0;
  m_x1 = &x1;
  m_find_clean = find_clean;
  m_wanted = 0;
  if (m_clean_mask_dirty) m_clean_mask.assign(m_clean_mask.size(), 0);
  m_clean_mask_dirty = false;
  for (Index c = 0; c < m_clusters.num_clusters(); ++c) {
    ClusterState& state = m_state[c];
    state.counts = {};
    state.face_sign.clear();
    if (!m_clusters.usable(c)) continue;
    state.observer0 = m_clusters.observer(c, x0);
    state.observer1 = m_clusters.observer(c, x1);
    state.face_raw.assign(m_clusters.faces(c).size(), kNotComputed);
  }
}

signed char RadialViewCulling::raw_sign(Index c, Index f) const {
  ClusterState& state = m_state[c];
  std::atomic_ref<signed char> cached(state.face_raw[m_slot[c][f]]);
  signed char raw = cached.load(std::memory_order_relaxed);
  if (raw != kNotComputed) return raw;
  // det(b-a, c-a, o-a) = det(o-a, b-a, c-a): the side of the observer of the face's
  // plane. Deterministic, so threads racing on one entry store the same value.
  const auto v = m_clusters.mesh().faces().row(f);
  const Positions& x0 = *m_x0;
  const Positions& x1 = *m_x1;
  raw = static_cast<signed char>(
      coplanarity_sign({x0.row(v[0]), state.observer0, x0.row(v[1]), x0.row(v[2])},
                       {x1.row(v[0]), state.observer1, x1.row(v[1]), x1.row(v[2])}));
  cached.store(raw, std::memory_order_relaxed);
  return raw;
}

RadialViewCounts RadialViewCulling::classify_wanted(bool every_cluster) {
  if (every_cluster) return classify_clusters(m_usable);
  std::uint64_t wanted = m_wanted;
  if (!m_find_clean) {
    // Only certification can cull here, and it needs every raw sign equal and nonzero: two
    // different raw signs among those the pairs computed already rule it out.
    for (std::uint64_t rest = wanted; rest != 0; rest &= rest - 1) {
      const auto c = static_cast<Index>(std::countr_zero(rest));
      bool seen_negative = false, seen_positive = false, seen_zero = false;
      for (signed char raw : m_state[c].face_raw) {
        seen_negative |= raw < 0, seen_positive |= raw == 1, seen_zero |= raw == 0;
      }
      if (seen_zero || (seen_negative && seen_positive)) wanted &= ~(std::uint64_t{1} << c);
    }
  }
  return classify_clusters(wanted);
}

RadialViewCounts RadialViewCulling::classify_clusters(std::uint64_t clusters) {
  std::vector<Index> chosen;
  for (std::uint64_t rest = clusters & m_usable; rest != 0; rest &= rest - 1) {
    chosen.push_back(static_cast<Index>(std::countr_zero(rest)));
  }
  tbb::parallel_for(std::size_t{0}, chosen.size(),
                    [&](std::size_t i) { classify_cluster(chosen[i]); });
  RadialViewCounts counts;
  counts.clusters_classified = static_cast<std::int64_t>(chosen.size());
  for (Index c : chosen) {
    const ClusterState& state = m_state[c];
    counts.clusters_used += state.counts.clusters_used;
    counts.clusters_certified += state.counts.clusters_certified;
    counts.triangles_positive += state.counts.triangles_positive;
    counts.triangles_negative += state.counts.triangles_negative;
    counts.triangles_undetermined += state.counts.triangles_undetermined;
    counts.faces_clean += state.counts.faces_clean;
    const auto& faces = m_clusters.faces(c);
    for (std::size_t i = 0; i < state.face_sign.size(); ++i) {
      if (state.face_sign[i] == FaceSign::positive_clean) {
        if (m_clean_mask.empty()) m_clean_mask.assign(m_clusters.mesh().num_faces(), 0);
        m_clean_mask[faces[i]] |= std::uint64_t{1} << c;
        m_clean_mask_dirty = true;
      }
    }
  }
  return counts;
}

void RadialViewCulling::classify_cluster(Index c) {
  ClusterState& state = m_state[c];
  const Positions& x0 = *m_x0;
  const Positions& x1 = *m_x1;
  const bool find_clean = m_find_clean;
  const TriangleMesh& mesh = m_clusters.mesh();
  const auto& faces = m_clusters.faces(c);
  const Vec3 o0 = state.observer0, o1 = state.observer1;

  // Raw signs of det(b-a, c-a, o-a) over the step (those the pairs did not need yet).
  for (Index f : faces) raw_sign(c, f);
  const std::vector<Ghost> ghosts = ghost_triangles(m_clusters.ghost_loops(c), x0, x1, o0, o1);
  const int seeing = seeing_sign(mesh, faces, state.face_raw, ghosts, x0, x1, o0, o1);
  RadialViewCounts& counts = state.counts;
  if (seeing == 0) {
    counts.triangles_undetermined += static_cast<std::int64_t>(faces.size() + ghosts.size());
    state.face_sign.assign(faces.size(), FaceSign::undetermined);
    return;
  }
  counts.clusters_used = 1;
  const auto relative = [&](signed char raw) {
    return raw == 0        ? FaceSign::undetermined
           : raw == seeing ? FaceSign::positive
                           : FaceSign::negative;
  };
  state.face_sign.resize(faces.size());
  std::vector<std::size_t> blocking;  // cluster face slots, then faces.size() + ghost index
  for (std::size_t i = 0; i < faces.size(); ++i) {
    state.face_sign[i] = relative(state.face_raw[i]);
    if (state.face_sign[i] != FaceSign::positive) blocking.push_back(i);
  }
  for (std::size_t i = 0; i < ghosts.size(); ++i) {
    if (relative(ghosts[i].raw) != FaceSign::positive) blocking.push_back(faces.size() + i);
  }
  for (std::size_t i = 0; i < faces.size() + ghosts.size(); ++i) {
    const FaceSign sign =
        i < faces.size() ? state.face_sign[i] : relative(ghosts[i - faces.size()].raw);
    ++(sign == FaceSign::positive       ? counts.triangles_positive
       : sign == FaceSign::undetermined ? counts.triangles_undetermined
                                        : counts.triangles_negative);
  }
  if (blocking.empty()) {
    counts.clusters_certified = 1;
    std::fill(state.face_sign.begin(), state.face_sign.end(), FaceSign::positive_clean);
    counts.faces_clean = static_cast<std::int64_t>(faces.size());
    return;
  }
  if (!find_clean) return;

  // View cones of the faces (from directions to the vertices, shared by the faces around
  // each vertex) and of the ghost triangles.
  if (m_local_faces[c].empty()) build_local_faces(c);
  const std::vector<Index>& vertices = m_cluster_vertices[c];
  state.unit0.resize(vertices.size());
  state.unit1.resize(vertices.size());
  state.unit_ok.resize(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    state.unit_ok[i] = unit_direction(o0, x0.row(vertices[i]), state.unit0[i]) &&
                       unit_direction(o1, x1.row(vertices[i]), state.unit1[i]);
  }
  state.cones.resize(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const auto& l = m_local_faces[c][i];
    if (!state.unit_ok[l[0]] || !state.unit_ok[l[1]] || !state.unit_ok[l[2]]) {
      state.cones[i] = {};
      continue;
    }
    const Vec3 unit[6] = {state.unit0[l[0]], state.unit0[l[1]], state.unit0[l[2]],
                          state.unit1[l[0]], state.unit1[l[1]], state.unit1[l[2]]};
    state.cones[i] = view_cone_of_directions(unit);
  }
  std::vector<ViewCone> ghost_cones(ghosts.size());
  for (std::size_t i = 0; i < ghosts.size(); ++i) {
    const auto p = ghost_corners(ghosts[i], x0, x1);
    ghost_cones[i] = swept_view_cone({p[0], p[1], p[2]}, {p[3], p[4], p[5]}, o0, o1);
  }
  find_clean_faces(c, blocking, ghost_cones);
}

void RadialViewCulling::find_clean_faces(Index c, const std::vector<std::size_t>& blocking,
                                         const std::vector<ViewCone>& ghost_cones) {
  ClusterState& state = m_state[c];
  const std::size_t num_faces = state.face_sign.size();
  const auto cone_of = [&](std::size_t i) -> const ViewCone& {
    return i < num_faces ? state.cones[i] : ghost_cones[i - num_faces];
  };
  // Blocking triangles in groups under bounding cones.
  std::vector<ViewCone> block_cones, block_groups;
  block_cones.reserve(blocking.size());
  for (std::size_t i : blocking) block_cones.push_back(cone_of(i));
  for (std::size_t i = 0; i < block_cones.size(); i += kGroup) {
    const int n = static_cast<int>(std::min<std::size_t>(kGroup, block_cones.size() - i));
    block_groups.push_back(bounding_view_cone(&block_cones[i], n));
  }
  // Positive faces in groups of consecutive faces; a face stays clean until a blocking
  // triangle may be seen in its cone.
  std::vector<ViewCone> members;
  for (std::size_t first = 0; first < num_faces; first += kGroup) {
    const std::size_t last = std::min(num_faces, first + kGroup);
    members.clear();
    for (std::size_t i = first; i < last; ++i) {
      if (state.face_sign[i] == FaceSign::positive) members.push_back(state.cones[i]);
    }
    if (members.empty()) continue;
    const ViewCone group = bounding_view_cone(members.data(), static_cast<int>(members.size()));
    std::vector<char> clean(last - first, 1);
    for (std::size_t b = 0; b < block_groups.size(); ++b) {
      if (view_cones_disjoint(group, block_groups[b])) continue;
      const std::size_t b_end = std::min(block_cones.size(), (b + 1) * kGroup);
      for (std::size_t i = first; i < last; ++i) {
        if (state.face_sign[i] != FaceSign::positive || !clean[i - first]) continue;
        if (view_cones_disjoint(state.cones[i], block_groups[b])) continue;
        for (std::size_t j = b * kGroup; j < b_end && clean[i - first]; ++j) {
          clean[i - first] = view_cones_disjoint(state.cones[i], block_cones[j]);
        }
      }
    }
    for (std::size_t i = first; i < last; ++i) {
      if (state.face_sign[i] == FaceSign::positive && clean[i - first]) {
        state.face_sign[i] = FaceSign::positive_clean;
        ++state.counts.faces_clean;
      }
    }
  }
}

namespace {

// The corners of one face at t = 0 and t = 1.
struct FaceCorners {
  Vec3 at0[3], at1[3];
};

FaceCorners face_corners(const TriangleMesh& mesh, Index f, const Positions& x0,
                         const Positions& x1) {
  FaceCorners c;
  for (int k = 0; k < 3; ++k) {
    c.at0[k] = x0.row(mesh.faces()(f, k));
    c.at1[k] = x1.row(mesh.faces()(f, k));
  }
  return c;
}

// Rule (5) of the header: some edge (a, b) of `f`, whose third vertex lies on side `side`
// of the plane through o, a, b over the step, has the three corners of `g` strictly on
// the other side over the whole step.
bool edge_plane_separates(const FaceCorners& f, int side, const FaceCorners& g, const Vec3& o0,
                          const Vec3& o1) {
  if (side == 0) return false;
  // Plain double first, relative to the observer: det(b-a, p-a, o-a) = -((a-o)×(b-o))·(p-o).
  // Its values at t = 0 and t = 1 are the end Bernstein coefficients; rounding here can
  // only keep a pair, the certificate below decides.
  Vec3 rf0[3], rg0[3];
  for (int k = 0; k < 3; ++k) {
    rf0[k] = f.at0[k] - o0;
    rg0[k] = g.at0[k] - o0;
  }
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    const Vec3 n0 = rf0[k].cross(rf0[l]);
    if (!(n0.dot(rg0[0]) * side > 0 && n0.dot(rg0[1]) * side > 0 && n0.dot(rg0[2]) * side > 0)) {
      continue;
    }
    const Vec3 n1 = (f.at1[k] - o1).cross(f.at1[l] - o1);
    bool maybe = true;
    for (int j = 0; j < 3 && maybe; ++j) maybe = n1.dot(g.at1[j] - o1) * side > 0;
    if (!maybe) continue;
    // Certified on the given doubles: det(b-a, p-a, o-a) = det(p-a, o-a, b-a), the side
    // of p of the plane through a, o, b.
    const MovingPlane plane(f.at0[k], o0, f.at0[l], f.at1[k], o1, f.at1[l]);
    bool separated = true;
    for (int j = 0; j < 3 && separated; ++j) {
      separated = static_cast<int>(plane.side(g.at0[j], g.at1[j])) == -side;
    }
    if (separated) return true;
  }
  return false;
}

}  // namespace

bool RadialViewCulling::separated_in(Index f, Index g, std::uint64_t clusters,
                                     std::uint64_t* wanted) const {
  const TriangleMesh& mesh = m_clusters.mesh();
  const FaceCorners cf = face_corners(mesh, f, *m_x0, *m_x1);
  const FaceCorners cg = face_corners(mesh, g, *m_x0, *m_x1);
  for (std::uint64_t rest = clusters; rest != 0; rest &= rest - 1) {
    const auto c = static_cast<Index>(std::countr_zero(rest));
    const ClusterState& state = m_state[c];
    const signed char raw_f = raw_sign(c, f), raw_g = raw_sign(c, g);
    if (edge_plane_separates(cf, raw_f, cg, state.observer0, state.observer1) ||
        edge_plane_separates(cg, raw_g, cf, state.observer0, state.observer1)) {
      return true;
    }
    // Without clean faces only a certified cluster (every face positive, so both raw
    // signs equal and nonzero) can still cull the pair.
    if (wanted && (m_find_clean || (raw_f != 0 && raw_f == raw_g))) {
      *wanted |= std::uint64_t{1} << c;
    }
  }
  return false;
}

bool RadialViewCulling::edge_planes_separate(Index f, Index g) {
  std::uint64_t wanted = 0;
  if (separated_in(f, g, shared_clusters(f, g), &wanted)) return true;
  std::atomic_ref<std::uint64_t> all_wanted(m_wanted);
  if ((all_wanted.load(std::memory_order_relaxed) & wanted) != wanted) {
    all_wanted.fetch_or(wanted, std::memory_order_relaxed);
  }
  return false;
}

bool RadialViewCulling::pair_culled(Index f, Index g) const {
  return classified_clean(f, g) || separated_in(f, g, shared_clusters(f, g), nullptr);
}

std::int64_t RadialViewCulling::cull(std::vector<TrianglePair>& pairs) const {
  std::vector<char> culled(pairs.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pairs.size(), 256),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        culled[i] = pair_culled(pairs[i].first, pairs[i].second);
                      }
                    });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (!culled[i]) pairs[kept++] = pairs[i];
  }
  const auto removed = static_cast<std::int64_t>(pairs.size() - kept);
  pairs.resize(kept);
  return removed;
}

}  // namespace tailor
