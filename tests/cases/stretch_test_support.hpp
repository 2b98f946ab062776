// Shared by the stretch tests: the shipped discocyte meshes, read as a user's mesh would be, and
// a stretch run that keeps every equilibrium shape with its forces.
#pragma once

#include <string>
#include <vector>

#include "cases/stretch_case.hpp"
#include "mesh/import.hpp"

namespace rbcsim::cases::testing {

// meshes/discocyte_n<level>.stl (level 3: 642 vertices, level 4: 2562, the paper's).
inline mesh::TriangleMesh shipped_discocyte(int level) {
  return mesh::import_mesh(std::string(RBCSIM_SOURCE_DIR) + "/meshes/discocyte_n" +
                           std::to_string(level) + ".stl")
      .mesh;
}

struct ObservedState {
  StretchPoint point;
  std::vector<Vec3> positions_um;
  std::vector<Vec3> membrane_forces_pN;
  std::vector<Vec3> external_forces_pN;
  double membrane_energy_pN_um = 0.0;
};

struct ObservedRun {
  StretchRun run;
  std::vector<ObservedState> states;
};

inline ObservedRun run_and_observe(const membrane::MembraneModel& model, const StretchCell& cell,
                                   const StretchSettings& settings) {
  ObservedRun observed;
  observed.run = run_stretch(model, cell, settings, [&observed](const StretchState& state) {
    observed.states.push_back(
        {state.point,
         {state.positions_um.begin(), state.positions_um.end()},
         state.membrane_forces ? state.membrane_forces->total_pN : std::vector<Vec3>{},
         {state.external_forces_pN.begin(), state.external_forces_pN.end()},
         state.membrane_forces ? state.membrane_forces->total_energy_pN_um() : 0.0});
  });
  return observed;
}

}  // namespace rbcsim::cases::testing
