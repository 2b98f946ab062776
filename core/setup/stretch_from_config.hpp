// stretch.* options -> cases::StretchSettings, and the embedded reference data of the stretch
// experiment (share/reference/mills2004_stretch.csv).
#pragma once

#include <string_view>
#include <vector>

#include "cases/stretch_case.hpp"
#include "cases/stretch_reference.hpp"
#include "config/config.hpp"
#include "io/csv_table.hpp"

namespace rbcsim::setup {

// A CSV file of share/reference/ as embedded in the binary (source "share/reference/<name>").
io::CsvTable embedded_reference_table(std::string_view file_name);

// Mills et al. (2004), Fig. 8.
std::vector<cases::StretchReferencePoint> mills2004_stretch_reference();

// The forces of a stretch.forces_pN text: "mills2004" for the reference forces, else a range
// list (config/range.hpp; "start:stop" alone means 9 values, every 25 pN over 0:200). Errors name
// `source`. Negative forces are rejected (the tweezers pull).
std::vector<double> stretch_forces_from(std::string_view text, std::string_view source);

// Throws InputError for a bad stretch.forces_pN. The fluid mode's output_directory stays empty:
// the run directory is the caller's.
cases::StretchSettings stretch_settings_from(const config::Config& config);

// "Cell larger than the domain" for the fluid mode: the resting `cell` (prepared for the stretch)
// against its periodic box (cases::stretch_box). InputError naming stretch.fluid.box_margin_um
// and lattice.spacing_um and the sizes in um; nothing to check in the quasi-static mode.
void require_cell_fits_stretch_box(const mesh::TriangleMesh& cell,
                                   const cases::StretchSettings& settings);

}  // namespace rbcsim::setup
