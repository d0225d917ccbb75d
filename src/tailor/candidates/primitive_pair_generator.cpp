#include "tailor/candidates/primitive_pair_generator.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "tailor/geometry/coplanarity_sign.hpp"

namespace tailor {
namespace {

struct ThreadOutput {
  std::vector<VertexFacePair> vertex_face;
  std::vector<EdgeEdgePair> edge_edge;
  LowLevelCounts counts;
};

bool face_has_vertex(const FaceArray& faces, Index f, Index v) {
  return faces(f, 0) == v || faces(f, 1) == v || faces(f, 2) == v;
}

bool edges_share_vertex(const EdgeArray& edges, Index e1, Index e2) {
  return edges(e1, 0) == edges(e2, 0) || edges(e1, 0) == edges(e2, 1) ||
         edges(e1, 1) == edges(e2, 0) || edges(e1, 1) == edges(e2, 1);
}

class StepContext {
 public:
  StepContext(const TriangleMesh& mesh, const FeatureAssignment& assignment,
              const std::vector<Aabb>& edge_boxes, const std::vector<Aabb>& face_boxes,
              const Positions& x0, const Positions& x1, const LowLevelOptions& options)
      : m_faces(mesh.faces()),
        m_edges(mesh.edges()),
        m_assignment(assignment),
        m_edge_boxes(edge_boxes),
        m_face_boxes(face_boxes),
        m_x0(x0),
        m_x1(x1),
        m_options(options) {}

  // Stages 2 and 3 for one VF pair.
  void offer_vertex_face(Index v, Index f, ThreadOutput& out) const {
    ++out.counts.vf_generated;
    if (m_options.primitive_boxes &&
        !swept_box(m_x0, m_x1, {v}).overlaps(m_face_boxes[static_cast<std::size_t>(f)])) {
      return;
    }
    ++out.counts.vf_after_boxes;
    const Index a = m_faces(f, 0), b = m_faces(f, 1), c = m_faces(f, 2);
    if (m_options.coplanarity_filter &&
        !may_become_coplanar(m_x0.row(a), m_x0.row(b), m_x0.row(c), m_x0.row(v), m_x1.row(a),
                             m_x1.row(b), m_x1.row(c), m_x1.row(v))) {
      return;
    }
    ++out.counts.vf_after_filter;
    out.vertex_face.push_back({v, f});
  }

  // Stages 2 and 3 for one EE pair, e1 < e2.
  void offer_edge_edge(Index e1, Index e2, ThreadOutput& out) const {
    ++out.counts.ee_generated;
    if (m_options.primitive_boxes && !m_edge_boxes[static_cast<std::size_t>(e1)].overlaps(
                                         m_edge_boxes[static_cast<std::size_t>(e2)])) {
      return;
    }
    ++out.counts.ee_after_boxes;
    const Index a = m_edges(e1, 0), b = m_edges(e1, 1), c = m_edges(e2, 0), d = m_edges(e2, 1);
    if (m_options.coplanarity_filter &&
        !may_become_coplanar(m_x0.row(a), m_x0.row(b), m_x0.row(c), m_x0.row(d), m_x1.row(a),
                             m_x1.row(b), m_x1.row(c), m_x1.row(d))) {
      return;
    }
    ++out.counts.ee_after_filter;
    out.edge_edge.push_back({e1, e2});
  }

  // Stage 1: the feature pairs a CTP (f, g) owes.
  void expand(const TriangleMesh& mesh, Index f, Index g, ThreadOutput& out) const {
    const bool assigned = m_options.feature_assignment;
    const bool adjacency = m_options.adjacency_culling;
    for (const auto& [from, to] : {std::pair{f, g}, std::pair{g, f}}) {
      for (int k = 0; k < 3; ++k) {
        const Index v = m_faces(from, k);
        if (face_has_vertex(m_faces, to, v)) continue;
        if (assigned && m_assignment.vf_representative(v, to, adjacency) != from) continue;
        offer_vertex_face(v, to, out);
      }
    }
    const auto edges_f = mesh.face_edges(f), edges_g = mesh.face_edges(g);
    for (Index ef : edges_f) {
      for (Index eg : edges_g) {
        if (edges_share_vertex(m_edges, ef, eg)) continue;
        const Index lo = std::min(ef, eg), hi = std::max(ef, eg);
        if (assigned) {
          const auto rep = m_assignment.ee_representative(lo, hi, adjacency);
          const auto expected = ef < eg ? std::pair{f, g} : std::pair{g, f};
          if (rep != expected) continue;
        }
        offer_edge_edge(lo, hi, out);
      }
    }
  }

