/// @file
/// libFuzzer target: OBJ text through parse_obj().

#include "fuzz_support.hpp"
#include "tailor/io/obj_io.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  tailor::fuzz::set_up();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tailor;
  try {
    fuzz::check_mesh(parse_obj(fuzz::as_text(data, size), "fuzz.obj"));
  } catch (const InputError& error) {
    fuzz::check_message(error, "fuzz.obj");
  }
  return 0;
}
