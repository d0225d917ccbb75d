#pragma once
/// @file
/// The sleeve's pinned vertices (its shoulder ring), kept once, in the forms the parts of
/// the simulation read: sorted ids (ClothModel), a flag per vertex (arm contact and the arm
/// projection leave them alone), their rest positions (the arm's skin carries them), and
/// masses made infinite (the strain limiter and the contact solver never move them).

#include <vector>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Pinned vertices of one mesh.
class PinnedVertices {
 public:
  PinnedVertices() = default;
  /// The vertices `ids` of a mesh of `rest.rows()` vertices at rest positions `rest`.
  /// Throws InputError on an id out of range.
  PinnedVertices(std::vector<Index> ids, const Positions& rest);

  /// The pinned vertices, sorted, without duplicates.
  const std::vector<Index>& ids() const { return m_ids; }
  /// Per vertex of the mesh: 1 when pinned.
  const std::vector<char>& flags() const { return m_flags; }
  /// Row i: the rest position of ids()[i].
  const Positions& rest() const { return m_rest; }
  /// `masses` (one per vertex) with the pinned ones infinite.
  Eigen::VectorXd with_infinite_masses(Eigen::VectorXd masses) const;

 private:
  std::vector<Index> m_ids;
  std::vector<char> m_flags;
  Positions m_rest;
};

}  // namespace tailor
