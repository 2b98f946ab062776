// membrane.* options -> membrane::MembraneParameters (in the membrane module's pN / um units).
#pragma once

#include <cstddef>

#include "config/config.hpp"
#include "membrane/parameters.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::setup {

membrane::MembraneParameters membrane_parameters_from(const config::Config& config);

// The factor k_link and k_area are scaled by on a cell mesh of triangle_count triangles:
// sqrt(membrane.network_calibrated_triangle_count / triangle_count), the mesh's mean edge length
// over the calibrated resolution's, or 1 when that option is 0. The link spring (Eq. 6) and the
// area term (Eq. 8) are each a stiffness per edge length (docs/physics.md, "Calibration"), so the
// scaled k keep the calibrated shear and area moduli.
double network_stiffness_scale(const config::Config& config, std::size_t triangle_count);

// membrane_parameters_from for the cells of a run on this mesh, k_link and k_area scaled as above.
// The paper calibrates both "according to the specific mesh resolution" (section 2.4): Table 2's
// are for its 2562-vertex cell, and a coarser mesh needs larger ones for the same moduli.
membrane::MembraneParameters cell_membrane_parameters_from(const config::Config& config,
                                                           const mesh::TriangleMesh& cell);

}  // namespace rbcsim::setup
