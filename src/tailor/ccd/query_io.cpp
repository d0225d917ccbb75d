#include "tailor/ccd/query_io.hpp"

#include <gmpxx.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tailor/geometry/error.hpp"
#include "tailor/io/excerpt.hpp"
#include "tailor/io/input_file.hpp"
#include "tailor/io/json_file.hpp"
#include "tailor/io/memory_budget.hpp"

namespace tailor {

namespace {

[[noreturn]] void fail(const std::string& path, std::size_t line, const std::string& what) {
  if (line > 0) throw InputError(fmt::format("{}:{}: {}", path, line, what));
  throw InputError(fmt::format("{}: {}", path, what));
}

std::string_view trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

bool is_integer(std::string_view s) {
  std::size_t i = (!s.empty() && (s[0] == '-' || s[0] == '+')) ? 1 : 0;
  if (i >= s.size()) return false;
  for (; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
  }
  return true;
}

/// num/den as a double, which must be exact.
double exact_ratio(std::string_view num, std::string_view den, const std::string& path,
                   std::size_t line) {
  if (!is_integer(num) || !is_integer(den)) {
    fail(path, line, fmt::format("expected integers, got '{}', '{}'", excerpt(num), excerpt(den)));
  }
  if (num.size() > kMaxCcdQueryDigits || den.size() > kMaxCcdQueryDigits) {
    fail(path, line, fmt::format("integer longer than {} digits", kMaxCcdQueryDigits));
  }
  const auto digits = [](std::string_view s) { return std::string(s[0] == '+' ? s.substr(1) : s); };
  const mpz_class n(digits(num), 10);
  const mpz_class d(digits(den), 10);
  if (d == 0) fail(path, line, "zero denominator");
  mpq_class q(n, d);
  q.canonicalize();
  const double x = q.get_d();
  if (!std::isfinite(x) || mpq_class(x) != q) {
    fail(path, line,
         fmt::format("value {}/{} is not exactly a double", excerpt(num), excerpt(den)));
  }
  return x;
}

// Splits a CSV line into its trimmed fields, at most 7; returns how many (8: more than 7).
int split_fields(std::string_view rest, std::string_view (&fields)[7]) {
  int n = 0;
  for (;;) {
    const std::size_t comma = rest.find(',');
    if (n == 7) return 8;  // too many: the count is all the message needs
    fields[n++] = trim(rest.substr(0, comma));
    if (comma == std::string_view::npos) return n;
    rest.remove_prefix(comma + 1);
  }
}

// The points read, one per row, with the row's truth (when the file has the column) and
// line number.
struct QueryRows {
  std::vector<Vec3> points;
  std::vector<int> truth;
  std::vector<std::size_t> line;
};

// Eight rows per query, into the file's queries and their truth.
void assemble_queries(const QueryRows& read, bool with_truth, const std::string& path,
                      CcdQueryFile& file) {
  const std::size_t count = read.points.size() / 8;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3* r = &read.points[8 * i];
    if (file.kind == CcdQueryKind::vertex_face) {
      file.vertex_face.push_back({r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]});
    } else {
      file.edge_edge.push_back({r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]});
    }
    if (!with_truth) continue;
    for (int k = 1; k < 8; ++k) {
      if (read.truth[8 * i + k] != read.truth[8 * i]) {
        fail(path, read.line[8 * i + k], "truth differs within one query");
      }
    }
    file.truth.push_back(read.truth[8 * i] != 0);
  }
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

CcdQueryFile parse_ccd_queries(std::string_view text, const std::string& path,
                               std::optional<CcdQueryKind> kind) {
  CcdQueryFile file;
  file.path = path;
  if (!kind) kind = ccd_query_kind_from_path(path);
  if (!kind) {
    fail(path, 0,
         "cannot tell vertex-face from edge-edge: expected a 'vertex-face'/'edge-edge' folder "
         "or a file name ending in 'vf'/'ee'");
  }
  file.kind = *kind;

  QueryRows read;
  std::vector<Vec3>& rows = read.points;
  std::vector<int>& row_truth = read.truth;
  std::vector<std::size_t>& row_line = read.line;
  int columns = -1;
  std::size_t line = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    ++line;
    // Look for the line's end only so far: a binary file is no CSV.
    const std::size_t scan = std::min(text.size() - pos, kMaxCcdQueryLineBytes + 1);
    const char* nl = static_cast<const char*>(std::memchr(text.data() + pos, '\n', scan));
    if (nl == nullptr && scan > kMaxCcdQueryLineBytes) {
      fail(path, line, fmt::format("line longer than {} bytes", kMaxCcdQueryLineBytes));
    }
    const std::size_t end = nl ? static_cast<std::size_t>(nl - text.data()) : text.size();
    std::string_view rest = text.substr(pos, end - pos);
    pos = end + 1;
    if (trim(rest).empty()) continue;
    std::string_view fields[7];
    const int n = split_fields(rest, fields);
    if (n != 6 && n != 7) {
      fail(path, line,
           fmt::format("expected 6 or 7 columns, got {}", n == 8 ? "more" : std::to_string(n)));
    }
    if (columns == -1) columns = n;
    if (n != columns) fail(path, line, "inconsistent number of columns");
    if (rows.size() == rows.capacity()) {
      // Rows, their truth and line numbers; doubled while the vectors grow.
      check_memory_budget(2.0 * static_cast<double>(rows.size() + 1) *
                              (sizeof(Vec3) + sizeof(int) + sizeof(std::size_t)),
                          fmt::format("{}:{}: reading the queries", path, line));
    }
    Vec3 x;
    for (int k = 0; k < 3; ++k) x[k] = exact_ratio(fields[2 * k], fields[2 * k + 1], path, line);
    rows.push_back(x);
    row_line.push_back(line);
    if (n == 7) {
      if (fields[6] != "0" && fields[6] != "1") fail(path, line, "truth must be 0 or 1");
      row_truth.push_back(fields[6] == "1");
    }
  }
  if (rows.empty()) fail(path, 0, "no queries (the file has no data rows)");
  if (rows.size() % 8 != 0) {
    fail(path, line,
         "the number of rows (" + std::to_string(rows.size()) + ") is not a multiple of 8");
  }
  assemble_queries(read, columns == 7, path, file);
  return file;
}

CcdQueryFile read_ccd_queries(const std::string& path, std::optional<CcdQueryKind> kind) {
  if (!kind) kind = ccd_query_kind_from_path(path);
  if (!kind) return parse_ccd_queries({}, path, kind);  // the error about the kind
  const InputFile file(path);
  return parse_ccd_queries(file.bytes(), path, kind);
}

std::vector<bool> read_ccd_truth_json(const std::string& path) {
  const nlohmann::json j = read_json_file(path);
  if (!j.is_array()) fail(path, 0, "expected a JSON array of booleans, got " + json_excerpt(j));
  std::vector<bool> truth;
  truth.reserve(j.size());
  for (std::size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_boolean()) {
      fail(path, 0, fmt::format("entry {} is not a boolean: {}", i, json_excerpt(j[i])));
    }
    truth.push_back(j[i].get<bool>());
  }
  return truth;
}

}  // namespace tailor
