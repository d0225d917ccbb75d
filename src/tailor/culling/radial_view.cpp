#include "tailor/culling/radial_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "tailor/geometry/coplanarity_sign.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

// Boundary loops of a face set, or false if it is not edge-manifold, consistently
// oriented, edge-connected, with each boundary vertex on one loop once. Sorted arrays, not
// maps: a sleeve cluster holds hundreds of thousands of faces.
bool cluster_loops(const TriangleMesh& mesh, const std::vector<Index>& faces,
                   std::vector<std::vector<Index>>& loops) {
  struct Use {
    Index edge, from, to, slot;  // a face's directed edge, and the face's slot in `faces`
  };
  std::vector<Use> uses;
  uses.reserve(3 * faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Index f = faces[i];
    const auto edges = mesh.face_edges(f);
    for (int k = 0; k < 3; ++k) {
      uses.push_back(
          {edges[k], mesh.faces()(f, k), mesh.faces()(f, (k + 1) % 3), static_cast<Index>(i)});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) {
    return a.edge != b.edge ? a.edge < b.edge : a.slot < b.slot;
  });
  // Each edge used once (boundary) or twice in opposite directions; faces sharing an edge
  // are joined (edge-connectedness: ghost fans keep each loop's faces together).
  std::vector<std::pair<Index, Index>> boundary;  // half-edges (from, to)
  std::vector<Index> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](Index i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t end = i + 1;
    while (end < uses.size() && uses[end].edge == uses[i].edge) ++end;
    if (end - i > 2) return false;
    if (end - i == 2) {
      if (uses[i].from != uses[i + 1].to) return false;  // inconsistent orientation
      parent[find(uses[i + 1].slot)] = find(uses[i].slot);
    } else {
      boundary.push_back({uses[i].from, uses[i].to});
    }
    i = end;
  }
  uses = {};
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (find(static_cast<Index>(i)) != find(0)) return false;
  }
  std::sort(boundary.begin(), boundary.end());
  for (std::size_t i = 1; i < boundary.size(); ++i) {
    if (boundary[i].first == boundary[i - 1].first) return false;  // a vertex on it twice
  }
  // Loops in order of their smallest vertex, each starting there.
  loops.clear();
  std::vector<char> used(boundary.size(), 0);
  for (std::size_t first = 0; first < boundary.size(); ++first) {
    if (used[first]) continue;
    std::vector<Index> loop;
    const Index start = boundary[first].first;
    Index v = start;
    do {
      loop.push_back(v);
      const auto it = std::lower_bound(boundary.begin(), boundary.end(), std::pair{v, Index{-1}});
      if (it == boundary.end() || it->first != v) return false;  // open chain
      const auto k = static_cast<std::size_t>(it - boundary.begin());
      if (used[k]) return false;
      used[k] = 1;
      v = it->second;
    } while (v != start);
    loops.push_back(std::move(loop));
  }
  return true;
}

}  // namespace

Vec3 loop_centroid(const Positions& x, const std::vector<Index>& vertices) {
  Vec3 sum = Vec3::Zero();
  for (Index v : vertices) sum += x.row(v).transpose();
  return sum / static_cast<double>(vertices.size());
}

RadialViewClusters::RadialViewClusters(const TriangleMesh& mesh, const Positions& x_build,
                                       std::vector<std::vector<Index>> section_loops)
    : m_mesh(&mesh), m_section_loops(std::move(section_loops)) {
  if (m_section_loops.empty()) throw InputError("radial view needs at least one section loop");
  if (m_section_loops.size() > static_cast<std::size_t>(kMaxObservers)) {
    throw InputError(fmt::format("radial view takes at most {} section loops, got {}",
                                 kMaxObservers, m_section_loops.size()));
  }
  for (std::size_t i = 0; i < m_section_loops.size(); ++i) {
    if (m_section_loops[i].empty()) throw InputError(fmt::format("section loop {} is empty", i));
    for (Index v : m_section_loops[i]) {
      if (v < 0 || v >= mesh.num_vertices()) {
        throw InputError(fmt::format("section loop {} has vertex {} out of range [0, {})", i, v,
                                     mesh.num_vertices()));
      }
    }
  }
  const std::size_t num_observers = m_section_loops.size();
  std::vector<Vec3> observers;
  for (const auto& loop : m_section_loops) observers.push_back(loop_centroid(x_build, loop));
  // Each vertex is watched by its kWatchers nearest observers (ties to the lower index).
  // On a ring-structured tube this cuts along rings of vertices, which keeps the ghost
  // fans closing the cuts facing away from the observers.
  std::vector<std::uint64_t> watched(static_cast<std::size_t>(mesh.num_vertices()), 0);
  std::vector<std::pair<double, std::size_t>> by_distance(num_observers);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const Vec3 p = x_build.row(v);
    for (std::size_t c = 0; c < num_observers; ++c) {
      by_distance[c] = {(p - observers[c]).squaredNorm(), c};
    }
    const std::size_t watchers = std::min<std::size_t>(kWatchers, num_observers);
    std::partial_sort(by_distance.begin(),
                      by_distance.begin() + static_cast<std::ptrdiff_t>(watchers),
                      by_distance.end());
    for (std::size_t i = 0; i < watchers; ++i) {
      watched[v] |= std::uint64_t{1} << by_distance[i].second;
    }
  }
  m_cluster_faces.resize(num_observers);
  m_member_mask.assign(static_cast<std::size_t>(mesh.num_faces()), 0);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto v = mesh.faces().row(f);
    m_member_mask[f] = watched[v[0]] & watched[v[1]] & watched[v[2]];
    for (std::size_t c = 0; c < num_observers; ++c) {
      if ((m_member_mask[f] >> c) & 1) m_cluster_faces[c].push_back(f);
    }
  }
  m_usable.assign(num_observers, 0);
  m_ghost_loops.resize(num_observers);
  for (std::size_t c = 0; c < num_observers; ++c) {
    m_usable[c] =
        !m_cluster_faces[c].empty() && cluster_loops(mesh, m_cluster_faces[c], m_ghost_loops[c]);
    if (!m_usable[c]) {
      // Never used: drop the cluster from the faces' masks.
      for (Index f : m_cluster_faces[c]) m_member_mask[f] &= ~(std::uint64_t{1} << c);
    }
  }
}

Vec3 RadialViewClusters::observer(Index c, const Positions& x) const {
  return loop_centroid(x, m_section_loops[c]);
}

}  // namespace tailor
