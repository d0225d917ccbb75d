#pragma once
/// @file
/// Procedural meshes for tests and benchmarks: grids, tubes, spheres, a crumpling cloth.

#include "tailor/mesh/mesh_data.hpp"

namespace tailor {

/// A flat `size × size` grid in the z=0 plane with `cells × cells` quads, two triangles
/// each, consistently oriented (normals +z).
MeshData make_grid(int cells_x, int cells_y, double size_x, double size_y);

/// An open tube along +z: `rings` rings of `segments` vertices, radius and length given.
/// Two boundary loops (the end rings).
MeshData make_tube(int rings, int segments, double radius, double length);

/// A closed UV sphere with `stacks` × `slices` quads (poles are single vertices).
MeshData make_sphere(int stacks, int slices, double radius);

/// Positions of a square grid cloth crumpling over time `t` (0 = flat): a sum of folds
/// whose amplitude grows with t, so that larger t brings more self-contacts. `rest` are
/// the flat grid's positions. Deterministic.
Positions crumpling_cloth(const Positions& rest, double t);

}  // namespace tailor
