// Many cells in a straight tube (docs/physics.md, "Suspensions"): the blood-flow experiment of
// Pries et al. 1992 in a periodic piece of tube.
//
//   1. the cells packed to the target hematocrit (suspension_packing.hpp), each a membrane of its
//      own morphology with its stress-free mesh as reference;
//   2. the fluid alone (plasma) run to its steady Poiseuille flow under a body force that stands
//      for the pressure gradient: the force that drives plasma_mean_velocity_m_per_s through the
//      tube; its flow rate Q_plasma is measured on the lattice, so the discretisation of the wall
//      cancels in the viscosity ratio;
//   3. the coupled run under the same force, the cells pushed off the wall (wall_repulsion.hpp)
//      and off each other (contact/cell_repulsion.hpp), for duration_s.
//
// Measured every sample: the flow rate Q; relative apparent viscosity Q_plasma / Q (the same
// pressure gradient drives both); tube hematocrit (cell volumes over the lumen) and discharge
// hematocrit sum(V_i u_i) / (Q L) with u_i a cell's mean vertex velocity along the axis; the
// cell-free layer R - mean over (x, angle) bins of the outermost vertex's radius (bins holding no
// vertex left out); the hematocrit profile (the cells' volume fraction in rings about the axis,
// suspension_profile.hpp). Each cell's centroid, radial position, axial velocity and deformation
// index. The averages are over the samples of the last `averaging_fraction` of the run.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "cases/suspension_packing.hpp"
#include "cases/wall_repulsion.hpp"
#include "contact/cell_repulsion.hpp"
#include "coupling/coupled_simulation.hpp"
#include "membrane/parameters.hpp"
#include "mesh/triangle_mesh.hpp"
#include "units/unit_converter.hpp"

