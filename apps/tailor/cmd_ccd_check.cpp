/// @file
/// `tailor ccd-check FILE... [--truth FILE.json]...`: runs the exact CCD on every query of
/// reference query files and compares with the ground truth. Exit code 1 on any false
/// negative.

#include <fmt/format.h>

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

struct Tally {
  std::size_t queries = 0, colliding = 0, fn = 0, fp = 0;
  std::size_t by_path[3] = {0, 0, 0};
  double seconds = 0.0;

  void add(const Tally& o) {
    queries += o.queries;
    colliding += o.colliding;
    fn += o.fn;
    fp += o.fp;
    for (int i = 0; i < 3; ++i) by_path[i] += o.by_path[i];
    seconds += o.seconds;
  }
  std::string describe() const {
    const double ns = queries ? seconds * 1e9 / static_cast<double>(queries) : 0.0;
    return fmt::format(
        "queries={} colliding={} fn={} fp={} ns/query={:.0f} filter={} double={} "
        "exact={}",
        queries, colliding, fn, fp, ns, by_path[0], by_path[1], by_path[2]);
  }
};

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

Tally check_file(const CcdQueryFile& file, const std::vector<bool>& truth) {
  Tally t;
  t.queries = file.size();
  std::vector<CcdResult> results(file.size());
  // One thread, one query at a time, timed in this thread's CPU time: a single-core
  // figure that other processes on the machine do not inflate.
  const double start = thread_cpu_seconds();
  for (std::size_t i = 0; i < file.size(); ++i) {
    results[i] = file.kind == CcdQueryKind::vertex_face ? vertex_face_ccd(file.vertex_face[i])
                                                        : edge_edge_ccd(file.edge_edge[i]);
  }
  t.seconds = thread_cpu_seconds() - start;
  for (std::size_t i = 0; i < file.size(); ++i) {
    t.colliding += truth[i];
    t.fn += truth[i] && !results[i].hit;
    t.fp += !truth[i] && results[i].hit;
    ++t.by_path[static_cast<int>(results[i].path)];
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

const CommandRegistration registration{
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
          "Prints one line per file and a total (queries, colliding, false negatives, false "
          "positives, CPU ns per query on one core, queries decided by each path), then the line "
          "'queries=N fn=F fp=P'. Exit code 1 on any false negative, 2 on bad input.");
      return [files, truths] { return run_ccd_check(*files, *truths); };
    }};

}  // namespace
}  // namespace tailor::cli
