/// @file
/// The external reference meshes load with the documented counts and edge order.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tailor/io/mesh_io.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {
namespace {

const std::filesystem::path kData = TAILOR_DATA_DIR;

TEST(ReferenceData, ClothFunnelFrames) {
  const MeshData a = read_mesh(kData / "cloth-funnel/frames/227.ply");
  const MeshData b = read_mesh(kData / "cloth-funnel/frames/228.ply");
  EXPECT_EQ(a.vertices.rows(), 9450);
  EXPECT_EQ(a.faces.rows(), 18484);
  EXPECT_EQ(b.vertices.rows(), 9450);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.vertices.colwise().minCoeff(), Eigen::RowVector3d(-1.25, -1.25, -2.0));
  const TriangleMesh mesh(9450, a.faces);
  EXPECT_TRUE(mesh.validation().unreferenced_vertices.empty());
}

TEST(ReferenceData, EdgeOrderMatchesTheBoxIds) {
  // Ids count vertices, then edges (sorted by (b, a)), then faces; listed pairs never
  // share a vertex, which fails quickly if our edge numbering differs from the data's.
  const MeshData a = read_mesh(kData / "cloth-funnel/frames/227.ply");
  const TriangleMesh mesh(static_cast<Index>(a.vertices.rows()), a.faces);
  const Index nv = mesh.num_vertices(), ne = mesh.num_edges();
  std::ifstream ee_file(kData / "cloth-funnel/boxes/227ee.json");
  const auto ee = nlohmann::json::parse(ee_file);
  ASSERT_GT(ee.size(), 100u);
  for (const auto& pair : ee) {
    const Index e0 = pair[0].get<Index>() - nv, e1 = pair[1].get<Index>() - nv;
    ASSERT_GE(e0, 0);
    ASSERT_LT(e1, ne);
    const auto ea = mesh.edges().row(e0), eb = mesh.edges().row(e1);
    EXPECT_FALSE(ea(0) == eb(0) || ea(0) == eb(1) || ea(1) == eb(0) || ea(1) == eb(1))
        << "edges " << e0 << " and " << e1 << " share a vertex";
  }
  std::ifstream vf_file(kData / "cloth-funnel/boxes/227vf.json");
  const auto vf = nlohmann::json::parse(vf_file);
  for (const auto& pair : vf) {
    const Index v = pair[0].get<Index>(), f = pair[1].get<Index>() - nv - ne;
    ASSERT_GE(f, 0);
    ASSERT_LT(f, mesh.num_faces());
    EXPECT_FALSE(a.faces(f, 0) == v || a.faces(f, 1) == v || a.faces(f, 2) == v);
  }
}

TEST(ReferenceData, ThickCloth) {
  for (const char* name : {"t0.ply", "t1.ply"}) {
    SCOPED_TRACE(name);
    const MeshData m = read_mesh(kData / "thick-cloth" / name);
    EXPECT_EQ(m.vertices.rows(), 233);
    EXPECT_EQ(m.faces.rows(), 404);
    const TriangleMesh mesh(233, m.faces);
    EXPECT_TRUE(mesh.validation().is_manifold());
  }
}

}  // namespace
}  // namespace tailor
