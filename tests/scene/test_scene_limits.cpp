/// @file
/// Scene files and resolutions that would exhaust the stack or the memory: refused with
/// an InputError naming the file (or the resolution), never a crash.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/scoped_memory_budget.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/scene/scene.hpp"

namespace tailor {
namespace {

namespace fs = std::filesystem;

/// The InputError message of loading a scene file holding `text` ("" if none was thrown).
std::string limit_error(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "tailor_test_scene_limits";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  try {
    load_scene_config(path);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << name << ": no InputError";
  return "";
}

void expect_contains(const std::string& message, std::initializer_list<const char*> parts) {
  for (const char* part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << message << "\nlacks: " << part;
  }
}

TEST(SceneLimits, DeeplyNestedValueIsAnInputError) {
  // Used to overflow the stack: the error path dumped the whole value.
  const std::string deep = std::string(100'000, '[') + std::string(100'000, ']');
  const std::string message = limit_error("deep.json", R"({"arm": )" + deep + "}");
  expect_contains(message, {"deep.json", "nested deeper"});
  EXPECT_LT(message.size(), 200u);
}

TEST(SceneLimits, WrongTypeQuotesAShortExcerpt) {
  // Within the nesting limit, but wide: the message quotes ~40 bytes of it.
  std::string wide = "[";
  for (int i = 0; i < 100'000; ++i) wide += "1,";
  wide += "1]";
  const std::string message = limit_error("wide.json", R"({"arm": )" + wide + "}");
  expect_contains(message, {"wide.json", "'arm' must be an object", "[1, 1, 1"});
  EXPECT_LT(message.size(), 200u);
}

TEST(SceneLimits, NumberOverflowIsAnInputError) {
  // Used to escape as nlohmann::json::out_of_range, naming no file.
  expect_contains(limit_error("overflow.json", R"({"gravity": [0, 1e400, 0]})"),
                  {"overflow.json", "1e400"});
}

TEST(SceneLimits, HugeSleeveIsRefusedByTheMemoryBudget) {
  // 16384 × 16384 passed the old 2^28-vertex cap and took over 4 GB in seconds.
  expect_contains(limit_error("sleeve.json", R"({"sleeve": {"rings": 16384, "segments": 16384}})"),
                  {"sleeve.json", "16384 × 16384", "memory budget of 4.0 GiB"});
  const Arm arm;
  SleeveParams params;
  params.rings = 16384;
  params.segments = 16384;
  EXPECT_THROW(make_sleeve(arm, params), InputError);  // CLI overrides bypass the file
}

TEST(SceneLimits, HugeArmIsRefusedByTheMemoryBudget) {
  // The arm's resolution had no cap at all (and 100000 × 100000 overflows Index).
  expect_contains(limit_error("arm.json", R"({"arm": {"rings": 100000, "segments": 100000}})"),
                  {"arm.json", "memory budget"});
  ArmParams params;
  params.cap_rings = 10000;
  params.segments = 100000;
  EXPECT_THROW(Arm{params}, InputError);
  // Whatever the budget, the vertex count stays within 32-bit ids.
  const test::ScopedMemoryBudget petabyte(std::uint64_t{1} << 50);
  params.rings = 100000;
  EXPECT_THROW(Arm{params}, InputError);
}

TEST(SceneLimits, TheBudgetDecides) {
  const SceneConfig defaults;
  const double needed = sleeve_memory_estimate(defaults.sleeve) + arm_memory_estimate(defaults.arm);
  EXPECT_GT(needed, 1e6);  // the estimate is not vacuous: the default scene needs some MB
  {
    const test::ScopedMemoryBudget budget(static_cast<std::uint64_t>(needed / 2));
    EXPECT_THROW(Scene{defaults}, InputError);
    EXPECT_THROW(parse_scene_config(nlohmann::json::object(), "x.json"), InputError);
  }
  EXPECT_NO_THROW(Scene{defaults});
}

}  // namespace
}  // namespace tailor
