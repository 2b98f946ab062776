#include "coupling/cell_growth.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rbcsim::coupling {

void require_valid(const CellGrowth& growth) {
  if (!(growth.start_scale > 0.0 && growth.start_scale <= 1.0)) {
    throw std::invalid_argument("cell growth: start scale " + std::to_string(growth.start_scale) +
                                " outside (0, 1]");
  }
  if (growth.start_scale < 1.0 && growth.steps == 0) {
    throw std::invalid_argument("cell growth: a start scale below 1 needs steps to grow over");
  }
}

std::size_t growth_stage_count(const CellGrowth& growth) {
  if (growth.start_scale >= 1.0) return 0;
  // Less a round-off, so that a start of 0.85 takes 150 stages, not 151.
  return static_cast<std::size_t>(std::ceil((1.0 - growth.start_scale) / kGrowthStageScale - 1e-9));
}

std::size_t growth_stage(const CellGrowth& growth, std::size_t step) {
  const std::size_t stages = growth_stage_count(growth);
  if (stages == 0 || step >= growth.steps) return stages;
  // floor(step stages / steps) in integers: the same stage on every machine.
  return step * stages / growth.steps;
}

double growth_stage_scale(const CellGrowth& growth, std::size_t stage) {
  const std::size_t stages = growth_stage_count(growth);
  if (stage >= stages) return 1.0;
  return growth.start_scale +
         (1.0 - growth.start_scale) * static_cast<double>(stage) / static_cast<double>(stages);
}

double growth_scale(const CellGrowth& growth, std::size_t step) {
  if (growth.start_scale >= 1.0 || step >= growth.steps) return 1.0;
  return growth.start_scale +
         (1.0 - growth.start_scale) * static_cast<double>(step) / static_cast<double>(growth.steps);
}

}  // namespace rbcsim::coupling
