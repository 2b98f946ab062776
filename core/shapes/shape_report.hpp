// What `rbcsim mesh generate --json` says of an energy-minimised shape beside `mesh info`'s
// figures: each energy term, the realised area difference, the morphology measures
// (shape_analysis.hpp) and how the minimisation went. Member names carry their units.
#pragma once

#include <nlohmann/json.hpp>

#include "mesh/triangle_mesh.hpp"
#include "shapes/energy_shape.hpp"

namespace rbcsim::shapes {

// Spicules, invagination and the distance from Evans-Fung of any closed mesh.
nlohmann::ordered_json morphology_json(const mesh::TriangleMesh& mesh);

// The bilayer-couple energies of `mesh` (generated at `subdivisions`, so on the icosphere's
// connectivity, against the skeleton reference `settings` make at that level), pN um and in units
// of a sphere's bending energy 8 pi kappa, and the realised reduced area difference.
nlohmann::ordered_json energy_json(const mesh::TriangleMesh& mesh, int subdivisions,
                                   const EnergyShapeSettings& settings);

// Trials (seed, iterations, converged, largest force, seconds, total energy) and the winner.
nlohmann::ordered_json minimisation_json(const EnergyShape& shape);

// What redistributing the minimum's vertices changed (EnergyShape::redistribution).
nlohmann::ordered_json redistribution_json(const Redistribution& redistribution);

}  // namespace rbcsim::shapes
