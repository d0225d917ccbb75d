/// @file
/// libFuzzer target: scene files. Every input is an InputError naming the file or a
/// configuration that survives a round trip through JSON and builds a Scene.

#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "tailor/io/json_file.hpp"
#include "tailor/scene/scene.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  tailor::fuzz::set_up();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tailor;
  const std::string source = "fuzz-scene.json";
  SceneConfig config;
  try {
    const nlohmann::json json = parse_json_text(fuzz::as_text(data, size), source);
    config = with_json_errors(source, [&] { return parse_scene_config(json, source); });
  } catch (const InputError& error) {
    fuzz::check_message(error, source);
    return 0;
  }
  const nlohmann::json written = scene_config_to_json(config);
  const SceneConfig back = parse_scene_config(written, "round-trip");  // must not throw
  if (scene_config_to_json(back) != written) {
    fuzz::fail("scene changed in a JSON round trip: " + written.dump());
  }
  // A configuration the reader accepts must build (small ones only: building costs time).
  if (sleeve_memory_estimate(config.sleeve) + arm_memory_estimate(config.arm) < 24e6) {
    try {
      const Scene scene(config);
    } catch (const InputError& error) {
      fuzz::fail(std::string("accepted scene does not build: ") + error.what());
    }
  }
  return 0;
}
