#pragma once
/// @file
/// Readers for the reference CCD query files (../shared/data/README.md).
///
/// Query CSV: 8 rows per query, each row one vertex as `x_num,x_den,y_num,y_den,z_num,z_den`
/// plus an optional 7th `truth` column (0/1, the same on the 8 rows); commas, optionally
/// followed by spaces. Numerators and denominators are integers of any length; each
/// num/den must be exactly a double (else InputError). Row order per query:
/// edge-edge `ea0_t0, ea1_t0, eb0_t0, eb1_t0, ea0_t1, ea1_t1, eb0_t1, eb1_t1`,
/// vertex-face `p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1, c_t1`.
///
/// The query type is not in the file: it comes from the path. A path with a folder named
/// `vertex-face` or `edge-edge` (the Sample-Queries layout, e.g.
/// `erleben-spikes/vertex-face/data_0_0.csv`) gives that type; otherwise a file name whose
/// stem ends in `vf` or `ee` (the cloth-funnel layout, `227vf.csv`, `227ee.csv`).

#include <optional>
#include <string>
#include <vector>

#include "tailor/ccd/ccd.hpp"

namespace tailor {

/// The two kinds of primitive pair.
enum class CcdQueryKind { vertex_face, edge_edge };

/// The queries of one file.
struct CcdQueryFile {
  std::string path;  ///< where they were read from
  CcdQueryKind kind = CcdQueryKind::vertex_face;
  std::vector<VertexFaceQuery> vertex_face;  ///< filled when kind == vertex_face
  std::vector<EdgeEdgeQuery> edge_edge;      ///< filled when kind == edge_edge
  /// Ground truth per query (from the 7th column), empty when the file has none.
  std::vector<bool> truth;

  /// Number of queries.
  std::size_t size() const {
    return kind == CcdQueryKind::vertex_face ? vertex_face.size() : edge_edge.size();
  }
};

/// The query type of a file from its path (see the file comment); nullopt when the path
/// says nothing.
std::optional<CcdQueryKind> ccd_query_kind_from_path(const std::string& path);

/// Reads a query CSV. `kind` overrides the type taken from the path. Throws InputError
/// (naming the file and line) on a malformed file, an unknown type, or a value that is not
/// exactly a double.
CcdQueryFile read_ccd_queries(const std::string& path,
                              std::optional<CcdQueryKind> kind = std::nullopt);

/// Reads a JSON array of booleans (the `mma_bool` ground truth). Throws InputError.
std::vector<bool> read_ccd_truth_json(const std::string& path);

}  // namespace tailor
