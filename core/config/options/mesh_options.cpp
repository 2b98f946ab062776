#include "config/options/option_areas.hpp"

namespace rbcsim::config {

void add_mesh_options(OptionTable& table) {
  table.add_string("mesh.file", "",
                   "Cell mesh to import (STL, OBJ, PLY, OFF); empty: generate the morphology's "
                   "built-in shape.");
  // Level 4 is the paper's 2562-vertex cell; level 6 already has 40962 vertices.
  table
      .add_integer("mesh.subdivisions", "", 4,
                   "Icosphere subdivision level of the built-in shape (4: 2562 vertices).")
      .at_least(1)
      .at_most(6);
}

}  // namespace rbcsim::config
