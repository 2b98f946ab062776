// The suspension experiment (`rbcsim capillary --geometry tube --hematocrit H`) from a config: its
// settings, its morphologies (each with its own overlay: mesh and Table 2 stiffnesses), the
// number of cells of each, and its low-Reynolds time-scale compression.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cases/sheared_suspension.hpp"
#include "cases/suspension_case.hpp"
#include "config/config.hpp"

namespace rbcsim::setup {

// suspension.mix parsed: names (morphologies, in the order given) and number fractions. Empty
// mix: the configured morphology alone. Throws InputError naming suspension.mix for an unknown
// morphology, a repeated one, a fraction outside (0, 1] or fractions not summing to 1 (within
// 1e-6). With suspension.cells, the kinds of the placed cells in order of appearance, each a
// morphology with, where a cell names one, its mesh file (placed_kind_name).
struct SuspensionMix {
  std::vector<std::string> names;  // as reported: placed_kind_name
  std::vector<double> fractions;
  std::vector<std::string> morphologies;  // each kind's membrane (and shape without a file)
  std::vector<std::string> mesh_files;    // each kind's mesh file; empty: the morphology's shape
};
SuspensionMix suspension_mix_from(const config::Config& config);
// "discocyte", or "discocyte (cells/bent.stl)" for a cell of that mesh file.
std::string placed_kind_name(const config::CellPlacement& cell);

// One index into the mix's morphologies per cell: packed, `hematocrit` of `volume_um3` by the mix's
// number fractions (cases::cell_counts_for), morphology after morphology.
std::vector<std::size_t> packed_cell_kinds(
    std::span<const cases::SuspensionMorphology> morphologies, const SuspensionMix& mix,
    double volume_um3, double hematocrit);
// The same for cells placed by hand (suspension.cells), in their order.
std::vector<std::size_t> placed_cell_kinds(const SuspensionMix& mix,
                                           const std::vector<config::CellPlacement>& placed);

cases::SuspensionSettings suspension_settings_from(const config::Config& config);

// The sheared suspension (`rbcsim shear --hematocrit H`) at one simulated rate: the gap
// shear.gap_diameters and the periodic length and width shear.width_diameters times
// `diameter_um` (the largest cell's), the interactions as the tube's.
cases::ShearedSuspensionSettings sheared_suspension_settings_from(const config::Config& config,
                                                                  double diameter_um,
                                                                  double simulated_rate_per_s);

// A notice when suspension.contact_range_um is shorter than the immersed-boundary kernel's width
// (ibm.kernel's support times lattice.spacing_um): two membranes the contact holds closer than
// that spread into the same fluid nodes, their equal and opposite pushes largely cancel there,
// and in a 10 um tube the push then folded a membrane or let it through (docs/validation.md).
std::optional<std::string> contact_range_notice(const config::Config& config);

// Each kind of the mix resolved from `request` with its own --morphology (and mesh.file where it
// has one): mesh and membrane. The repairs made on importing a mesh file, each after its kind's
// name, are appended to `import_notices` when given.
std::vector<cases::SuspensionMorphology> suspension_morphologies_from(
    const config::ConfigRequest& request, const SuspensionMix& mix, double compression_factor,
    std::vector<std::string>* import_notices = nullptr);

// As the capillary's (capillary_from_config.hpp): below suspension.max_reynolds_number the run
// divides the plasma viscosity (and the membrane's) by s and multiplies the drive velocity by s,
// at equal capillary number; every time is divided by s, to be multiplied back in the results.
struct SuspensionCompression {
  double factor = 1.0;
  double physical_reynolds_number = 0.0;
  double simulated_reynolds_number = 0.0;
};
SuspensionCompression suspension_compression_from(const config::Config& config);
config::Config compressed_suspension_config(const config::Config& config, double factor);
// The same for a sheared suspension at `rate_per_s` (shear.viscosity_scaling, up to
// shear.max_reynolds_number, Re = rate R^2 / nu with R half of `diameter_um`); the simulated
// rate is rate x factor, times divided by it as above (compressed_suspension_config).
SuspensionCompression sheared_suspension_compression_from(const config::Config& config,
                                                          double rate_per_s, double diameter_um);
// Times back to physical ones (x s), velocities and flow rates (/ s), the gradient (/ s^2 x s).
void to_physical_units(cases::SuspensionRun& run, double factor);

}  // namespace rbcsim::setup
