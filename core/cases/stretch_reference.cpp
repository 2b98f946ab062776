#include "cases/stretch_reference.hpp"

#include <algorithm>
#include <cmath>

namespace rbcsim::cases {
namespace {

// Two forces closer than this (relative) are the same force: a CSV round trip or a range step
// may leave the last digit different.
constexpr double kSameForceTolerance = 1e-9;

struct Diameters {
  double axial_um;
  double transverse_um;
};

// The converged points sorted by force.
std::vector<StretchPoint> converged_by_force(std::span<const StretchPoint> points) {
  std::vector<StretchPoint> sorted;
  std::copy_if(points.begin(), points.end(), std::back_inserter(sorted),
               [](const StretchPoint& point) { return point.converged; });
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const auto& a, const auto& b) { return a.force_pN < b.force_pN; });
  return sorted;
}

std::optional<Diameters> diameters_at(const std::vector<StretchPoint>& sorted, double force_pN) {
  const double slack_pN = kSameForceTolerance * std::max(1.0, std::abs(force_pN));
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (std::abs(sorted[i].force_pN - force_pN) <= slack_pN) {
      return Diameters{sorted[i].axial_um, sorted[i].transverse_um};
    }
    if (i > 0 && sorted[i - 1].force_pN < force_pN && force_pN < sorted[i].force_pN) {
      const auto& low = sorted[i - 1];
      const auto& high = sorted[i];
      const double weight = (force_pN - low.force_pN) / (high.force_pN - low.force_pN);
      return Diameters{low.axial_um + weight * (high.axial_um - low.axial_um),
                       low.transverse_um + weight * (high.transverse_um - low.transverse_um)};
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<StretchReferencePoint> stretch_reference_from(const io::CsvTable& table) {
  const auto forces = table.numbers("force_pN");
  const auto axial = table.numbers("axial_um");
  const auto axial_low = table.numbers("axial_bar_low_um");
  const auto axial_high = table.numbers("axial_bar_high_um");
  const auto transverse = table.numbers("transverse_um");
  const auto transverse_low = table.numbers("transverse_bar_low_um");
  const auto transverse_high = table.numbers("transverse_bar_high_um");
  std::vector<StretchReferencePoint> points;
  for (std::size_t i = 0; i < forces.size(); ++i) {
    points.push_back({forces[i],
                      {axial[i], axial_low[i], axial_high[i]},
                      {transverse[i], transverse_low[i], transverse_high[i]}});
  }
  return points;
}

StretchComparison compare_with_reference(std::span<const StretchPoint> simulated,
                                         std::span<const StretchReferencePoint> reference) {
  const auto sorted = converged_by_force(simulated);
  StretchComparison comparison;
  double axial_squares = 0.0;
  double transverse_squares = 0.0;
  for (const auto& measured : reference) {
    const auto diameters = diameters_at(sorted, measured.force_pN);
    if (!diameters) continue;
    ++comparison.point_count;
    axial_squares += std::pow(diameters->axial_um - measured.axial.mean_um, 2);
    transverse_squares += std::pow(diameters->transverse_um - measured.transverse.mean_um, 2);
    const bool axial_inside = measured.axial.contains(diameters->axial_um);
    const bool transverse_inside = measured.transverse.contains(diameters->transverse_um);
    comparison.axial_inside_error_bar += axial_inside ? 1 : 0;
    comparison.transverse_inside_error_bar += transverse_inside ? 1 : 0;
    comparison.inside_error_bars += axial_inside && transverse_inside ? 1 : 0;
    comparison.misfit += measured.axial.misfit(diameters->axial_um) +
                         measured.transverse.misfit(diameters->transverse_um);
  }
  if (comparison.point_count > 0) {
    const auto count = static_cast<double>(comparison.point_count);
    comparison.rms_axial_um = std::sqrt(axial_squares / count);
    comparison.rms_transverse_um = std::sqrt(transverse_squares / count);
  }
  return comparison;
}

}  // namespace rbcsim::cases
