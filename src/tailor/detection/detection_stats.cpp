#include "tailor/detection/detection_stats.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace tailor {

DetectionStats& DetectionStats::operator+=(const DetectionStats& other) {
#define TAILOR_ADD(field, ...) field += other.field;
  TAILOR_DETECTION_STATS(TAILOR_ADD, TAILOR_ADD)
#undef TAILOR_ADD
  return *this;
}

void to_json(nlohmann::json& json, const DetectionStats& stats) {
  json = nlohmann::json::object();
  for (const DetectionStatField& field : kDetectionStatFields) {
    std::visit([&](auto member) { json[std::string(field.name)] = stats.*member; }, field.member);
  }
}

}  // namespace tailor
