/// @file
/// libFuzzer target: PLY bytes (any encoding) through parse_ply().

#include "fuzz_support.hpp"
#include "tailor/io/ply_reader.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  tailor::fuzz::set_up();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tailor;
  try {
    fuzz::check_mesh(parse_ply(fuzz::as_text(data, size), "fuzz.ply"));
  } catch (const InputError& error) {
    fuzz::check_message(error, "fuzz.ply");
  }
  return 0;
}
