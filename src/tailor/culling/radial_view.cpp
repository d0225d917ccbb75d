#include "tailor/culling/radial_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <numeric>

#include "tailor/geometry/coplanarity_sign.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

// Boundary loops of a face set, or false if it is not edge-manifold, consistently
// oriented, edge-connected, with each boundary vertex on one loop once.
bool cluster_loops(const TriangleMesh& mesh, const std::vector<Index>& faces,
                   std::vector<std::vector<Index>>& loops) {
  std::map<Index, std::vector<std::pair<Index, Index>>> edge_uses;  // edge -> (from, to)
  for (Index f : faces) {
    const auto edges = mesh.face_edges(f);
    for (int k = 0; k < 3; ++k) {
      edge_uses[edges[k]].push_back({mesh.faces()(f, k), mesh.faces()(f, (k + 1) % 3)});
    }
  }
  std::map<Index, Index> next;  // boundary half-edges, from -> to
  for (const auto& [edge, uses] : edge_uses) {
    if (uses.size() > 2) return false;
    if (uses.size() == 2) {
      if (uses[0].first != uses[1].second) return false;  // inconsistent orientation
    } else if (!next.emplace(uses[0].first, uses[0].second).second) {
      return false;  // a vertex on the boundary twice
    }
  }
  // Edge-connectedness of the faces (ghost fans keep each loop's faces together).
  std::map<Index, Index> face_slot;
  for (std::size_t i = 0; i < faces.size(); ++i) face_slot[faces[i]] = static_cast<Index>(i);
  std::vector<Index> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](Index i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& [edge, uses] : edge_uses) {
    const auto around = mesh.edge_faces(edge);
    Index first = -1;
    for (Index f : around) {
      auto it = face_slot.find(f);
      if (it == face_slot.end()) continue;
      if (first < 0)
        first = it->second;
      else
        parent[find(it->second)] = find(first);
    }
  }
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (find(static_cast<Index>(i)) != find(0)) return false;
  }
  loops.clear();
  while (!next.empty()) {
    std::vector<Index> loop;
    const Index start = next.begin()->first;
    Index v = start;
    do {
      loop.push_back(v);
      auto it = next.find(v);
      if (it == next.end()) return false;  // open chain
      v = it->second;
      next.erase(it);
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
