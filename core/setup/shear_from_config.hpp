// shear.* options -> cases::ShearSettings, and the medium and engine of a shear run
// (lattice.*, physics.*, ibm.*, stability.*) -> cases::ShearEngine.
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "cases/shear_case.hpp"
#include "config/config.hpp"

namespace rbcsim::setup {

// The rates of a shear.rates_per_s text: a range list (config/range.hpp; "start:stop" alone
// means 5 values). Errors name `source`; negative rates are rejected.
std::vector<double> shear_rates_from(std::string_view text, std::string_view source);

// Throws InputError for bad shear.rates_per_s.
cases::ShearSettings shear_settings_from(const config::Config& config);

// "Cell larger than the domain": `cell` (in the shear frame) against the box of
// cases::shear_box, periodic lengths along x and z, the gap along y. InputError naming the box's
// options and the sizes in um.
void require_cell_fits_shear_box(const mesh::TriangleMesh& cell,
                                 const cases::ShearSettings& settings,
                                 const cases::ShearEngine& engine);

// Failure dumps of each rate go below run_directory (empty: none).
cases::ShearEngine shear_engine_from(const config::Config& config,
                                     const std::filesystem::path& run_directory);

}  // namespace rbcsim::setup
