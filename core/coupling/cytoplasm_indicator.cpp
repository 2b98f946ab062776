#include "coupling/cytoplasm_indicator.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"

namespace rbcsim::coupling {
namespace {

// Calls visit(grid node, box index) for every node of `box` that exists in `grid`, box order.
template <class Visit>
void for_each_grid_node(const ibm::GridView& grid, const ibm::NodeBox& box, Visit&& visit) {
  std::size_t n = 0;
  for (int k = 0; k < box.count[2]; ++k) {
    for (int j = 0; j < box.count[1]; ++j) {
      for (int i = 0; i < box.count[0]; ++i, ++n) {
        std::size_t node = 0;
        if (ibm::grid_node_of(grid, box, i, j, k, node)) visit(node, n);
      }
    }
  }
}

std::string positions_name(std::size_t cell) {
  return "cytoplasm.cell " + std::to_string(cell) + ".positions_lu";
}

}  // namespace

bool CytoplasmIndicator::update(std::span<const Cell> cells, const ibm::GridView& grid,
                                std::span<lattice::ViscosityClass> classes) {
  bool rewritten = false;
  if (restored_) {
    recompute(cells, grid, classes);  // from the restored positions
    restored_ = false;
    rewritten = true;
  }
  if (!due(cells)) return rewritten;
  computed_at_.resize(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const auto positions = cells[c].positions_lu();
    computed_at_[c].assign(positions.begin(), positions.end());
  }
  recompute(cells, grid, classes);
  return true;
}

bool CytoplasmIndicator::due(std::span<const Cell> cells) const {
  if (update_displacement_lu_ <= 0.0 || computed_at_.size() != cells.size()) return true;
  const double limit_squared = update_displacement_lu_ * update_displacement_lu_;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const auto positions = cells[c].positions_lu();
    for (std::size_t v = 0; v < positions.size(); ++v) {
      if ((positions[v] - computed_at_[c][v]).squaredNorm() >= limit_squared) return true;
    }
  }
  return false;
}

void CytoplasmIndicator::recompute(std::span<const Cell> cells, const ibm::GridView& grid,
                                   std::span<lattice::ViscosityClass> classes) {
  surfaces_.resize(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    surfaces_[c].compute(computed_at_[c], cells[c].model().triangles(), half_width_);
  }
  // Serial over the boxes' nodes (bytes, a few thousand per cell): a box wider than a periodic
  // grid would reach one node twice, which a parallel loop could not allow.
  for (const ibm::NodeBox& box : written_) {
    for_each_grid_node(grid, box, [&](std::size_t node, std::size_t) { classes[node] = 0; });
  }
  written_.clear();
  for (const ibm::SurfaceIndicator& surface : surfaces_) {
    const auto values = surface.values();
    for_each_grid_node(grid, surface.box(), [&](std::size_t node, std::size_t n) {
      classes[node] = std::max(classes[node], lattice::viscosity_class(values[n]));
    });
    written_.push_back(surface.box());
  }
}

void CytoplasmIndicator::save_state(StateArchive& archive) const {
  archive.put("cytoplasm.cells", {static_cast<double>(computed_at_.size())});
  for (std::size_t c = 0; c < computed_at_.size(); ++c) {
    archive.put(positions_name(c), computed_at_[c]);
  }
}

void CytoplasmIndicator::restore_state(StateArchive& archive, std::span<const Cell> cells) {
  const double count = archive.take_number("cytoplasm.cells");
  if (count != 0.0 && count != static_cast<double>(cells.size())) {
    throw InputError(archive.source(), "cytoplasm.cells does not match the simulation's " +
                                           std::to_string(cells.size()) + " cells");
  }
  computed_at_.assign(static_cast<std::size_t>(count), {});
  for (std::size_t c = 0; c < computed_at_.size(); ++c) {
    computed_at_[c].resize(cells[c].vertex_count());
    archive.take(positions_name(c), computed_at_[c]);
  }
  restored_ = !computed_at_.empty();
}

}  // namespace rbcsim::coupling