namespace rbcsim::cases {

struct SuspensionSettings {
  double tube_diameter_um = 0.0;
  double tube_length_um = 0.0;
  // What the pressure gradient would drive through the tube without cells (mean velocity).
  double plasma_mean_velocity_m_per_s = 0.0;
  double duration_s = 0.0;
  double sample_interval_s = 0.0;
  double averaging_fraction = 0.5;  // of the run, at its end
  std::size_t profile_rings = 10;   // of the hematocrit profile (suspension_profile.hpp)
  double wall_repulsion_pN_per_um2 = 20.0;
  double wall_repulsion_range_um = 0.5;
  WallLaw wall_law = WallLaw::pressure;  // suspension.wall_law (wall_repulsion.hpp)
  // The surface law, acting over 1 um: the width of the phi2 kernel at dx 0.5 um, so that the
  // fluid can still part two membranes where the push is strong (docs/physics.md, "Suspensions":
  // over 0.75 um, within the kernel, the pushed membranes folded, and the vertex law let them
  // through). Its cap: the membrane's own vertex force cap (MembraneParameters::
  // vertex_force_cap_pN, HemoCell's 50 pN), so that a contact push alone never exceeds what a
  // vertex may carry.
  contact::ContactParameters contact{5.0, 1.0, contact::ContactLaw::surface, 50.0};
  PackingSettings packing;
  // Cells packed below their size (packing.scale < 1) grow to it over this time from the release
  // (coupling/cell_growth.hpp); it must end before the averaging window starts.
  double growth_time_s = 0.005;
  // Cells placed by hand (suspension.cells): one pose per cell, instead of the packing.
  std::vector<CellPose> placed_cells;
  double fluid_tolerance = 1e-6;
  std::size_t fluid_max_steps = 200000;
};

// One kind of cell in the suspension: its name, stress-free mesh and membrane (each morphology
// has its own Table 2 stiffnesses).
struct SuspensionMorphology {
  std::string name;
  mesh::TriangleMesh mesh;
  membrane::MembraneParameters membrane;
};

struct SuspensionPhysics {
  lattice::FluidParameters fluid;
  coupling::CouplingParameters coupling;
  units::UnitConverter units;
};

struct SuspensionSample {
  double time_s = 0.0;
  double flow_rate_um3_per_s = 0.0;
  double relative_apparent_viscosity = 0.0;
  double tube_hematocrit = 0.0;
  double discharge_hematocrit = 0.0;
  double cell_free_layer_um = 0.0;
  double populated_bin_fraction = 0.0;  // of the (x, angle) bins the layer is measured over
  std::size_t contact_pairs = 0;        // ordered vertex pairs of different cells within the range
  std::size_t close_contact_pairs = 0;
  // Cells with a vertex inside another cell (find_pierced_cells): surfaces that passed through
  // each other, which the contact is there to prevent.
  std::size_t pierced_cells = 0;
  // The volume fraction of cells in each of SuspensionSettings::profile_rings rings of equal
  // width about the axis, the first innermost (suspension_profile.hpp).
  std::vector<double> volume_fraction_by_ring;
};

struct SuspensionCellSample {
  double time_s = 0.0;
  std::size_t cell = 0;
  Vec3 centroid_um = Vec3::Zero();
  double radial_position_um = 0.0;
  double velocity_x_m_per_s = 0.0;
  double deformation_index = 0.0;
};

// Where the cells of one morphology were over the averaging window, averaged over their samples:
// whether a kind marginates (radial position) or lags (axial velocity) in a mixture.
struct MorphologyAverages {
  std::size_t cell_samples = 0;
  double radial_position_um = 0.0;
  double velocity_x_m_per_s = 0.0;
  double deformation_index = 0.0;
};

struct SuspensionAverages {
  std::size_t samples = 0;
  double relative_apparent_viscosity = 0.0;
  double relative_apparent_viscosity_sd = 0.0;
  double tube_hematocrit = 0.0;
  double discharge_hematocrit = 0.0;
  double cell_free_layer_um = 0.0;
  std::vector<double> volume_fraction_by_ring;  // the hematocrit profile
  std::vector<MorphologyAverages> by_morphology;  // indexed as the morphologies
};

struct SuspensionRun {
  std::vector<std::size_t> cell_morphologies;  // per cell, an index into the morphologies
  double packed_hematocrit = 0.0;
  std::size_t packing_iterations = 0;
  double plasma_flow_rate_um3_per_s = 0.0;
  double pressure_gradient_Pa_per_m = 0.0;
  double pseudo_shear_rate_per_s = 0.0;  // plasma mean velocity / diameter
  std::size_t fluid_settling_steps = 0;
  std::vector<SuspensionSample> samples;
  std::vector<SuspensionCellSample> cell_samples;
  SuspensionAverages averages;
  std::size_t steps = 0;
  double time_s = 0.0;
  std::size_t close_contact_steps = 0;
  std::size_t capped_contact_steps = 0;  // steps with a push held at the contact's force cap
  std::size_t samples_with_pierced_cells = 0;
  std::vector<std::size_t> force_capped_steps;  // per cell
  coupling::StepPhaseTimes phase_times;         // of the coupled steps (not the plasma's settling)
  coupling::SubSpacingDragSummary sub_spacing_drag;
  std::string stop_reason;
  std::string failure;
  bool interrupted = false;
  bool ok() const { return failure.empty(); }
};

using SuspensionConfigure = std::function<void(coupling::CoupledSimulation&)>;

// `cell_morphologies` holds one index into `morphologies` per cell. Throws InputError for bad
// settings, a tube the cells cannot be packed into, or a flow beyond the lattice's Mach limit;
// runtime failures end the run with SuspensionRun::failure set.
SuspensionRun run_suspension(std::span<const SuspensionMorphology> morphologies,
                             std::span<const std::size_t> cell_morphologies,
                             const SuspensionPhysics& physics, const SuspensionSettings& settings,
                             const SuspensionConfigure& configure = {});

// Cells packed below their size (packing_scale < 1) grow in the flow: InputError naming
// suspension.growth_time_s for a growth that is not positive or that ends after
// `window_start_s`, when the averages start (`length_option` names what sets the run's length).
void require_growth_before_window(double packing_scale, double growth_time_s, double window_start_s,
                                  const char* length_option);
// The growth of cells packed at `packing_scale` over `growth_time_s` (at least one step), in the
// run's steps; none at a scale of 1.
coupling::CellGrowth cell_growth_for(const units::UnitConverter& units, double packing_scale,
                                     double growth_time_s);

// Throws InputError naming suspension.contact_range_um when the range is shorter than the longest
// membrane edge of a morphology: a vertex could pass between another cell's vertices
// (cell_repulsion.hpp).
void require_contact_reaches_across_edges(std::span<const SuspensionMorphology> morphologies,
                                          double range_um);

// The walls' push on every cell (wall_repulsion.hpp): `per_um2.force_at_wall_pN` is a pressure
// (pN/um^2), each cell's push at contact that pressure times its morphology's area per vertex;
// `wall` tells where a point lies from the walls.
using SuspensionWall = std::function<WallDistance(const Vec3& position_um)>;
void add_suspension_walls(coupling::CoupledSimulation& simulation,
                          std::span<const SuspensionMorphology> morphologies,
                          std::span<const std::size_t> cell_morphologies,
                          const WallRepulsion& per_um2, const SuspensionWall& wall);

// Runs the simulation to its stop: its stop reason, or the failure that ended it (a runtime
// failure, or an interruption, which also sets `interrupted`). What both suspensions report.
struct SuspensionEnd {
  std::string stop_reason;
  std::string failure;
  bool interrupted = false;
};
SuspensionEnd run_to_end(coupling::CoupledSimulation& simulation);

// The number of cells of each morphology that fills a lumen of volume_um3 to `hematocrit` with
// number fractions `fractions` (summing to 1): N = round(H V / sum_m f_m V_m) cells, split by
// largest remainders. Throws InputError naming suspension.hematocrit when N is 0.
std::vector<std::size_t> cell_counts_for(double hematocrit, double lumen_volume_um3,
                                         std::span<const double> fractions,
                                         std::span<const double> cell_volumes_um3);

// How far the flow carried the cells: the mean over the cells of the distance along the axis (x)
// between a cell's centroid at its first sample and at its last. Centroids travel
// unwrapped along the periodic axis, so a cell that crossed the period counts its whole way.
// A suspension released from a packing develops (the cells migrate to the axis, the cell-free
// layer forms) only after the flow has carried it 25-50 tube diameters (Chien, Gompper & Fedosov,
// arXiv:2003.09217); the report compares with Pries et al. only beyond that. 0 without samples.
double mean_cell_travel_um(std::span<const SuspensionCellSample> samples);

// The cells' samples from (1 - fraction) end_s on (the window of the flow's averages), averaged
// per morphology (cell_morphologies: each cell's index among morphology_count).
std::vector<MorphologyAverages> morphology_averages(std::span<const SuspensionCellSample> samples,
                                                    std::span<const std::size_t> cell_morphologies,
                                                    std::size_t morphology_count, double end_s,
                                                    double fraction);

}  // namespace rbcsim::cases
