#pragma once
/// @file
/// Writes CCD queries in the reference query CSV format (query_io.hpp), exactly: every
/// coordinate becomes an integer numerator and a power-of-two denominator, so reading the
/// file back gives the same doubles bit for bit. Used to dump the queries of a detection
/// step for benchmarks and to store generated query sets.

#include <span>
#include <string>
#include <vector>

#include "tailor/ccd/ccd.hpp"

namespace tailor {

/// The queries as CSV text: 8 rows per query in the reader's row order, with the 7th
/// `truth` column (0/1) when `truth` is not empty (then it must have one entry per query,
/// else std::invalid_argument). Throws std::invalid_argument on a non-finite coordinate.
std::string ccd_queries_csv(std::span<const VertexFaceQuery> queries,
                            const std::vector<bool>& truth = {});
/// Edge-edge form of ccd_queries_csv.
std::string ccd_queries_csv(std::span<const EdgeEdgeQuery> queries,
                            const std::vector<bool>& truth = {});

/// Writes ccd_queries_csv(queries, truth) to `path` (atomically). Name the file so that
/// read_ccd_queries can tell its type (e.g. a stem ending in `vf`). Throws InputError
/// naming the path when it cannot be written.
void write_ccd_queries(const std::string& path, std::span<const VertexFaceQuery> queries,
                       const std::vector<bool>& truth = {});
/// Edge-edge form of write_ccd_queries (e.g. a stem ending in `ee`).
void write_ccd_queries(const std::string& path, std::span<const EdgeEdgeQuery> queries,
                       const std::vector<bool>& truth = {});

}  // namespace tailor
