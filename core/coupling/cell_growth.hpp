// Cells that start smaller than their stress-free size and grow to it in the flow
// (CoupledSimulation::grow_cells; docs/physics.md, "Suspensions"). A rigid packing cannot place
// cells at a blood-like hematocrit in a capillary (nine discocytes in a 10 x 30 um tube come clear
// only at 0.85 of their size), because real cells there are not their resting shape. So the cells
// are packed at `start_scale` of their size, and over `steps` lattice steps their membrane's
// reference (every length, area and the volume) rises linearly to full size while the flow,
// the contact and the walls shape them: the cells find their crowded shapes by their own
// mechanics instead of a packer's rigid moves.
//
// The reference changes in stages of at most kGrowthStageScale (a strain of 0.1 % per stage,
// small against the deformations of the flow), and the last stage is the cell's own reference,
// unchanged: once grown, a cell is the one a full-size start builds. The cell's shape follows the
// scale continuously: every step its vertices are scaled about its centroid by the step's growth,
// after the flow has moved them. A volume term or hold alone would not do: pushed along its
// normals by the volume's gradient a cell rounds out and its triangles strain, and the paper's
// local area law failed (at 162 vertices, dx 1 um) a third of the way.
#pragma once

#include <cstddef>

namespace rbcsim::coupling {

inline constexpr double kGrowthStageScale = 1e-3;

struct CellGrowth {
  double start_scale = 1.0;  // of the full size, in (0, 1]; 1: no growth
  std::size_t steps = 0;     // lattice steps from start_scale to full size
};

// Throws std::invalid_argument for a start scale outside (0, 1], or below 1 with no steps.
void require_valid(const CellGrowth& growth);
// The stages of the growth: the last one (stage_count) is full size.
std::size_t growth_stage_count(const CellGrowth& growth);
// The stage the reference is at during step `step` (0 at the start, growth_stage_count from
// `steps` on).
std::size_t growth_stage(const CellGrowth& growth, std::size_t step);
// The scale of stage `stage` (exactly 1 at the last).
double growth_stage_scale(const CellGrowth& growth, std::size_t stage);
// The continuous scale after `step` steps: start_scale + (1 - start_scale) min(1, step / steps).
double growth_scale(const CellGrowth& growth, std::size_t step);

}  // namespace rbcsim::coupling
