// Where the cytoplasm is (docs/physics.md, "Cytoplasm viscosity"): keeps the fluid's per-node
// viscosity classes (lattice/collision.hpp) on the interiors of the cells. A recomputation finds
// every cell's smoothed inside indicator H (ibm/inside_indicator.hpp) from its vertex positions and
// writes class(max over cells of H) at the nodes around the cells; nodes that were around a cell at
// the previous recomputation and are not any more go back to class 0 (plasma). The maximum makes
// the result independent of the order of the cells.
//
// Cadence: a recomputation costs about as much as a fluid step of a small box
// (docs/performance.md), so it is done only once some vertex has moved `update_displacement_lu` or
// more since the last one (0: every step). H has slope at most 1/eps, so the classes then lag the
// membrane by less than update_displacement / eps in H. The decision depends on positions only,
// hence not on the thread count; the positions of the last recomputation go into checkpoints, so a
// resumed run recomputes the same classes and recomputes again at the same steps.
#pragma once

#include <span>
#include <vector>

#include "common/state_archive.hpp"
#include "common/vec3.hpp"
#include "coupling/cell.hpp"
#include "ibm/grid_view.hpp"
#include "ibm/inside_indicator.hpp"
#include "lattice/collision.hpp"

namespace rbcsim::coupling {

class CytoplasmIndicator {
 public:
  // `half_width`: the smoothing half width eps in lattice spacings (the IBM kernel's support / 2).
  CytoplasmIndicator(double half_width, double update_displacement_lu)
      : half_width_(half_width), update_displacement_lu_(update_displacement_lu) {}

  // Before a fluid step: recomputes `classes` (one per node of `grid`) if it is due, or if a
  // restore_state left them to be rewritten. Returns whether it wrote them.
  bool update(std::span<const Cell> cells, const ibm::GridView& grid,
              std::span<lattice::ViscosityClass> classes);

  // The positions of the last recomputation (checkpoint.hpp). restore_state throws InputError
  // naming the archive for arrays that do not fit `cells`; the classes are rewritten from the
  // restored positions at the next update.
  void save_state(StateArchive& archive) const;
  void restore_state(StateArchive& archive, std::span<const Cell> cells);

 private:
  bool due(std::span<const Cell> cells) const;
  void recompute(std::span<const Cell> cells, const ibm::GridView& grid,
                 std::span<lattice::ViscosityClass> classes);

  double half_width_;
  double update_displacement_lu_;
  std::vector<std::vector<Vec3>> computed_at_;  // per cell, the positions of the last recomputation
  bool restored_ = false;                       // classes still to be rewritten from computed_at_
  std::vector<ibm::SurfaceIndicator> surfaces_;  // one per cell, reused
  std::vector<ibm::NodeBox> written_;            // the boxes the latest recomputation wrote
};

}  // namespace rbcsim::coupling
