/// @file
/// `tailor ccd-check FILE... [--truth FILE.json]...`: runs the exact CCD on every query of
/// reference query files and compares with the ground truth; reports the cost per query
/// overall and per tier. Exit code 1 on any false negative.

#include <fmt/format.h>

#include <array>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "tailor/ccd/ccd.hpp"
#include "tailor/ccd/query_io.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor::cli {
namespace {

/// Minimum CPU time of one timing: small files are run several times over, so the
/// figure is not a cold-cache first pass.
constexpr double kMinSeconds = 0.05;

struct Tally {
  std::size_t queries = 0, colliding = 0, fn = 0, fp = 0;
  std::array<std::size_t, kCcdPathCount> by_path{};
  // CPU seconds per query: all queries, and the queries each tier decided (timed alone).
  double seconds = 0.0;
  std::array<double, kCcdPathCount> tier_seconds{};

  void add(const Tally& o) {
    queries += o.queries;
    colliding += o.colliding;
    fn += o.fn;
    fp += o.fp;
    seconds += o.seconds;
    for (int i = 0; i < kCcdPathCount; ++i) {
      by_path[i] += o.by_path[i];
      tier_seconds[i] += o.tier_seconds[i];
    }
  }

  std::string describe() const {
    auto ns = [](double s, std::size_t n) { return n ? s * 1e9 / static_cast<double>(n) : 0.0; };
    std::string line = fmt::format("queries={} colliding={} fn={} fp={} ns/query={:.0f}", queries,
                                   colliding, fn, fp, ns(seconds, queries));
    for (int i = 0; i < kCcdPathCount; ++i) {
      line += fmt::format(" {}={}", ccd_path_name(static_cast<CcdPath>(i)), by_path[i]);
    }
    line += "\n  per tier:";
    for (int i = 0; i < kCcdPathCount; ++i) {
      if (by_path[i] == 0) continue;
      line += fmt::format(" {} {:.0f} ns/query ({:.2f}%);", ccd_path_name(static_cast<CcdPath>(i)),
                          ns(tier_seconds[i], by_path[i]),
                          100.0 * static_cast<double>(by_path[i]) / static_cast<double>(queries));
    }
    const std::size_t beyond_double = by_path[static_cast<int>(CcdPath::exact_signs)] +
                                      by_path[static_cast<int>(CcdPath::exact)] +
                                      by_path[static_cast<int>(CcdPath::gmp)];
    const std::size_t exact_tier =
        by_path[static_cast<int>(CcdPath::exact)] + by_path[static_cast<int>(CcdPath::gmp)];
    auto rate = [&](std::size_t n) {
      return queries ? 100.0 * static_cast<double>(n) / static_cast<double>(queries) : 0.0;
    };
    line += fmt::format(
        "\n  fallback rates: exact arithmetic {:.2f}%, exact tier {:.2f}%, gmp {:.4f}%",
        rate(beyond_double), rate(exact_tier), rate(by_path[static_cast<int>(CcdPath::gmp)]));
    return line;
  }
};

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

CcdResult run_one(const CcdQueryFile& file, std::size_t i) {
  return file.kind == CcdQueryKind::vertex_face ? vertex_face_ccd(file.vertex_face[i])
                                                : edge_edge_ccd(file.edge_edge[i]);
}

/// CPU seconds per pass over `indices` (repeated until kMinSeconds), one query at a time
/// in this thread: a single-core figure that other processes on the machine do not
/// inflate.
double seconds_per_pass(const CcdQueryFile& file, const std::vector<std::size_t>& indices) {
  if (indices.empty()) return 0.0;
  int passes = 0;
  std::size_t hits = 0;
  const double start = thread_cpu_seconds();
  double elapsed = 0.0;
  do {
    for (std::size_t i : indices) hits += run_one(file, i).hit;
    ++passes;
    elapsed = thread_cpu_seconds() - start;
  } while (elapsed < kMinSeconds);
  if (hits == static_cast<std::size_t>(-1)) fmt::print("");  // keep the loop observable
  return elapsed / passes;
}

Tally check_file(const CcdQueryFile& file, const std::vector<bool>& truth) {
  Tally t;
  t.queries = file.size();
  std::vector<CcdResult> results(file.size());
  for (std::size_t i = 0; i < file.size(); ++i) results[i] = run_one(file, i);
  std::array<std::vector<std::size_t>, kCcdPathCount> by_tier;
  std::vector<std::size_t> all(file.size());
  for (std::size_t i = 0; i < file.size(); ++i) {
    all[i] = i;
    t.colliding += truth[i];
    t.fn += truth[i] && !results[i].hit;
    t.fp += !truth[i] && results[i].hit;
    by_tier[static_cast<int>(results[i].path)].push_back(i);
  }
  t.seconds = seconds_per_pass(file, all);
  for (int k = 0; k < kCcdPathCount; ++k) {
    t.by_path[k] = by_tier[k].size();
    t.tier_seconds[k] = seconds_per_pass(file, by_tier[k]);
  }
  return t;
}

int run_ccd_check(const std::vector<std::string>& files, const std::vector<std::string>& truths) {
  std::vector<CcdQueryFile> loaded;
  std::size_t without_truth = 0;
  for (const auto& f : files) {
    loaded.push_back(read_ccd_queries(f));
    without_truth += loaded.back().truth.empty();
  }
  if (truths.size() != without_truth) {
    throw InputError(
        fmt::format("{} file(s) have no truth column but {} --truth file(s) given; "
                    "give one --truth per such file, in the same order",
                    without_truth, truths.size()));
  }
  Tally total;
  std::size_t next_truth = 0;
  for (auto& file : loaded) {
    std::vector<bool> truth = file.truth;
    if (truth.empty()) {
      const std::string& json = truths[next_truth++];
      truth = read_ccd_truth_json(json);
      if (truth.size() != file.size()) {
        throw InputError(fmt::format("{}: {} booleans for {} queries in {}", json, truth.size(),
                                     file.size(), file.path));
      }
    }
    const Tally t = check_file(file, truth);
    fmt::print("{} [{}] {}\n", file.path,
               file.kind == CcdQueryKind::vertex_face ? "vertex-face" : "edge-edge", t.describe());
    total.add(t);
  }
  fmt::print("total {}\n", total.describe());
  fmt::print("queries={} fn={} fp={}\n", total.queries, total.fn, total.fp);
  return total.fn > 0 ? kFailure : kSuccess;
}

const CommandRegistration ccd_check_registration{
    "ccd-check", [](CLI::App& app) -> std::function<int()> {
      CLI::App* command = app.add_subcommand(
          "ccd-check",
          "Run the exact CCD on reference query files and compare with their ground truth");
      auto files = std::make_shared<std::vector<std::string>>();
      auto truths = std::make_shared<std::vector<std::string>>();
      command
          ->add_option("files", *files,
                       "Query CSV files (type from a vertex-face/edge-edge folder or a "
                       "name ending in vf/ee)")
          ->required()
          ->check(CLI::ExistingFile);
      command
          ->add_option("--truth", *truths,
                       "JSON array of booleans (mma_bool) for a file without a truth column; "
                       "repeat it, one per such file, in the order of those files")
          ->expected(1)
          ->allow_extra_args(false)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
          ->check(CLI::ExistingFile);
      command->footer(
          "Prints one block per file and a total: queries, colliding, false negatives, false "
          "positives, CPU ns per query on one core (repeated passes), how many queries each "
          "tier decided (filter, double, exact_signs: the double tier with some signs settled "
          "in exact arithmetic, exact: fixed-size integers, gmp: the GMP last resort), each "
          "tier's ns per query on its own queries, and the fallback rates; then the line "
          "'queries=N fn=F fp=P'. Exit code 1 on any false negative, 2 on bad input.");
      return [files, truths] { return run_ccd_check(*files, *truths); };
    }};

}  // namespace
}  // namespace tailor::cli
