// Shared by the stretch tests: the shipped discocyte meshes, read as a user's mesh would be, and
// a stretch run that keeps every equilibrium shape with its forces.
#pragma once

#include <gtest/gtest.h>
#include <omp.h>

#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "cases/stretch_case.hpp"
#include "cases/stretch_reference.hpp"
#include "mesh/cell_shapes.hpp"
#include "mesh/import.hpp"

namespace rbcsim::cases::testing {

// meshes/discocyte_n<level>.stl (level 3: 642 vertices, level 4: 2562, the paper's).
// The Evans-Fung discocyte of the parametric generator: exactly axisymmetric and 2 R0 = 7.82 um
// across, which the stretch machinery's tests rely on (the shipped, energy-minimised cell is
// neither exactly).
inline mesh::TriangleMesh evans_fung_discocyte(int level) {
  return mesh::generate_cell("discocyte", level);
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

// What every Validate stretch curve must show and prints against Mills et al. (2004): the axial
// diameter grows and the transverse one shrinks with the force, all 13 forces are compared, and
// the RMS deviations and the points inside the error bars are printed (a finding, not a bound).
// `run_summary` completes the last line (steps, wall time).
inline void expect_and_print_mills_comparison(std::span<const StretchPoint> points,
                                              std::span<const StretchReferencePoint> reference,
                                              const std::string& run_summary) {
  for (std::size_t i = 1; i < points.size(); ++i) {
    EXPECT_GT(points[i].axial_um, points[i - 1].axial_um) << points[i].force_pN;
    EXPECT_LT(points[i].transverse_um, points[i - 1].transverse_um) << points[i].force_pN;
  }
  const auto comparison = compare_with_reference(points, reference);
  EXPECT_EQ(comparison.point_count, 13u);
  std::printf(
      "RMS vs Mills: axial %.3f um, transverse %.3f um; inside the error bars: %zu of 13 "
      "(axial %zu, transverse %zu); %s on %d threads\n",
      *comparison.rms_axial_um, *comparison.rms_transverse_um, comparison.inside_error_bars,
      comparison.axial_inside_error_bar, comparison.transverse_inside_error_bar,
      run_summary.c_str(), omp_get_max_threads());
}

}  // namespace rbcsim::cases::testing
