// The fluid's drag on membrane modes finer than the lattice (`ibm.sub_spacing_drag`;
// docs/physics.md, "Beyond the paper: the drag on sub-spacing modes").
//
// The immersed boundary moves a vertex with the velocity interpolated from the lattice, which
// cannot carry a force pattern that varies within one lattice spacing: neighbouring vertices
// pushed apart spread onto the same nodes and come back with one velocity. A membrane whose edges
// are shorter than the spacing (the paper's 2562 vertices on dx 0.5 um) then has modes, one
// triangle compressed beside stretched ones, that its own forces cannot move back; they drift
// until a triangle reaches a force law's limit (docs/validation.md, "What deforms the triangles").
//
// In Stokes flow a traction f of wavenumber q on a membrane between fluids of viscosities eta_out
// and eta_in moves it at v = f / ((eta_out + eta_in) q) along itself and at half that along its
// normal: on each side the flow decays as exp(-q |z|) and resists with eta q tangentially and
// 2 eta q normally. This adds that response for the part of each vertex's force its edge
// neighbours do not share:
//
//     v_i += (T_i + N_i / 2) / ((eta_out + eta_in) q_i A_i),   q_i = pi / l_i,
//
// T_i and N_i the tangential and normal parts of F_i - <F>_i, <F>_i the mean force of i's edge
// neighbours, l_i the mean length of i's edges (q_i is the shortest mode's, two edges long) and
// A_i the vertex area (a third of its triangles'). A force uniform along the membrane has no such
// part, and one that varies over many edges (what the lattice resolves) one smaller by (q l)^2 / 4
// (on a curved or irregular mesh also by the ring's curvature and irregularity): the resolved flow
// is left to the lattice. On a curved membrane a pressure's normal forces differ from their
// neighbours' mean by (l / 2R)^2 of themselves, which moves the membrane along its normals: with
// `ibm.hold_volume` (as in the physiological preset) the volume's part of that is taken out.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/surface_energies.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::coupling {

class SubSpacingDrag {
 public:
  SubSpacingDrag(std::span<const mesh::Triangle> triangles, const mesh::MeshTopology& topology);

  // Adds the drag's velocities to `velocities` for the vertex forces `forces` at `positions`, in
  // any consistent units (lattice units in the coupled step): `viscosity_sum` is eta_out + eta_in
  // in force x time / length^2 (lattice density times kinematic viscosity). Throws
  // std::invalid_argument for arrays of another length or a viscosity sum that is not positive.
  void add_velocities(std::span<const Vec3> positions, std::span<const Vec3> forces,
                      double viscosity_sum, std::span<Vec3> velocities);

 private:
  membrane::SurfaceMeasures measures_;
  // Copies of the topology's rows (a cell's model, which owns the topology, moves with the cell):
  // the edge neighbours of each vertex, neighbours_[offsets_[v] .. offsets_[v + 1]), and its
  // triangles, triangles_[triangle_offsets_[v] .. triangle_offsets_[v + 1]).
  std::vector<std::int32_t> offsets_;
  std::vector<std::int32_t> neighbours_;
  std::vector<std::int32_t> triangle_offsets_;
  std::vector<std::int32_t> triangles_;
};

// The drag is explicit: a mode of stiffness k relaxes by k dt / drag per step, which must stay
// below 1 (beyond 2 it grows). Its largest rate per unit time at `positions` (the same units as
// add_velocities), by power iteration on the drag applied to the membrane's stiffness:
// `forces_at(x, f)` writes the membrane's forces at positions x into f. Deterministic (a fixed
// seed); about 30 force evaluations.
using ForceFunction = std::function<void(std::span<const Vec3>, std::span<Vec3>)>;
double fastest_drag_rate(SubSpacingDrag& drag, std::span<const Vec3> positions,
                         const ForceFunction& forces_at, double viscosity_sum);

// ibm.sub_spacing_drag as the cells use it: the fastest relaxation per step of the drag at the
// fluids' viscosities over all cells (Cell::sub_spacing_drag_rate), how many cells had it
// raised because theirs exceeded Cell::kMaxDragRatePerStep (their drag is then stronger than the
// fluid's: a numerical damping, not physics), and the largest factor one was raised by
// (Cell::sub_spacing_drag_raised_by; 1 when none was).
struct SubSpacingDragSummary {
  bool on = false;
  double fastest_rate_per_step = 0.0;
  std::size_t raised_cells = 0;
  double viscosity_raised_by = 1.0;
};

}  // namespace rbcsim::coupling
