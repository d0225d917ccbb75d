#include "bench/paper_benchmark.hpp"

#include <fmt/format.h>

#include <numeric>

#include "bench/svg_plot.hpp"
#include "tailor/io/file_bytes.hpp"
#include "tailor/sim/simulation.hpp"

namespace tailor {
namespace {

// The high-level configurations of Fig. 1 that are not rows of Table 1: `basic` is
// Table 1's basic, `isolated_set` is Table 1's paper (same high-level stages).
DetectionConfig high_level(bool cones, bool radial) {
  DetectionConfig config = DetectionConfig::preset("basic");
  config.normal_cones = config.contour_test = cones;
  config.radial_view = radial;
  return config;
}

// The paper preset classifying every radial-view cluster every step: the same culling, run
// only for the classification shares (the detector otherwise classifies only what a kept
// pair needs, and in most sleeve steps that is nothing).
DetectionConfig every_cluster_classified() {
  DetectionConfig config = DetectionConfig::preset("paper");
  config.classify_every_cluster = true;
  return config;
}

template <class T>
double mean(const std::vector<T>& values) {
  if (values.empty()) return 0;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

PlotSeries per_step(const std::string& name, const std::vector<std::int64_t>& values) {
  PlotSeries series;
  series.name = name;
  for (std::size_t i = 0; i < values.size(); ++i) {
    series.x.push_back(static_cast<double>(i));
    series.y.push_back(static_cast<double>(values[i]));
  }
  return series;
}

}  // namespace

const PaperRun& PaperBenchmark::run(const std::string& name) const {
  for (const PaperRun& r : runs) {
    if (r.name == name) return r;
  }
  throw std::out_of_range("no run " + name);
}

namespace {

// Share of `part` in `positive + negative + undetermined` at substep `i` (0 if none).
double share(const PaperRun& r, const std::vector<std::int64_t>& part, std::size_t i) {
  const std::int64_t total = r.radial_positive[i] + r.radial_negative[i] + r.radial_undetermined[i];
  return total > 0 ? static_cast<double>(part[i]) / static_cast<double>(total) : 0.0;
}

// Mean over the steps that classified (the detector skips radial view when the traversal
// leaves no candidate pair).
double mean_share(const PaperRun& r, const std::vector<std::int64_t>& part) {
  double sum = 0;
  std::size_t classified = 0;
  for (std::size_t i = 0; i < part.size(); ++i) {
    if (r.radial_positive[i] + r.radial_negative[i] + r.radial_undetermined[i] == 0) continue;
    sum += share(r, part, i);
    ++classified;
  }
  return classified == 0 ? 0 : sum / static_cast<double>(classified);
}

// Fig. 1's stages in order, then Tang's configuration beside them.
const std::vector<std::pair<std::string, std::string>>& fig1_rows() {
  static const std::vector<std::pair<std::string, std::string>> rows{
      {"basic BVH", "basic"},
      {"+ normal cones", "normal_cones"},
      {"+ radial view", "radial_view"},
      {"+ isolated set (paper)", "paper"},
      {"Tang: normal cones + isolated set, no radial view", "tang"}};
  return rows;
}

}  // namespace

std::string PaperBenchmark::fig1_csv() const {
  const auto& a = run("basic").ctps;
  const auto& b = run("normal_cones").ctps;
  const auto& c = run("radial_view").ctps;
  const auto& d = run("paper").ctps;
  const auto& e = run("tang").ctps;
  const PaperRun& paper = run("radial_statistics");
  std::string csv =
      "step,basic,normal_cones,radial_view,isolated_set,tang,positive,negative,undetermined\n";
  for (std::size_t i = 0; i < a.size(); ++i) {
    csv +=
        fmt::format("{},{},{},{},{},{},{:.4f},{:.4f},{:.4f}\n", i, a[i], b[i], c[i], d[i], e[i],
                    share(paper, paper.radial_positive, i), share(paper, paper.radial_negative, i),
                    share(paper, paper.radial_undetermined, i));
  }
  return csv;
}

bool PaperBenchmark::fig1_stages_decrease() const {
  double previous = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const double m = mean(run(fig1_rows()[i].second).ctps);
    if (i > 0 && !(m < previous || previous == 0)) return false;  // nothing left to lower
    previous = m;
  }
  return true;
}

std::string PaperBenchmark::fig1_markdown() const {
  std::string md = "| high-level culling | mean CTPs per step | max |\n|---|---:|---:|\n";
  for (const auto& [label, name] : fig1_rows()) {
    const auto& ctps = run(name).ctps;
    md += fmt::format("| {} | {:.1f} | {} |\n", label, mean(ctps),
                      ctps.empty() ? 0 : *std::max_element(ctps.begin(), ctps.end()));
  }
  const double cones = mean(run("normal_cones").ctps), radial = mean(run("radial_view").ctps);
  const double tang = mean(run("tang").ctps), paper = mean(run("paper").ctps);
  md += fmt::format(
      "\n+ radial view / + normal cones: {:.3f} (target ≤ 0.6); paper / Tang: {:.3f} (the paper "
      "claims ≤ 0.5); every stage lowers the mean: {}\n",
      cones > 0 ? radial / cones : 0.0, tang > 0 ? paper / tang : 0.0,
      fig1_stages_decrease() ? "yes" : "NO");
  const PaperRun& r = run("radial_statistics");
  md += fmt::format(
      "\nRadial-view classification (paper preset classifying every cluster every step, real "
      "and ghost triangles of every cluster, "
      "mean share per step that classified): positive {:.3f}, negative {:.3f}, undetermined "
      "{:.3f}\n",
      mean_share(r, r.radial_positive), mean_share(r, r.radial_negative),
      mean_share(r, r.radial_undetermined));
  return md;
}

std::string PaperBenchmark::table1_csv() const {
  std::string csv = "method,vf,ee,detect_ms,step_ms,fps\n";
  for (const std::string name : {"basic", "curtis", "tang", "paper"}) {
    const PaperRun& r = run(name);
    csv += fmt::format("{},{:.1f},{:.1f},{:.3f},{:.3f},{:.2f}\n", name, mean(r.vf), mean(r.ee),
                       mean(r.detect_ms), mean(r.step_ms), r.fps());
  }
  return csv;
}

std::string PaperBenchmark::table1_markdown() const {
  struct Published {
    const char* name;
    double vf, ee, fps;
  };
  const Published published[] = {{"basic", 1122, 2056, 12.70},
                                 {"curtis", 74, 45, 32},
                                 {"tang", 44, 338, 37.54},
                                 {"paper", 31, 137, 34.22}};
  std::string md =
      "| method | VF (ours) | EE (ours) | detect ms | step ms | fps (ours) | VF (paper) | "
      "EE (paper) | fps (paper) |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Published& p : published) {
    const PaperRun& r = run(p.name);
    md += fmt::format("| {} | {:.1f} | {:.1f} | {:.3f} | {:.3f} | {:.2f} | {} | {} | {} |\n",
                      p.name, mean(r.vf), mean(r.ee), mean(r.detect_ms), mean(r.step_ms), r.fps(),
                      p.vf, p.ee, p.fps);
  }
  return md;
}

