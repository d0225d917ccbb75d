// The field lists (TAILOR_DETECTION_SETTINGS, TAILOR_DETECTION_STATS) and the surfaces made
// from them: JSON output, docs/settings.md, the detector filling every counter. The CLI and
// Python surfaces are checked in tests/cli/test_cli_detect.cpp and
// python/tests/test_field_lists.py.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "culling/radial_view_tubes.hpp"
#include "detection/settings_table.hpp"
#include "tailor/detection/detection_config.hpp"
#include "tailor/detection/detection_stats.hpp"
#include "tailor/detection/self_collision_detector.hpp"

namespace tailor {
namespace {

// A config whose every setting differs from the default (a switch flipped, a number + 1).
DetectionConfig every_setting_changed() {
  static const DetectionConfig defaults;
  DetectionConfig config;
  for (const DetectionSetting& setting : kDetectionSettings) {
    std::visit(
        [&](auto member) {
          using T = std::remove_cvref_t<decltype(config.*member)>;
          if constexpr (std::is_same_v<T, bool>) {
            config.*member = !(defaults.*member);
          } else {
            config.*member = static_cast<T>(defaults.*member + 1);
          }
        },
        setting.member);
  }
  return config;
}

TEST(FieldLists, SettingsAreNamedOnceWithHelp) {
  std::set<std::string_view> names, cli;
  for (const DetectionSetting& s : kDetectionSettings) {
    EXPECT_TRUE(names.insert(s.name).second) << s.name << " twice";
    if (!s.cli.empty()) {
      EXPECT_TRUE(cli.insert(s.cli).second) << "--" << s.cli << " twice";
    }
    EXPECT_FALSE(s.help.empty()) << s.name;
    EXPECT_NE(s.help.back(), '.') << s.name << ": help is one line without a final period";
    EXPECT_LE(s.min, s.max) << s.name;
  }
  // A default-constructed config is the paper preset.
  EXPECT_EQ(nlohmann::json(DetectionConfig{}), nlohmann::json(DetectionConfig::preset("paper")));
}

TEST(FieldLists, ConfigJsonHasEverySetting) {
  const DetectionConfig config = every_setting_changed();
  const nlohmann::json json = config;
  EXPECT_EQ(json.size(), kDetectionSettings.size()) << json.dump();
  for (const DetectionSetting& setting : kDetectionSettings) {
    const std::string name(setting.name);
    ASSERT_TRUE(json.contains(name)) << "the JSON of DetectionConfig misses " << name;
    EXPECT_EQ(json[name].dump(), setting_value(config, setting)) << name;
    EXPECT_NE(setting_value(config, setting), setting_value(DetectionConfig{}, setting)) << name;
  }
}

TEST(FieldLists, StatsJsonAndSumHaveEveryField) {
  DetectionStats stats;
  double value = 1;
  for (const DetectionStatField& field : kDetectionStatFields) {
    std::visit([&](auto member) { stats.*member = static_cast<int>(value++); }, field.member);
  }
  DetectionStats sum = stats;
  sum += stats;
  const nlohmann::json json = stats;
  EXPECT_EQ(json.size(), kDetectionStatFields.size()) << json.dump();
  value = 1;
  for (const DetectionStatField& field : kDetectionStatFields) {
    const std::string name(field.name);
    ASSERT_TRUE(json.contains(name)) << "the JSON of DetectionStats misses " << name;
    EXPECT_EQ(json[name].get<double>(), value) << name;
    std::visit([&](auto member) { EXPECT_EQ(sum.*member, 2 * value) << "+= misses " << name; },
               field.member);
    ++value;
  }
}

// Every counter of the list is filled by the detector: summed over steps that exercise
// every stage (folding tubes with observers; classify_every_cluster fills the radial
// counts), each is positive, except the few listed here with the reason.
TEST(FieldLists, DetectorFillsEveryCounter) {
  const std::set<std::string_view> may_stay_zero = {
      "ccd_exact_fallbacks",  // only near-degenerate queries reach the exact path
  };
  DetectionConfig config;
  config.classify_every_cluster = true;
  DetectionStats sum;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const testing::TubeStep step = testing::random_folding_tube(seed);
    const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
    SelfCollisionDetector detector(mesh, step.mesh.vertices, config, step.loops);
    sum += detector.detect(step.mesh.vertices, step.x1).stats;
  }
  for (const DetectionStatField& field : kDetectionStatFields) {
    if (may_stay_zero.contains(field.name)) continue;
    std::visit(
        [&](auto member) {
          EXPECT_GT(sum.*member, 0) << field.name
                                    << " stayed 0 over steps that run every stage: is it "
                                       "filled (detection/stage_counts.cpp, the detector)?";
        },
        field.member);
  }
}

TEST(FieldLists, DocsTableIsCurrent) {
  const std::filesystem::path path =
      std::filesystem::path(TAILOR_SOURCE_DIR) / "docs" / "settings.md";
  const std::string expected = testing::settings_markdown();
  if (std::getenv("TAILOR_UPDATE_DOCS") != nullptr) {
    std::ofstream(path, std::ios::binary) << expected;
  }
  std::ifstream file(path, std::ios::binary);
  std::stringstream actual;
  actual << file.rdbuf();
  for (const DetectionSetting& s : kDetectionSettings) {
    EXPECT_NE(actual.str().find(fmt::format("| `{}` |", s.name)), std::string::npos)
        << path << " misses the setting " << s.name;
  }
  for (const DetectionStatField& f : kDetectionStatFields) {
    EXPECT_NE(actual.str().find(fmt::format("| `{}` |", f.name)), std::string::npos)
        << path << " misses the statistic " << f.name;
  }
  EXPECT_TRUE(actual.str() == expected)
      << path << " is not the table of the field lists; regenerate it:\n  "
      << testing::kSettingsDocsCommand;
}

}  // namespace
}  // namespace tailor
