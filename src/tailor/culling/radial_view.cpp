#include "tailor/culling/radial_view.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <numeric>

#include "tailor/geometry/coplanarity_sign.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

Vec3 centroid(const Positions& x, const std::vector<Index>& vertices) {
  Vec3 sum = Vec3::Zero();
  for (Index v : vertices) sum += x.row(v).transpose();
  return sum / static_cast<double>(vertices.size());
}

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

RadialViewClusters::RadialViewClusters(const TriangleMesh& mesh, const Positions& x_build,
                                       std::vector<std::vector<Index>> section_loops)
    : m_mesh(&mesh), m_section_loops(std::move(section_loops)) {
  if (m_section_loops.empty()) throw InputError("radial view needs at least one section loop");
  for (std::size_t i = 0; i < m_section_loops.size(); ++i) {
    if (m_section_loops[i].empty()) throw InputError(fmt::format("section loop {} is empty", i));
    for (Index v : m_section_loops[i]) {
      if (v < 0 || v >= mesh.num_vertices()) {
        throw InputError(fmt::format("section loop {} has vertex {} out of range [0, {})", i, v,
                                     mesh.num_vertices()));
      }
    }
  }
  std::vector<Vec3> observers;
  for (std::size_t c = 0; c < m_section_loops.size(); ++c) {
    observers.push_back(centroid(x_build, m_section_loops[c]));
  }
  // Each vertex goes to its nearest observer; a face goes to the lowest cluster among
  // its vertices. On a ring-structured tube this cuts along a ring of vertices, which
  // keeps the ghost fans closing the cut facing away from the observers (a zigzag cut
  // would put ghost triangles edge-on to them).
  std::vector<Index> vertex_cluster(static_cast<std::size_t>(mesh.num_vertices()), 0);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const Vec3 p = x_build.row(v);
    for (std::size_t c = 1; c < observers.size(); ++c) {
      if ((p - observers[c]).squaredNorm() < (p - observers[vertex_cluster[v]]).squaredNorm()) {
        vertex_cluster[v] = static_cast<Index>(c);
      }
    }
  }
  m_cluster_faces.resize(observers.size());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto v = mesh.faces().row(f);
    m_cluster_faces[std::min({vertex_cluster[v[0]], vertex_cluster[v[1]], vertex_cluster[v[2]]})]
        .push_back(f);
  }
  m_certifiable.assign(observers.size(), 0);
  m_ghost_loops.resize(observers.size());
  for (std::size_t c = 0; c < observers.size(); ++c) {
    m_certifiable[c] =
        !m_cluster_faces[c].empty() && cluster_loops(mesh, m_cluster_faces[c], m_ghost_loops[c]);
  }
}

Vec3 RadialViewClusters::observer(Index c, const Positions& x) const {
  return centroid(x, m_section_loops[c]);
}

std::vector<char> RadialViewClusters::certify(const Positions& x0, const Positions& x1,
                                              RadialViewCounts& counts) const {
  std::vector<char> certified(m_cluster_faces.size(), 0);
  for (std::size_t c = 0; c < m_cluster_faces.size(); ++c) {
    if (!m_certifiable[c]) continue;
    const Vec3 o0 = observer(static_cast<Index>(c), x0), o1 = observer(static_cast<Index>(c), x1);
    std::int64_t positive = 0, negative = 0, undetermined = 0;
    auto classify = [&](const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& a1,
                        const Vec3& b1, const Vec3& c1) {
      switch (coplanarity_sign(a0, b0, c0, o0, a1, b1, c1, o1)) {
        case StepSign::positive:
          ++positive;
          break;
        case StepSign::negative:
          ++negative;
          break;
        case StepSign::mixed:
          ++undetermined;
          break;
      }
    };
    for (Index f : m_cluster_faces[c]) {
      const auto v = m_mesh->faces().row(f);
      classify(x0.row(v[0]), x0.row(v[1]), x0.row(v[2]), x1.row(v[0]), x1.row(v[1]), x1.row(v[2]));
    }
    for (const auto& loop : m_ghost_loops[c]) {
      const Vec3 center0 = centroid(x0, loop), center1 = centroid(x1, loop);
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index u = loop[i], w = loop[(i + 1) % loop.size()];
        // The face traverses u -> w; the ghost closing it traverses w -> u.
        classify(x0.row(w), x0.row(u), center0, x1.row(w), x1.row(u), center1);
      }
    }
    counts.triangles_positive += positive;
    counts.triangles_negative += negative;
    counts.triangles_undetermined += undetermined;
    certified[c] = undetermined == 0 && (positive == 0 || negative == 0);
    counts.clusters_certified += certified[c];
  }
  return certified;
}

}  // namespace tailor
