#include "setup/cell_from_config.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "cases/capillary_observables.hpp"
#include "common/format.hpp"
#include "config/option_table.hpp"
#include "config/validation.hpp"
#include "ibm/delta_kernels.hpp"
#include "mesh/import.hpp"
#include "mesh/inspection.hpp"

namespace rbcsim::setup {
namespace {

using Shapes = mesh::CellShapeParameters;

// Number options of the generators: path -> (member of CellShapeParameters, member of the shape).
template <class Shape>
using ShapeNumber = std::pair<const char*, double Shape::*>;

constexpr std::array<ShapeNumber<mesh::DiscocyteShape>, 4> kDiscocyteNumbers{{
    {"mesh.discocyte.radius_um", &mesh::DiscocyteShape::radius_um},
    {"mesh.discocyte.c0", &mesh::DiscocyteShape::c0},
    {"mesh.discocyte.c2", &mesh::DiscocyteShape::c2},
    {"mesh.discocyte.c4", &mesh::DiscocyteShape::c4},
}};
constexpr std::array<ShapeNumber<mesh::StomatocyteShape>, 4> kStomatocyteNumbers{{
    {"mesh.stomatocyte.membrane_area_um2", &mesh::StomatocyteShape::membrane_area_um2},
    {"mesh.stomatocyte.reduced_volume", &mesh::StomatocyteShape::reduced_volume},
    {"mesh.stomatocyte.cup_half_angle_deg", &mesh::StomatocyteShape::cup_half_angle_deg},
    {"mesh.stomatocyte.rim_thickening", &mesh::StomatocyteShape::rim_thickening},
}};
constexpr std::array<ShapeNumber<mesh::EchinocyteShape>, 5> kEchinocyteNumbers{{
    {"mesh.echinocyte.membrane_area_um2", &mesh::EchinocyteShape::membrane_area_um2},
    {"mesh.echinocyte.spicule_height_um", &mesh::EchinocyteShape::spicule_height_um},
    {"mesh.echinocyte.spicule_tip_radius_um", &mesh::EchinocyteShape::spicule_tip_radius_um},
    {"mesh.echinocyte.spicule_flank_angle_deg", &mesh::EchinocyteShape::spicule_flank_angle_deg},
    {"mesh.echinocyte.spicule_base_blend_um", &mesh::EchinocyteShape::spicule_base_blend_um},
}};

template <class Shape, std::size_t N>
void read_numbers(const config::Config& config, const std::array<ShapeNumber<Shape>, N>& numbers,
                  Shape& shape) {
  for (const auto& [path, member] : numbers) shape.*member = config.number(path);
}

}  // namespace

mesh::CellShapeParameters cell_shape_parameters_from(const config::Config& config) {
  Shapes parameters;
  read_numbers(config, kDiscocyteNumbers, parameters.discocyte);
  read_numbers(config, kStomatocyteNumbers, parameters.stomatocyte);
  read_numbers(config, kEchinocyteNumbers, parameters.echinocyte);
  parameters.echinocyte.spicule_count = config.integer("mesh.echinocyte.spicule_count");
  return parameters;
}

shapes::NamedCellSettings named_cell_settings_from(const config::Config& config,
                                                   std::string_view shape) {
  shapes::NamedCellSettings settings;
  settings.method = config.string("mesh.method");
  settings.subdivisions = config.integer("mesh.subdivisions");
  settings.parametric = cell_shape_parameters_from(config);
  auto& energy = settings.energy;
  energy.area_um2 = config.number("mesh.energy.membrane_area_um2");
  energy.reduced_volume = config.number("mesh.energy.reduced_volume");
  energy.bending_modulus_J = config.number("mesh.energy.bending_modulus_J");
  energy.nonlocal_bending_ratio = config.number("mesh.energy.nonlocal_bending_ratio");
  energy.skeleton.shear_modulus_pN_per_um = config.number("mesh.energy.shear_modulus_uN_per_m");
  energy.skeleton.area_modulus_pN_per_um = config.number("mesh.energy.area_modulus_uN_per_m");
  energy.skeleton.a3 = config.number("mesh.energy.skeleton_a3");
  energy.skeleton.a4 = config.number("mesh.energy.skeleton_a4");
  energy.skeleton.b1 = config.number("mesh.energy.skeleton_b1");
  energy.skeleton.b2 = config.number("mesh.energy.skeleton_b2");
  energy.skeleton_reference_reduced_volume =
      config.number("mesh.energy.skeleton_reference_reduced_volume");
  energy.soft_skeleton_fraction = config.number("mesh.energy.soft_skeleton_fraction");
  energy.volume_stages = config.integer("mesh.energy.volume_stages");
  energy.stiffening_stages = config.integer("mesh.energy.stiffening_stages");
  energy.continuation_start_area_difference =
      config.number("mesh.energy.continuation_start_area_difference");
  energy.continuation_step = config.number("mesh.energy.continuation_step");
  energy.stage_iterations =
      static_cast<std::size_t>(config.integer("mesh.energy.stage_iterations"));
  energy.seed = static_cast<std::uint64_t>(config.integer("mesh.energy.seed"));
  energy.perturbation_um = config.number("mesh.energy.perturbation_um");
  energy.force_tolerance_pN = config.number("mesh.energy.force_tolerance_pN");
  energy.max_iterations = static_cast<std::size_t>(config.integer("mesh.energy.max_iterations"));
  energy.redistribution.iterations = config.integer("mesh.energy.redistribution_sweeps");
  energy.redistribution.step_fraction = config.number("mesh.energy.redistribution_step");
  const std::string key = "mesh.energy.relaxed_area_difference." + std::string(shape);
  if (config::option_table().find(key) != nullptr) {
    energy.relaxed_area_difference = config.number(key);
    energy.relaxed_area_difference_key = key;
    energy.paths = config.string_list("mesh.energy.paths." + std::string(shape));
    energy.trials = config.integer("mesh.energy.trials." + std::string(shape));
  }
  return settings;
}

CellMesh cell_mesh_from(const config::Config& config) {
  const auto file = config.string("mesh.file");
  if (!file.empty()) {
    mesh::ImportOptions options;
    options.max_triangles = static_cast<std::size_t>(config.integer("mesh.max_triangles"));
    auto imported = mesh::import_mesh(file, options);
    return {std::move(imported.mesh), file, std::move(imported.notices), {}};
  }
  const auto shape = config.string("morphology");
  auto cell = shapes::make_named_cell(shape, "morphology", named_cell_settings_from(config, shape));
  return {std::move(cell.mesh), std::move(cell.source), {}, {}};
}

void add_resolution_notice(CellMesh& cell, const config::Config& config) {
  if (!config.string("mesh.file").empty() || config.string("mesh.method") != "parametric") return;
  auto notice =
      mesh::resolution_notice(config.string("morphology"), config.integer("mesh.subdivisions"),
                              cell_shape_parameters_from(config), cell.mesh);
  if (notice) cell.run_notices.push_back(std::move(*notice));
}

void add_edge_spacing_notice(CellMesh& cell, double spacing_um) {
  const double edge_um = mesh::inspect_mesh(cell.mesh).edge_mean_um;
  const double edge_per_spacing = edge_um / spacing_um;
  if (edge_per_spacing >= kQuietEdgePerSpacing) return;
  cell.run_notices.push_back(
      "the membrane's mean edge (" + format_number(std::round(edge_um * 1000.0) / 1000.0) +
      " um) is " + format_number(std::round(edge_per_spacing * 100.0) / 100.0) +
      " lattice spacings (lattice.spacing_um = " + format_number(spacing_um) +
      "); with edges of half a spacing the paper's cell fails at the local-area limit in "
      "sustained flow at capillary numbers near 1 (it passes at 0.075), with edges of about one "
      "spacing it passes at both (docs/validation.md, capillary)");
}

void require_cell_fits_domain(const mesh::TriangleMesh& cell, const Vec3& domain_extent_um,
                              double spacing_um, std::string_view ibm_kernel,
                              std::string_view what) {
  const double reach_spacings = 0.5 * ibm::find_delta_kernel(ibm_kernel).support_width;
  const Vec3 cell_extent_um = cases::vertex_extents(cell.positions_um);
  config::require_cell_fits_domain(
      {cell_extent_um.x(), cell_extent_um.y(), cell_extent_um.z()},
      {domain_extent_um.x(), domain_extent_um.y(), domain_extent_um.z()}, spacing_um,
      reach_spacings, what);
}

}  // namespace rbcsim::setup
