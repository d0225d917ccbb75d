/// @file
/// libFuzzer target: CCD query CSV files (both kinds; the first byte picks one).

#include "fuzz_support.hpp"
#include "tailor/ccd/query_io.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  tailor::fuzz::set_up();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tailor;
  fuzz::ByteReader input(data, size);
  const bool edge_edge = (input.byte() & 1) != 0;
  const std::string source = edge_edge ? "fuzz/edge-edge/q.csv" : "fuzz/vertex-face/q.csv";
  try {
    const CcdQueryFile file = parse_ccd_queries(input.rest(), source);
    if (file.size() == 0) fuzz::fail("file without queries accepted");
    if (!file.truth.empty() && file.truth.size() != file.size()) fuzz::fail("truth count");
    if (edge_edge != (file.kind == CcdQueryKind::edge_edge)) fuzz::fail("kind from the path");
  } catch (const InputError& error) {
    fuzz::check_message(error, source);
  }
  return 0;
}
