#include "contact/cell_repulsion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/registry.hpp"

namespace rbcsim::contact {

namespace {

struct NamedContactLaw {
  std::string_view name;
  ContactLaw law;
};
constexpr NamedContactLaw kContactLaws[] = {{"vertex", ContactLaw::vertex},
                                            {"surface", ContactLaw::surface}};

}  // namespace

std::vector<std::string> contact_law_names() { return entry_names(kContactLaws); }

std::string contact_law_name(ContactLaw law) {
  for (const auto& entry : kContactLaws) {
    if (entry.law == law) return std::string(entry.name);
  }
  throw std::logic_error("contact law: not in the table");
}

ContactLaw contact_law_named(std::string_view name) {
  return find_entry(kContactLaws, name, "suspension.contact_law").law;
}

namespace {

// The cells as runs of equal owners, and each one's bounding box around its first vertex by
// minimum images. Throws for owners that are not grouped cell by cell.
void find_cell_boxes(std::span<const Vec3> positions_um, std::span<const std::uint32_t> owner,
                     const PeriodicBox& box, ContactWorkspace& workspace) {
  auto& start = workspace.cell_start;
  start.clear();
  for (std::size_t i = 0; i < owner.size(); ++i) {
    if (i > 0 && owner[i] < owner[i - 1]) {
      throw std::invalid_argument("cell contact: the vertices must be grouped cell by cell");
    }
    if (i == 0 || owner[i] != owner[i - 1]) start.push_back(i);
  }
  start.push_back(owner.size());
  const auto cells = static_cast<std::ptrdiff_t>(start.size() - 1);
  workspace.box_centre_um.resize(start.size() - 1);
  workspace.box_half_um.resize(start.size() - 1);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t signed_c = 0; signed_c < cells; ++signed_c) {
    const auto c = static_cast<std::size_t>(signed_c);
    const Vec3 first = positions_um[start[c]];
    Vec3 low = Vec3::Zero();
    Vec3 high = Vec3::Zero();
    for (std::size_t i = start[c]; i < start[c + 1]; ++i) {
      const Vec3 offset = box.minimum_image(positions_um[i] - first);
      low = low.cwiseMin(offset);
      high = high.cwiseMax(offset);
    }
    workspace.box_centre_um[c] = first + 0.5 * (low + high);
    workspace.box_half_um[c] = 0.5 * (high - low);
  }
}

// Whether a point `offset` from a box's centre (a minimum image) lies within `reach` of a box of
// half-extent `half`, axis by axis (a conservative test: a box, not a rounded box).
bool within_reach(const Vec3& offset, const Vec3& half, double reach) {
  return std::abs(offset.x()) <= half.x() + reach && std::abs(offset.y()) <= half.y() + reach &&
         std::abs(offset.z()) <= half.z() + reach;
}

}  // namespace

// The broad phase: per cell, the other cells whose boxes come within `reach` of its own; then the
// vertices within `reach` of such a neighbour's box, in increasing index.
void select_candidates(std::span<const Vec3> positions_um, std::span<const std::uint32_t> owner,
                       double reach, const PeriodicBox& box, ContactWorkspace& workspace) {
  find_cell_boxes(positions_um, owner, box, workspace);
  const auto& start = workspace.cell_start;
  const auto& centre = workspace.box_centre_um;
  const auto& half = workspace.box_half_um;
  const std::size_t cell_count = start.size() - 1;
  workspace.near_cells.resize(cell_count);
  workspace.is_candidate.assign(positions_um.size(), 0);
  const auto cells = static_cast<std::ptrdiff_t>(cell_count);
#pragma omp parallel for schedule(dynamic, 4)
  for (std::ptrdiff_t signed_a = 0; signed_a < cells; ++signed_a) {
    const auto a = static_cast<std::size_t>(signed_a);
    auto& near = workspace.near_cells[a];
    near.clear();
    for (std::size_t b = 0; b < cell_count; ++b) {
      if (b != a &&
          within_reach(box.minimum_image(centre[a] - centre[b]), half[a] + half[b], reach)) {
        near.push_back(static_cast<std::uint32_t>(b));
      }
    }
    for (std::size_t i = start[a]; i < start[a + 1] && !near.empty(); ++i) {
      for (const std::uint32_t b : near) {
        if (within_reach(box.minimum_image(positions_um[i] - centre[b]), half[b], reach)) {
          workspace.is_candidate[i] = 1;
          break;
        }
      }
    }
  }
  workspace.candidates.clear();
  workspace.candidate_positions_um.clear();
  workspace.candidate_owners.clear();
  for (std::size_t i = 0; i < positions_um.size(); ++i) {
    if (!workspace.is_candidate[i]) continue;
    workspace.candidates.push_back(static_cast<std::uint32_t>(i));
    workspace.candidate_positions_um.push_back(positions_um[i]);
    workspace.candidate_owners.push_back(owner[i]);
  }
}

