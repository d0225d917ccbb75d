#include "tailor/ccd/query_io.hpp"

#include <gmpxx.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tailor/geometry/error.hpp"

namespace tailor {

namespace {

[[noreturn]] void fail(const std::string& path, std::size_t line, const std::string& what) {
  std::ostringstream s;
  s << path;
  if (line > 0) s << ":" << line;
  s << ": " << what;
  throw InputError(s.str());
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

bool is_integer(const std::string& s) {
  std::size_t i = (!s.empty() && (s[0] == '-' || s[0] == '+')) ? 1 : 0;
  if (i >= s.size()) return false;
  for (; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
  }
  return true;
}

/// num/den as a double, which must be exact.
double exact_ratio(const std::string& num, const std::string& den, const std::string& path,
                   std::size_t line) {
  if (!is_integer(num) || !is_integer(den))
    fail(path, line, "expected integers, got '" + num + "', '" + den + "'");
  const mpz_class n(num[0] == '+' ? num.substr(1) : num, 10);
  const mpz_class d(den[0] == '+' ? den.substr(1) : den, 10);
  if (d == 0) fail(path, line, "zero denominator");
  mpq_class q(n, d);
  q.canonicalize();
  const double x = q.get_d();
  if (!std::isfinite(x) || mpq_class(x) != q) {
    fail(path, line, "value " + num + "/" + den + " is not exactly a double");
  }
  return x;
}

}  // namespace

std::optional<CcdQueryKind> ccd_query_kind_from_path(const std::string& path) {
  const std::filesystem::path p(path);
  for (const auto& part : p.parent_path()) {
    if (part == "vertex-face") return CcdQueryKind::vertex_face;
    if (part == "edge-edge") return CcdQueryKind::edge_edge;
  }
  const std::string stem = p.stem().string();
  auto ends_with = [&](const char* suffix) {
    const std::string s(suffix);
    return stem.size() >= s.size() && stem.compare(stem.size() - s.size(), s.size(), s) == 0;
  };
  if (ends_with("vf")) return CcdQueryKind::vertex_face;
  if (ends_with("ee")) return CcdQueryKind::edge_edge;
  return std::nullopt;
}

CcdQueryFile read_ccd_queries(const std::string& path, std::optional<CcdQueryKind> kind) {
  CcdQueryFile file;
  file.path = path;
  if (!kind) kind = ccd_query_kind_from_path(path);
  if (!kind) {
    fail(path, 0,
         "cannot tell vertex-face from edge-edge: expected a 'vertex-face'/'edge-edge' folder "
         "or a file name ending in 'vf'/'ee'");
  }
  file.kind = *kind;
  std::ifstream in(path);
  if (!in) fail(path, 0, "cannot open file");

  std::vector<Vec3> rows;
  std::vector<int> row_truth;
  std::vector<std::size_t> row_line;
  int columns = -1;
  std::string text;
  std::size_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    if (trim(text).empty()) continue;
    std::vector<std::string> fields;
    std::stringstream ss(text);
    std::string field;
    while (std::getline(ss, field, ',')) fields.push_back(trim(field));
    const int n = static_cast<int>(fields.size());
    if (n != 6 && n != 7) fail(path, line, "expected 6 or 7 columns, got " + std::to_string(n));
    if (columns == -1) columns = n;
    if (n != columns) fail(path, line, "inconsistent number of columns");
    Vec3 x;
    for (int k = 0; k < 3; ++k) x[k] = exact_ratio(fields[2 * k], fields[2 * k + 1], path, line);
    rows.push_back(x);
    row_line.push_back(line);
    if (n == 7) {
      if (fields[6] != "0" && fields[6] != "1") fail(path, line, "truth must be 0 or 1");
      row_truth.push_back(fields[6] == "1");
    }
  }
  if (rows.size() % 8 != 0) {
    fail(path, line,
         "the number of rows (" + std::to_string(rows.size()) + ") is not a multiple of 8");
  }
  const std::size_t count = rows.size() / 8;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3* r = &rows[8 * i];
    if (file.kind == CcdQueryKind::vertex_face) {
      file.vertex_face.push_back({r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]});
    } else {
      file.edge_edge.push_back({r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]});
    }
    if (columns == 7) {
      for (int k = 1; k < 8; ++k) {
        if (row_truth[8 * i + k] != row_truth[8 * i]) {
          fail(path, row_line[8 * i + k], "truth differs within one query");
        }
      }
      file.truth.push_back(row_truth[8 * i] != 0);
    }
  }
  return file;
}

std::vector<bool> read_ccd_truth_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail(path, 0, "cannot open file");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    fail(path, 0, std::string("invalid JSON: ") + e.what());
  }
  if (!j.is_array()) fail(path, 0, "expected a JSON array of booleans");
  std::vector<bool> truth;
  for (std::size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_boolean()) fail(path, 0, "entry " + std::to_string(i) + " is not a boolean");
    truth.push_back(j[i].get<bool>());
  }
  return truth;
}

}  // namespace tailor
