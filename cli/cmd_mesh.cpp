// rbcsim mesh generate | import | info: build a cell mesh, read and check one, or describe one.
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "command_registry.hpp"
#include "common_options.hpp"
#include "mesh/cell_shapes.hpp"
#include "mesh/import.hpp"
#include "mesh/inspection.hpp"
#include "mesh/stl_writer.hpp"
#include "setup/cell_from_config.hpp"

namespace rbcsim::cli::mesh_command {
namespace {

struct GenerateOptions {
  config::ConfigRequest config;      // --config/--set carry the mesh.<shape>.* generator parameters
  std::optional<std::string> shape;  // default: the config's morphology
  std::optional<int> subdivisions;   // default: the config's mesh.subdivisions
  std::string output;
  bool json = false;
};

struct ImportCommandOptions {
  std::string input;
  std::string output;
  double target_area_um2 = 0.0;
  double target_volume_um3 = 0.0;
  bool center = false;
  bool align = false;
  bool json = false;
};

struct InfoOptions {
  std::string input;
  bool json = false;
};

// Results: JSON on stdout with --json, else the text table; notices always go to stderr.
void print_report(const mesh::MeshReport& report, bool json, nlohmann::ordered_json header) {
  if (json) {
    header["report"] = mesh::to_json(report);
    std::cout << header.dump(2) << '\n';
    return;
  }
  for (const auto& [key, value] : header.items()) {
    std::cout << key << ": " << (value.is_string() ? value.get<std::string>() : value.dump())
              << '\n';
  }
  std::cout << mesh::to_text(report);
}

void run_generate(const GenerateOptions& options) {
  const auto config = config::resolve_config(options.config);
  const auto shape = options.shape.value_or(config.string("morphology"));
  const auto subdivisions = options.subdivisions.value_or(config.integer("mesh.subdivisions"));
  const auto parameters = setup::cell_shape_parameters_from(config);
  const auto cell = mesh::generate_cell(shape, subdivisions, parameters);
  if (const auto notice = mesh::resolution_notice(shape, subdivisions, parameters, cell)) {
    std::cerr << "rbcsim: notice: " << *notice << '\n';
  }
  if (!options.output.empty()) mesh::write_mesh_file(options.output, cell);
  nlohmann::ordered_json header = {{"shape", shape}, {"subdivisions", subdivisions}};
  if (!options.output.empty()) header["output"] = options.output;
  print_report(mesh::inspect_mesh(cell), options.json, header);
}

void run_import(const ImportCommandOptions& options, const CLI::App& command) {
  mesh::ImportOptions import_options;
  if (command.count("--scale-to-area") > 0)
    import_options.target_area_um2 = options.target_area_um2;
  if (command.count("--scale-to-volume") > 0) {
    import_options.target_volume_um3 = options.target_volume_um3;
  }
  import_options.center = options.center;
  import_options.align = options.align;
  const auto imported = mesh::import_mesh(options.input, import_options);
  for (const auto& notice : imported.notices) std::cerr << "rbcsim: notice: " << notice << '\n';
  if (!options.output.empty()) mesh::write_mesh_file(options.output, imported.mesh);
  nlohmann::ordered_json header = {{"input", options.input}};
  if (!options.output.empty()) header["output"] = options.output;
  print_report(mesh::inspect_mesh(imported.mesh), options.json, header);
}

void run_info(const InfoOptions& options) {
  const auto imported = mesh::import_mesh(options.input);
  for (const auto& notice : imported.notices) std::cerr << "rbcsim: notice: " << notice << '\n';
  print_report(mesh::inspect_mesh(imported.mesh), options.json, {{"input", options.input}});
}

void attach_generate(CLI::App& mesh_command) {
  auto options = std::make_shared<GenerateOptions>();
  auto* command = mesh_command.add_subcommand(
      "generate", "Build a cell mesh from the icosphere (level 4: 2562 vertices, 5120 triangles)");
  command->add_option("--shape", options->shape,
                      "Cell shape: " + mesh::cell_shape_names() + " (default: --morphology)");
  command->add_option("--subdivisions", options->subdivisions,
                      "Icosphere level 0-7 (default: mesh.subdivisions, 4)");
  add_config_options(command, options->config);
  command->add_option("-o,--output", options->output, "Write the mesh (.stl binary or .vtp)");
  command->add_flag("--json", options->json, "Print the mesh report as JSON on stdout");
  command->callback([options] { run_generate(*options); });
}

void attach_import(CLI::App& mesh_command) {
  auto options = std::make_shared<ImportCommandOptions>();
  auto* command = mesh_command.add_subcommand(
      "import",
      "Read a surface (STL, OBJ, PLY, OFF; coordinates in um), weld, check, repair an inside-out "
      "mesh, optionally rescale/recentre/align, and write it");
  command->add_option("file", options->input, "Input mesh file")->required();
  command->add_option("-o,--output", options->output, "Write the cleaned mesh (.stl or .vtp)");
  auto* area = command->add_option("--scale-to-area", options->target_area_um2,
                                   "Scale uniformly to this area [um^2]");
  command
      ->add_option("--scale-to-volume", options->target_volume_um3,
                   "Scale uniformly to this enclosed volume [um^3]")
      ->excludes(area);
  command->add_flag("--center", options->center, "Move the centroid of the solid to the origin");
  command->add_flag("--align", options->align,
                    "Rotate the principal axes onto x (largest extent), y, z (smallest)");
  command->add_flag("--json", options->json, "Print the mesh report as JSON on stdout");
  command->callback([options, command] { run_import(*options, *command); });
}

void attach_info(CLI::App& mesh_command) {
  auto options = std::make_shared<InfoOptions>();
  auto* command = mesh_command.add_subcommand(
      "info", "Check a mesh file and print its statistics (topology, size, triangle quality)");
  command->add_option("file", options->input, "Mesh file")->required();
  command->add_flag("--json", options->json, "Print the report as JSON on stdout");
  command->callback([options] { run_info(*options); });
}

void attach_mesh(CLI::App& application) {
  auto* mesh_command =
      application.add_subcommand("mesh", "Generate, import and inspect cell meshes");
  mesh_command->require_subcommand(1);
  attach_generate(*mesh_command);
  attach_import(*mesh_command);
  attach_info(*mesh_command);
}

const bool registered = register_command({"mesh", 10, attach_mesh});

}  // namespace
}  // namespace rbcsim::cli::mesh_command
