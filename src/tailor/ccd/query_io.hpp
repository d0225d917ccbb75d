#pragma once
/// @file
/// Readers for the reference CCD query files (../shared/data/README.md).
///
/// Query CSV: 8 rows per query, each row one vertex as `x_num,x_den,y_num,y_den,z_num,z_den`
/// plus an optional 7th `truth` column (0/1, the same on the 8 rows); commas, optionally
/// followed by spaces; blank lines are skipped; at least one query. Numerators and
/// denominators are integers of up to 1000 characters (a double in lowest terms needs
/// at most 325 digits: 2^1074 as the denominator); each num/den must be exactly a double (else
/// InputError). Lines are at most 16 KiB; the file is mapped, not read into memory
/// (io/input_file.hpp). Row order per query: edge-edge `ea0_t0, ea1_t0, eb0_t0, eb1_t0, ea0_t1,
/// ea1_t1, eb0_t1, eb1_t1`, vertex-face `p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1, c_t1`.
///
/// The query type is not in the file: it comes from the path. A path with a folder named
/// `vertex-face` or `edge-edge` (the Sample-Queries layout, e.g.
/// `erleben-spikes/vertex-face/data_0_0.csv`) gives that type; otherwise a file name whose
/// stem ends in `vf` or `ee` (the cloth-funnel layout, `227vf.csv`, `227ee.csv`).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tailor/ccd/ccd.hpp"

namespace tailor {

/// Longest integer (in characters, sign included) accepted in a query CSV.
inline constexpr std::size_t kMaxCcdQueryDigits = 1000;
/// Longest line accepted in a query CSV.
inline constexpr std::size_t kMaxCcdQueryLineBytes = std::size_t{16} << 10;

/// The two kinds of primitive pair.
enum class CcdQueryKind { vertex_face, edge_edge };

/// The queries of one file.
struct CcdQueryFile {
  std::string path;                               ///< where they were read from
  CcdQueryKind kind = CcdQueryKind::vertex_face;  ///< which of the two lists is filled
  std::vector<VertexFaceQuery> vertex_face;       ///< filled when kind == vertex_face
  std::vector<EdgeEdgeQuery> edge_edge;           ///< filled when kind == edge_edge
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
/// (naming the file and line) on a malformed or empty file, an unknown type, a value that
/// is not exactly a double, or more rows than the memory budget allows.
CcdQueryFile read_ccd_queries(const std::string& path,
                              std::optional<CcdQueryKind> kind = std::nullopt);

/// Parses query CSV text already in memory as read_ccd_queries() does; `path` names it
/// in errors (and gives the type when `kind` does not).
CcdQueryFile parse_ccd_queries(std::string_view text, const std::string& path,
                               std::optional<CcdQueryKind> kind = std::nullopt);

/// Reads a JSON array of booleans (the `mma_bool` ground truth). Throws InputError naming
/// the file on any problem (json_file.hpp).
std::vector<bool> read_ccd_truth_json(const std::string& path);

}  // namespace tailor
