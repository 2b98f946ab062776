#include "contact/cell_repulsion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rbcsim::contact {

ContactStatistics add_cell_contact_forces(std::span<const Vec3> positions_um,
                                          std::span<const std::uint32_t> owner,
                                          const ContactParameters& parameters,
                                          const PeriodicBox& box, std::span<Vec3> forces_pN,
                                          CellList& workspace) {
  if (owner.size() != positions_um.size() || forces_pN.size() != positions_um.size()) {
    throw std::invalid_argument("cell contact: one owner and one force per position");
  }
  ContactStatistics statistics;
  if (parameters.force_at_contact_pN == 0.0) return statistics;
  const double range = parameters.range_um;
  if (!(range > 0.0)) throw std::invalid_argument("cell contact: the range must be > 0");
  workspace.build(positions_um, range, box, owner);
  const auto points = workspace.points();

  // Bin by bin: a bin whose neighbourhood holds one cell only (most of them: the inside of a
  // membrane patch) is skipped whole; otherwise each of its points sums the pushes of the other
  // cells' points around, in the neighbourhood's fixed order, and writes only its own force.
  const auto bins = static_cast<std::ptrdiff_t>(workspace.bin_count());
  std::size_t pairs = 0;
  std::size_t close = 0;
  double closest = std::numeric_limits<double>::infinity();
#pragma omp parallel reduction(+ : pairs, close) reduction(min : closest)
  {
    std::vector<CellList::Run> around;
    std::vector<Vec3> around_shift_um;  // of each run's bin
#pragma omp for schedule(dynamic, 16)
    for (std::ptrdiff_t signed_b = 0; signed_b < bins; ++signed_b) {
      const auto b = static_cast<std::size_t>(signed_b);
      const auto mine = workspace.bin(b);
      if (mine.empty()) continue;
      around.clear();
      around_shift_um.clear();
      const auto neighbours = workspace.neighbours_of_bin(b);
      bool mixed = false;
      for (std::size_t n = 0; n < neighbours.count; ++n) {
        for (const auto& run : workspace.runs(neighbours.bins[n])) {
          mixed = mixed || run.group != owner[mine[0]];
          around.push_back(run);
          around_shift_um.push_back(neighbours.shift_um[n]);
        }
      }
      if (!mixed) continue;
      const bool exact = workspace.has_exact_shifts();
      for (const std::uint32_t i : mine) {
        const Vec3 position = workspace.wrapped(i);
        Vec3 force = Vec3::Zero();
        for (std::size_t r = 0; r < around.size(); ++r) {
          const auto& run = around[r];
          if (run.group == owner[i]) continue;
          for (std::uint32_t k = run.begin; k < run.end; ++k) {
            const Vec3& other = workspace.wrapped(points[k]);
            // (x_i - x_j) - shift, not x_i - (x_j + shift): the partner computes exactly the
            // negative, (x_j - x_i) + shift, so the pair stays antisymmetric bit for bit.
            const Vec3 separation = exact ? Vec3((position - other) - around_shift_um[r])
                                          : box.minimum_image(position - other);
            const double squared = separation.squaredNorm();
            if (squared >= range * range) continue;
            const double distance = std::sqrt(squared);
            ++pairs;
            if (distance < 0.25 * range) ++close;
            closest = std::min(closest, distance);
            // Coincident vertices have no direction to push along; the stability checks will
            // see them.
            if (distance == 0.0) continue;
            const double closeness = 1.0 - distance / range;
            force += (parameters.force_at_contact_pN * closeness * closeness / distance) *
                     separation;
          }
        }
        forces_pN[i] += force;
      }
    }
  }
  statistics.pairs_in_range = pairs;
  statistics.close_pairs = close;
  statistics.closest_um = closest;
  return statistics;
}

}  // namespace rbcsim::contact
