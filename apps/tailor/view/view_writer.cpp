/// @file
/// The page folder of `tailor view`: data scripts and the embedded page.

#include "view/view_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "tailor/geometry/error.hpp"
#include "tailor/io/file_bytes.hpp"
#include "view/view_assets.hpp"

namespace tailor::cli {
namespace {

namespace fs = std::filesystem;

void append_le32(std::string& bytes, std::uint32_t word) {
  for (int shift = 0; shift < 32; shift += 8) bytes.push_back(static_cast<char>(word >> shift));
}

// Positions as Float32 (what WebGL draws); a coordinate beyond the float range is bad input.
std::string float32_bytes(const Positions& positions, const std::string& source) {
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(positions.size()) * 4);
  constexpr double kLargest = std::numeric_limits<float>::max();
  for (Eigen::Index v = 0; v < positions.rows(); ++v) {
    for (Eigen::Index c = 0; c < 3; ++c) {
      const double value = positions(v, c);
      if (!(std::abs(value) <= kLargest)) {
        throw InputError(fmt::format("{}: vertex {} has coordinate {} beyond the float range",
                                     source, v, value));
      }
      append_le32(bytes, std::bit_cast<std::uint32_t>(static_cast<float>(value)));
    }
  }
  return bytes;
}

std::string uint32_bytes(const Index* ids, std::size_t count) {
  std::string bytes;
  bytes.reserve(count * 4);
  for (std::size_t i = 0; i < count; ++i) append_le32(bytes, static_cast<std::uint32_t>(ids[i]));
  return bytes;
}

std::string faces_base64(const FaceArray& faces) {
  return base64_encode(uint32_bytes(faces.data(), static_cast<std::size_t>(faces.size())));
}

std::string float32_base64(const std::vector<float>& values) {
  std::string bytes;
  bytes.reserve(values.size() * 4);
  for (float value : values) append_le32(bytes, std::bit_cast<std::uint32_t>(value));
  return base64_encode(bytes);
}

// Contacts as typed arrays: millions of pairs (a 1M-triangle folded cloth has ~1.1M) stay
// compact and decode without a JSON parse of every number.
nlohmann::json contacts_json(const FrameContacts& contacts) {
  std::vector<Index> vf_ids, ee_ids;
  std::vector<float> vf_toi, ee_toi;
  for (const auto& c : contacts.vertex_face) {
    vf_ids.insert(vf_ids.end(), {c.vertex, c.face, c.substep});
    vf_toi.push_back(static_cast<float>(c.toi));
  }
  for (const auto& c : contacts.edge_edge) {
    ee_ids.insert(ee_ids.end(), {c.a0, c.a1, c.b0, c.b1, c.substep});
    ee_toi.push_back(static_cast<float>(c.toi));
  }
  nlohmann::json observers = nlohmann::json::array();
  for (const Vec3& o : contacts.observers) observers.push_back({o.x(), o.y(), o.z()});
  const auto ids = [](const std::vector<Index>& v) {
    return base64_encode(uint32_bytes(v.data(), v.size()));
  };
  return {{"candidates", ids(contacts.candidate_triangles)},
          {"candidate_count", contacts.candidate_triangles.size()},
          {"vertex_face", ids(vf_ids)},
          {"vertex_face_toi", float32_base64(vf_toi)},
          {"vertex_face_count", contacts.vertex_face.size()},
          {"edge_edge", ids(ee_ids)},
          {"edge_edge_toi", float32_base64(ee_toi)},
          {"edge_edge_count", contacts.edge_edge.size()},
          {"observers", observers},
          {"substeps", contacts.substeps}};
}

class FolderWriter {
 public:
  explicit FolderWriter(fs::path root) : m_root(std::move(root)) {}
  void write(const std::string& name, std::string_view bytes) {
    write_file_atomically(m_root / name, bytes);
    m_bytes += bytes.size();
  }
  std::uintmax_t bytes() const { return m_bytes; }

 private:
  fs::path m_root;
  std::uintmax_t m_bytes = 0;
};

}  // namespace

std::string base64_encode(std::string_view bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  const auto byte = [&](std::size_t at) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at]));
  };
  for (; i + 3 <= bytes.size(); i += 3) {
    const std::uint32_t word = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
    for (int shift = 18; shift >= 0; shift -= 6) text.push_back(kAlphabet[(word >> shift) & 63]);
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    const std::uint32_t word = byte(i) << 16 | (rest == 2 ? byte(i + 1) << 8 : 0);
    text.push_back(kAlphabet[(word >> 18) & 63]);
    text.push_back(kAlphabet[(word >> 12) & 63]);
    text.push_back(rest == 2 ? kAlphabet[(word >> 6) & 63] : '=');
    text.push_back('=');
  }
  return text;
}

ViewOutput write_view(const ViewInput& input, const fs::path& out) {
  std::error_code ec;
  fs::create_directories(out / "data", ec);
  if (ec || !fs::is_directory(out / "data")) {
    throw InputError(fmt::format("cannot create output folder '{}'{}", (out / "data").string(),
                                 ec ? ": " + ec.message() : std::string()));
  }
  fs::remove(out / "index.html", ec);

  FolderWriter folder(out);
  std::vector<bool> has_contacts;
  for (int k = 0; k < input.num_frames; ++k) {
    const ViewFrame frame = input.load_frame(k);
    const std::string source = fmt::format("{} (frame {})", input.title, k);
    nlohmann::json data = {{"cloth", base64_encode(float32_bytes(frame.cloth, source))}};
    if (frame.arm.rows() > 0) data["arm"] = base64_encode(float32_bytes(frame.arm, source));
    if (frame.contacts) data["contacts"] = contacts_json(*frame.contacts);
    has_contacts.push_back(frame.contacts.has_value());
    folder.write(fmt::format("data/frame_{:04d}.js", k),
                 fmt::format("tailorViewData.frame({}, {});\n", k, data.dump()));
  }

  nlohmann::json scene = {{"format", 1},
                          {"kind", input.kind},
                          {"title", input.title},
                          {"frames", input.num_frames},
                          {"cloth",
                           {{"vertices", input.cloth_vertices},
                            {"faces", input.cloth_faces.rows()},
                            {"indices", faces_base64(input.cloth_faces)}}},
                          {"arm", nullptr},
                          {"clusters", nullptr},
                          {"has_contacts", has_contacts},
                          {"stats", input.stats.is_null() ? nlohmann::json() : input.stats}};
  if (input.arm_vertices > 0) {
    scene["arm"] = {{"vertices", input.arm_vertices},
                    {"faces", input.arm_faces.rows()},
                    {"indices", faces_base64(input.arm_faces)}};
  }
  if (!input.cluster_of_face.empty()) {
    scene["clusters"] =
        base64_encode(uint32_bytes(input.cluster_of_face.data(), input.cluster_of_face.size()));
  }
  folder.write("data/scene.js", fmt::format("tailorViewData.scene({});\n", scene.dump()));

  const std::string script = viewer_script();
  if (script.empty()) {
    throw std::runtime_error(
        "this tailor was built without the viewer page (web/node_modules was missing): run "
        "scripts/install-deps.sh, then rebuild");
  }
  folder.write("viewer.js", script);
  folder.write("index.html", viewer_index_html());
  return {out / "index.html", input.num_frames, folder.bytes()};
}

}  // namespace tailor::cli
