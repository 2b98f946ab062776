// rbcsim mesh generate | import | info: build a cell mesh, read and check one, or describe one.
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "command_registry.hpp"
#include "common/format.hpp"
#include "common_options.hpp"
#include "config/option_table.hpp"
#include "mesh/cell_shapes.hpp"
#include "mesh/import.hpp"
#include "mesh/inspection.hpp"
#include "mesh/stl_writer.hpp"
#include "setup/cell_from_config.hpp"
#include "shapes/sequence.hpp"
#include "shapes/shape_report.hpp"

namespace rbcsim::cli::mesh_command {
namespace {

struct GenerateOptions {
  config::ConfigRequest config;  // --config/--set carry mesh.method, mesh.energy.*, mesh.<shape>.*
  std::optional<std::string> shape;   // default: the config's morphology
  std::optional<int> subdivisions;    // mesh.subdivisions
  std::optional<std::string> method;  // mesh.method
  bool fresh = false;                 // minimise even when a shipped shape has these settings
  std::string output;
  bool json = false;
  bool quiet = false;
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

// Progress of a minimisation on a terminal (stderr), one overwritten line.
shapes::EnergyShapeProgress minimisation_progress(const GenerateOptions& options, int trials) {
  if (options.quiet || isatty(STDERR_FILENO) != 1) return {};
  return [trials](int trial, int stage, const minimise::FireResult& so_far) {
    std::cerr << "\r\033[Kminimising: trial " << trial + 1 << "/" << trials << ", stage "
              << stage + 1 << ", iteration " << so_far.iterations << ", largest force "
              << format_significant(so_far.max_force, 3) << " pN" << std::flush;
  };
}

void run_generate(const GenerateOptions& options) {
  if (!options.output.empty()) mesh::require_mesh_file_format(options.output);
  auto request = options.config;
  if (options.method) assign_option(request, "--method", "mesh.method", *options.method);
  if (options.subdivisions) {
    assign_option(request, "--subdivisions", "mesh.subdivisions",
                  std::to_string(*options.subdivisions));
  }
  const auto config = config::resolve_config(request);
  const auto shape = options.shape.value_or(config.string("morphology"));
  auto settings = setup::named_cell_settings_from(config, shape);
  settings.use_shipped = !options.fresh;
  const auto cell = shapes::make_named_cell(
      shape, options.shape ? "--shape" : "morphology", settings,
      minimisation_progress(
          options, settings.energy.trials * static_cast<int>(settings.energy.paths.size())));
  if (cell.minimised && !options.quiet && isatty(STDERR_FILENO) == 1) std::cerr << '\n';
  if (settings.method == "parametric") {
    if (const auto notice =
            mesh::resolution_notice(shape, settings.subdivisions, settings.parametric, cell.mesh)) {
      std::cerr << "rbcsim: notice: " << *notice << '\n';
    }
  }
  if (!options.output.empty()) mesh::write_mesh_file(options.output, cell.mesh);
  nlohmann::ordered_json header = {
      {"shape", shape}, {"method", settings.method}, {"subdivisions", settings.subdivisions}};
  if (!options.output.empty()) header["output"] = options.output;
  if (settings.method == "energy") {
    header["source"] = cell.minimised ? "minimised" : "shipped";
    header["settings"] = shapes::to_json(settings.energy);
    // The energies are the minimum's; the mesh is the minimum with its vertices redistributed
    // over its surface (a shipped mesh's manifest entry holds both reports).
    if (cell.minimised) {
      header["minimisation"] = shapes::minimisation_json(*cell.minimised);
      header["energy"] =
          shapes::energy_json(cell.minimised->minimum, settings.subdivisions, settings.energy);
      header["redistribution"] = shapes::redistribution_json(cell.minimised->redistribution);
    } else {
      for (const char* part : {"minimisation", "energy", "redistribution"}) {
        header[part] = cell.shipped_entry.value(part, nlohmann::json());
      }
    }
  }
  header["morphology"] = shapes::morphology_json(cell.mesh);
  print_report(mesh::inspect_mesh(cell.mesh), options.json, header);
}

void run_import(const ImportCommandOptions& options, const CLI::App& command) {
  if (!options.output.empty()) mesh::require_mesh_file_format(options.output);
  mesh::ImportOptions import_options;
  if (command.count("--scale-to-area") > 0)
    import_options.target_area_um2 = options.target_area_um2;
  if (command.count("--scale-to-volume") > 0) {
    import_options.target_volume_um3 = options.target_volume_um3;
  }
  import_options.center = options.center;
  import_options.align = options.align;
  const auto imported = mesh::import_mesh(options.input, import_options);
  print_notices(imported.notices);
  if (!options.output.empty()) mesh::write_mesh_file(options.output, imported.mesh);
  nlohmann::ordered_json header = {{"input", options.input}};
  if (!options.output.empty()) header["output"] = options.output;
  print_report(mesh::inspect_mesh(imported.mesh), options.json, header);
}

void run_info(const InfoOptions& options) {
  const auto imported = mesh::import_mesh(options.input);
  print_notices(imported.notices);
  print_report(mesh::inspect_mesh(imported.mesh), options.json, {{"input", options.input}});
}

void attach_generate(CLI::App& mesh_command) {
  auto options = std::make_shared<GenerateOptions>();
  auto* command = mesh_command.add_subcommand(
      "generate", "Build a cell mesh from the icosphere (level 4: 2562 vertices, 5120 triangles)");
  command->add_option("--shape", options->shape,
                      "Cell shape: with --method energy one of " +
                          shapes::shape_sequence().joined_names() + "; with parametric one of " +
                          mesh::cell_shape_names() + " (default: --morphology)");
  command->add_option("--subdivisions", options->subdivisions,
                      "Icosphere level (mesh.subdivisions; default " +
                          config::option_table().find("mesh.subdivisions")->default_value.dump() +
                          ": 2562 vertices)");
  command->add_option(
      "--method", options->method,
      "How the shape is made (mesh.method): " + shapes::shape_methods().described_names());
  command->add_flag("--fresh", options->fresh,
                    "Minimise even when a shipped mesh was made with the same settings");
  add_config_options(command, options->config);
  command->add_option("-o,--output", options->output, "Write the mesh (.stl binary or .vtp)");
  command->add_flag("--json", options->json, "Print the mesh report as JSON on stdout");
  command->add_flag("--quiet", options->quiet, "No progress on the terminal");
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
