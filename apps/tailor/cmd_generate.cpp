/// @file
/// `tailor generate SCENE --triangles N --out DIR`: writes a procedural step as two meshes
/// (DIR/t0.ply, DIR/t1.ply) for `tailor detect`, benchmarks and bug reports.

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <string>

#include "command.hpp"
#include "tailor/io/file_bytes.hpp"
#include "tailor/io/mesh_io.hpp"
#include "tailor/mesh/procedural_steps.hpp"

namespace tailor::cli {
namespace {

struct GenerateOptions {
  std::string scene = "folded-cloth";
  std::int64_t triangles = 100'000;
  std::uint64_t seed = 1;
  int layers = 6;
  std::string out;
};

int run_generate(const GenerateOptions& options) {
  const std::filesystem::path dir(options.out);
  prepare_output_folder(dir);  // before the work; a file there is an InputError (exit 2)
  const ProceduralStep step =
      options.scene == "crumpling-cloth" ? make_crumpling_cloth_step(options.triangles)
      : options.scene == "pleated-cloth"
          ? make_pleated_cloth(options.triangles, options.layers, options.seed)
          : make_folded_cloth_on_sphere(options.triangles, options.seed);
  write_mesh(dir / "t0.ply", step.x0, step.faces);
  write_mesh(dir / "t1.ply", step.x1, step.faces);
  fmt::print("{}: {} vertices, {} triangles -> {} and {}\n", options.scene, step.x0.rows(),
             step.faces.rows(), (dir / "t0.ply").string(), (dir / "t1.ply").string());
  return kSuccess;
}

const CommandRegistration generate_registration{
    "generate", [](CLI::App& app) -> std::function<int()> {
      CLI::App* command = app.add_subcommand(
          "generate", "Write a procedural deforming step (t0.ply, t1.ply) for detect and bench");
      auto options = std::make_shared<GenerateOptions>();
      command
          ->add_option(
              "scene", options->scene,
              "Scene: folded-cloth (cloth folded onto itself on a sphere: contact-heavy), "
              "pleated-cloth (a cloth pleated into layers heaving through one another: the "
              "contact density of real dense steps such as cloth-ball) or crumpling-cloth (a "
              "crumpling square cloth: no contact)")
          ->check(CLI::IsMember({"folded-cloth", "pleated-cloth", "crumpling-cloth"}));
      command->add_option("--triangles", options->triangles, "Approximate triangle count")
          ->check(CLI::Range(std::int64_t{200}, std::int64_t{1} << 26));
      command->add_option("--seed", options->seed, "Random seed");
      command->add_option("--layers", options->layers, "Layers of pleated-cloth")
          ->check(CLI::Range(2, 64));
      command->add_option("--out", options->out, "Output folder")->required();
      return [options] { return run_generate(*options); };
    }};

}  // namespace
}  // namespace tailor::cli
