#pragma once
/// @file
/// Procedural frame sequences (one topology, moving vertices) whose answer is known per frame,
/// for tests and demonstrations of sequence checking.

#include <vector>

#include "tailor/mesh/mesh_data.hpp"

namespace tailor {

/// Frames of one animated mesh plus what is known about each frame by construction.
struct ProceduralSequence {
  /// Connectivity shared by every frame.
  FaceArray faces;
  /// Vertex positions of each frame.
  std::vector<Positions> frames;
  /// Per frame: true when the frame intersects itself (by construction, see the generator).
  std::vector<bool> intersecting;
};

/// Parameters of make_falling_fold.
struct FallingFoldOptions {
  int cells_along = 40;     ///< grid cells along the strip (the direction it folds in), ≥ 8
  int cells_across = 8;     ///< grid cells across the strip, ≥ 1
  int frames = 12;          ///< frames, ≥ 2
  int piercing_frame = -1;  ///< frame whose free layer dents down through the other; -1: none
  /// Each coordinate of each vertex of each frame moves by a pseudo-random offset of at most
  /// `jitter` · h (deterministic; at most 0.01). 0 keeps the frames exactly degenerate: a
  /// bottom layer exactly in z = 0 and edges across the strip exactly parallel, which the
  /// exact CCD decides only on its slow exact path.
  double jitter = 0;
};

/// A strip of cloth falling onto itself. The strip (length 1, square cells of side
/// h = 1 / cells_along) lies along x: its first half stays flat on z = 0, its second half is
/// folded back over it around a half-cylinder of radius r (axis along y at x = 0.5, z = r);
/// the free layer lies flat at z = 2r, pointing back toward x = 0, with the strip's length
/// conserved (the folded arc takes πr of it). Over the frames r shrinks linearly from 0.15
/// to 0.75 h, so the free layer falls from a standing half-loop to 1.5 h above the bottom.
///
/// Every frame is intersection-free, except the piercing frame: the mesh is the strip's
/// profile curve (in x-z) extruded along y, so it intersects itself exactly when the
/// profile polyline does, and that polyline visits points in order around the boundary of
/// a convex region (bottom segment, arc, top segment), so it is simple. At the piercing
/// frame, the free layer is pushed down by a smooth bump centred on its middle, well inside
/// the bottom layer's extent: depth 2r + 4h over a plateau at least 8h/3 wide (so it holds
/// vertices, which lie 4h below z = 0), easing to 0 over half that width on each side. The
/// profile then crosses the bottom segment twice, and the mesh intersects itself. The steps
/// into and out of that frame carry those vertices through the bottom layer (collisions).
/// A jitter of at most 0.01 h per coordinate changes none of these answers: it moves any
/// two points by less than 0.035 h relative to each other, far less than the clearance of
/// an intersection-free frame (a sizeable fraction of h between triangles that share no
/// vertex, 1.5 h between the layers) and than the 4 h the dent reaches below the bottom.
/// The piercing frame must leave the free layer at least 8 cells long (frames in the later
/// half do); throws std::invalid_argument otherwise or on out-of-range options.
ProceduralSequence make_falling_fold(const FallingFoldOptions& options = {});

}  // namespace tailor