ContactStatistics add_cell_contact_forces(std::span<const Vec3> positions_um,
                                          std::span<const std::uint32_t> owner,
                                          const ContactParameters& parameters,
                                          const PeriodicBox& box, std::span<Vec3> forces_pN,
                                          ContactWorkspace& workspace) {
  if (owner.size() != positions_um.size() || forces_pN.size() != positions_um.size()) {
    throw std::invalid_argument("cell contact: one owner and one force per position");
  }
  ContactStatistics statistics;
  if (parameters.force_at_contact_pN == 0.0) return statistics;
  const double range = parameters.range_um;
  if (!(range > 0.0)) throw std::invalid_argument("cell contact: the range must be > 0");
  // The broad phase's reach a little beyond the range: the boxes and the pair test round
  // differently, and a kept vertex too many costs nothing.
  select_candidates(positions_um, owner, range * (1.0 + 1e-9) + 1e-12, box, workspace);
  if (workspace.candidates.empty()) return statistics;
  const std::span<const std::uint32_t> kept = workspace.candidates;
  const std::span<const std::uint32_t> kept_owner = workspace.candidate_owners;
  CellList& list = workspace.list;
  list.build(workspace.candidate_positions_um, range, box, kept_owner);
  const auto points = list.points();

  // Bin by bin: a bin whose neighbourhood holds one cell only (most of them: the inside of a
  // membrane patch) is skipped whole; otherwise each of its points sums the pushes of the other
  // cells' points around, in the neighbourhood's fixed order, and writes only its own force.
  const auto bins = static_cast<std::ptrdiff_t>(list.bin_count());
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
      const auto mine = list.bin(b);
      if (mine.empty()) continue;
      around.clear();
      around_shift_um.clear();
      const auto neighbours = list.neighbours_of_bin(b);
      bool mixed = false;
      for (std::size_t n = 0; n < neighbours.count; ++n) {
        for (const auto& run : list.runs(neighbours.bins[n])) {
          mixed = mixed || run.group != kept_owner[mine[0]];
          around.push_back(run);
          around_shift_um.push_back(neighbours.shift_um[n]);
        }
      }
      if (!mixed) continue;
      const bool exact = list.has_exact_shifts();
      for (const std::uint32_t i : mine) {
        const Vec3 position = list.wrapped(i);
        Vec3 force = Vec3::Zero();
        for (std::size_t r = 0; r < around.size(); ++r) {
          const auto& run = around[r];
          if (run.group == kept_owner[i]) continue;
          for (std::uint32_t k = run.begin; k < run.end; ++k) {
            const Vec3& other = list.wrapped(points[k]);
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
            force +=
                (parameters.force_at_contact_pN * closeness * closeness / distance) * separation;
          }
        }
        forces_pN[kept[i]] += force;
      }
    }
  }
  statistics.pairs_in_range = pairs;
  statistics.close_pairs = close;
  statistics.closest_um = closest;
  return statistics;
}

}  // namespace rbcsim::contact