 private:
  const FaceArray& m_faces;
  const EdgeArray& m_edges;
  const FeatureAssignment& m_assignment;
  const std::vector<Aabb>& m_edge_boxes;
  const std::vector<Aabb>& m_face_boxes;
  const Positions& m_x0;
  const Positions& m_x1;
  const LowLevelOptions& m_options;
};

}  // namespace

LowLevelCounts& LowLevelCounts::operator+=(const LowLevelCounts& other) {
  vf_generated += other.vf_generated;
  ee_generated += other.ee_generated;
  vf_after_boxes += other.vf_after_boxes;
  ee_after_boxes += other.ee_after_boxes;
  vf_after_filter += other.vf_after_filter;
  ee_after_filter += other.ee_after_filter;
  return *this;
}

PrimitivePairGenerator::PrimitivePairGenerator(const TriangleMesh& mesh)
    : m_mesh(&mesh), m_assignment(mesh) {}

void PrimitivePairGenerator::generate(std::span<const TrianglePair> ctps,
                                      const IsolatedSet& isolated, const Positions& x0,
                                      const Positions& x1, const LowLevelOptions& options,
                                      std::vector<VertexFacePair>& vertex_face,
                                      std::vector<EdgeEdgePair>& edge_edge,
                                      LowLevelCounts& counts) {
  vertex_face.clear();
  edge_edge.clear();
  const TriangleMesh& mesh = *m_mesh;
  if (options.primitive_boxes) {
    m_edge_boxes.resize(static_cast<std::size_t>(mesh.num_edges()));
    m_face_boxes.resize(static_cast<std::size_t>(mesh.num_faces()));
    tbb::parallel_for(tbb::blocked_range<Index>(0, mesh.num_edges(), 4096), [&](const auto& r) {
      for (Index e = r.begin(); e < r.end(); ++e) {
        m_edge_boxes[e] = swept_box(x0, x1, {mesh.edges()(e, 0), mesh.edges()(e, 1)});
      }
    });
    tbb::parallel_for(tbb::blocked_range<Index>(0, mesh.num_faces(), 4096), [&](const auto& r) {
      for (Index f = r.begin(); f < r.end(); ++f) {
        const auto v = mesh.faces().row(f);
        m_face_boxes[f] = swept_box(x0, x1, {v[0], v[1], v[2]});
      }
    });
  }
  const StepContext context(mesh, m_assignment, m_edge_boxes, m_face_boxes, x0, x1, options);
  tbb::enumerable_thread_specific<ThreadOutput> outputs;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ctps.size(), 256), [&](const auto& r) {
    ThreadOutput& out = outputs.local();
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      context.expand(mesh, ctps[i].first, ctps[i].second, out);
    }
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, isolated.vertex_face.size(), 1024),
                    [&](const auto& r) {
                      ThreadOutput& out = outputs.local();
                      for (std::size_t i = r.begin(); i < r.end(); ++i) {
                        context.offer_vertex_face(isolated.vertex_face[i].vertex,
                                                  isolated.vertex_face[i].face, out);
                      }
                    });
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, isolated.edge_edge.size(), 1024), [&](const auto& r) {
        ThreadOutput& out = outputs.local();
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
          context.offer_edge_edge(isolated.edge_edge[i].edge_a, isolated.edge_edge[i].edge_b, out);
        }
      });
  for (ThreadOutput& out : outputs) {
    vertex_face.insert(vertex_face.end(), out.vertex_face.begin(), out.vertex_face.end());
    edge_edge.insert(edge_edge.end(), out.edge_edge.begin(), out.edge_edge.end());
    counts += out.counts;
  }
}

}  // namespace tailor
