/// @file
/// libFuzzer target: radial-view observer files. The first byte sets the mesh's vertex
/// count (0-255); the rest is the file.

#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "tailor/io/json_file.hpp"
#include "tailor/io/observer_loops.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  tailor::fuzz::set_up();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tailor;
  fuzz::ByteReader input(data, size);
  const Index num_vertices = input.byte();
  const std::string source = "fuzz-observers.json";
  try {
    const nlohmann::json json = parse_json_text(input.rest(), source);
    const auto loops = parse_observer_loops(json, source, num_vertices);
    if (loops.empty()) fuzz::fail("no loop accepted");
    for (const auto& loop : loops) {
      if (loop.empty()) fuzz::fail("empty loop accepted");
      for (const Index v : loop) {
        if (v < 0 || v >= num_vertices) fuzz::fail("vertex id out of range accepted");
      }
    }
  } catch (const InputError& error) {
    fuzz::check_message(error, source);
  }
  return 0;
}
