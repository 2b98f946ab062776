// The stomatocyte-discocyte-echinocyte sequence (the paper's Fig. 1, after Lim 2003): every named
// shape is the bilayer-couple minimum (energy_shape.hpp) at one reduced volume and its own relaxed
// area difference Delta a0, the single parameter that moves a cell along the sequence (Lim, Wortis
// & Mukhopadhyay 2002). ONE table (sequence.cpp) holds the shapes in order, with the Delta a0 each
// is generated at and why (docs/physics.md, "Shapes from membrane mechanics").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/registry.hpp"

namespace rbcsim::shapes {

struct SequenceShape {
  std::string_view name;           // as on the command line: "stomatocyte-II"
  std::string_view description;    // the morphological class (Lim 2003; the paper's Sec. 1)
  double relaxed_area_difference;  // default Delta a0 (mesh.energy.relaxed_area_difference.<name>)
  // Default paths of its minimisation (mesh.energy.paths.<name>; energy_shape.hpp).
  std::vector<std::string> paths;
  // Default seeded starts of each path (mesh.energy.trials.<name>); the lowest minimum wins.
  int trials = 1;
};

// In sequence order, from the most stomatocytic to the most echinocytic.
const Registry<SequenceShape>& shape_sequence();

}  // namespace rbcsim::shapes
