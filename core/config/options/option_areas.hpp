// One function per area of the option table, each defined in its own file beside this one.
// A new area: add its file, declare its function here and list it in kOptionAreas.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "config/option_table.hpp"

namespace rbcsim::config {

// The morphologies: the shapes of the sequence (shapes/sequence.hpp) that have a Table 2 parameter
// set, share/config/<name>.json (the choices of `morphology` and of a cell list).
std::vector<std::string> morphology_choices();

void add_morphology_options(OptionTable& table);
void add_physics_options(OptionTable& table);
void add_lattice_options(OptionTable& table);
void add_ibm_options(OptionTable& table);
void add_membrane_options(OptionTable& table);
void add_mesh_options(OptionTable& table);
void add_output_options(OptionTable& table);
void add_stability_options(OptionTable& table);
void add_stretch_options(OptionTable& table);
void add_shear_options(OptionTable& table);
void add_calibrate_options(OptionTable& table);
void add_capillary_options(OptionTable& table);
void add_suspension_options(OptionTable& table);

using AddOptionArea = void (*)(OptionTable&);
// std::to_array: adding an area does not mean counting them.
inline constexpr auto kOptionAreas = std::to_array<AddOptionArea>({
    add_morphology_options,
    add_physics_options,
    add_lattice_options,
    add_ibm_options,
    add_membrane_options,
    add_mesh_options,
    add_output_options,
    add_stability_options,
    add_stretch_options,
    add_shear_options,
    add_calibrate_options,
    add_capillary_options,
    add_suspension_options,
});

}  // namespace rbcsim::config
