#include "common/registry.hpp"
#include "config/options/option_areas.hpp"
#include "coupling/coupled_simulation.hpp"
#include "lattice/boundaries.hpp"
#include "lattice/collision.hpp"
#include "lattice/fluid_kernel.hpp"

namespace rbcsim::config {

void add_lattice_options(OptionTable& table) {
  // dx = 0.5 um against the 2562-vertex cell's ~0.25 um edges gives the paper's S = 0.5.
  table.add_number("lattice.spacing_um", "um", 0.5, "Lattice spacing dx.").above(0.0);
  table
      .add_number("lattice.relaxation_time", "", 1.0,
                  "Relaxation time tau; fixes dt = (tau - 1/2)/3 dx^2/nu.")
      .above(0.5);
  // TRT by default: with Lambda = 3/16 the bounce-back walls sit exactly half-way whatever tau,
  // so the wall position (and a capillary's diameter) does not depend on the viscosity.
  table.add_choice("lattice.collision", entry_names(lattice::collision_models()), "trt",
                   "Collision operator: single (BGK) or two relaxation times (TRT).");
  // Half-way by default: exact mass conservation. Bouzidi places curved walls at their true
  // position (pipe Poiseuille 0.2 % instead of 2.4 % at 20 nodes) but leaks ~1e-8 of the mass
  // per step, quadratic in the velocity (tests/lattice).
  table.add_choice("lattice.wall_rule", entry_names(lattice::wall_rules()), "halfway",
                   "Wall rule: half-way bounce-back (staircase walls) or Bouzidi interpolated "
                   "bounce-back (walls at their exact position).");
  // 3/16 puts half-way bounce-back walls exactly half-way between nodes for Poiseuille flow.
  table
      .add_number("lattice.trt_magic", "", 0.1875,
                  "TRT magic parameter Lambda = (tau+ - 1/2)(tau- - 1/2).")
      .above(0.0);
  table.add_choice("lattice.kernel", entry_names(lattice::fluid_kernels()), "optimised",
                   "Fluid kernel: the fused optimised one, or the plain reference it is tested "
                   "against (same populations to round-off).");
  table.add_choice("lattice.precision", entry_names(lattice::precisions()), "double",
                   "Population storage: double, or single (floats of f_i - w_i, half the memory "
                   "traffic; optimised kernel only; docs/physics.md, single precision).");
  // Two planes at least: the halo exchange fills two ghost planes from one neighbour.
  table
      .add_integer("lattice.block_planes", "", coupling::CouplingParameters{}.block_planes,
                   "Under mpirun: the lattice is cut into blocks of this many z-planes, dealt to "
                   "the processes by their fluid nodes (docs/architecture.md, across processes); "
                   "results do not depend on it or on the process count.")
      .at_least(2);
}

}  // namespace rbcsim::config