void PaperBenchmark::write(const std::filesystem::path& dir) const {
  std::filesystem::create_directories(dir);
  write_file_atomically(dir / "fig1.csv", fig1_csv());
  write_file_atomically(dir / "fig1.md", fig1_markdown());
  write_file_atomically(dir / "table1.csv", table1_csv());
  write_file_atomically(dir / "table1.md", table1_markdown());
  LinePlot fig1;
  fig1.title = fmt::format("Candidate triangle pairs per step ({} gesture)", gesture);
  fig1.x_label = "step";
  fig1.y_label = "CTPs";
  fig1.series = {per_step("basic BVH", run("basic").ctps),
                 per_step("+ normal cones", run("normal_cones").ctps),
                 per_step("+ radial view", run("radial_view").ctps),
                 per_step("+ isolated set", run("paper").ctps),
                 per_step("Tang (no radial view)", run("tang").ctps)};
  fig1.write(dir / "fig1.svg");
  LinePlot pairs;
  pairs.title = "VF + EE pairs reaching the exact CCD per step";
  pairs.x_label = "step";
  pairs.y_label = "pairs";
  for (const std::string name : {"basic", "curtis", "tang", "paper"}) {
    const PaperRun& r = run(name);
    std::vector<std::int64_t> sum(r.vf.size());
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] = r.vf[i] + r.ee[i];
    pairs.series.push_back(per_step(name, sum));
  }
  pairs.write(dir / "table1.svg");
  if (figures) figures->write(dir);
}

PaperBenchmark run_paper_benchmark(
    const SceneConfig& scene, const std::function<void(const std::string&, int, int)>& progress) {
  PaperBenchmark bench;
  bench.figures = std::make_shared<PaperFigures>(peak_flexion_frame(scene));
  bench.gesture = scene.gesture.name;
  const std::vector<std::pair<std::string, DetectionConfig>> configs{
      {"basic", DetectionConfig::preset("basic")},
      {"curtis", DetectionConfig::preset("curtis")},
      {"tang", DetectionConfig::preset("tang")},
      {"paper", DetectionConfig::preset("paper")},
      {"normal_cones", high_level(true, false)},
      {"radial_view", high_level(true, true)},
      {"radial_statistics", every_cluster_classified()}};
  for (const auto& [name, config] : configs) {
    PaperRun run;
    run.name = name;
    run.config = config;
    SimulationOptions options;
    options.detection = config;
    options.record_contacts = true;  // the candidate faces of Fig. 1's pictures
    Simulation simulation(scene, options);
    for (int frame = 0; frame < scene.frames; ++frame) {
      const std::vector<StepRecord>& records = simulation.step_frame();
      bench.figures->observe(name, simulation, records);
      for (const StepRecord& step : records) {
        const DetectionStats& d = step.contact.detection;
        run.ctps.push_back(d.candidate_triangle_pairs);
        run.vf.push_back(d.vf_tested);
        run.ee.push_back(d.ee_tested);
        run.self_collisions.push_back(step.contact.self_collisions);
        run.radial_positive.push_back(d.radial_positive);
        run.radial_negative.push_back(d.radial_negative);
        run.radial_undetermined.push_back(d.radial_undetermined);
        run.detect_ms.push_back(step.detection_ms);
        run.step_ms.push_back(step.step_ms);
      }
      if (progress) progress(name, frame + 1, scene.frames);
    }
    run.frames = scene.frames;
    run.wall_seconds = simulation.totals().wall_seconds;
    if (!bench.runs.empty() && bench.same_collisions) {
      const PaperRun& first = bench.runs.front();
      for (std::size_t i = 0;
           i < std::min(first.self_collisions.size(), run.self_collisions.size()); ++i) {
        if (first.self_collisions[i] != run.self_collisions[i]) {
          bench.same_collisions = false;
          bench.mismatch =
              fmt::format("step {}: {} found {} self-collisions, {} found {}", i, first.name,
                          first.self_collisions[i], name, run.self_collisions[i]);
          break;
        }
      }
    }
    bench.runs.push_back(std::move(run));
  }
  return bench;
}

}  // namespace tailor
