#include "contact/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rbcsim::contact {

void CellList::build(std::span<const Vec3> points_um, double reach_um, const PeriodicBox& box,
                     std::span<const std::uint32_t> groups) {
  if (!(reach_um > 0.0)) throw std::invalid_argument("cell list: the reach must be > 0");
  if (!groups.empty() && groups.size() != points_um.size()) {
    throw std::invalid_argument("cell list: one group per point");
  }
  for (std::size_t p = 1; p < groups.size(); ++p) {
    if (groups[p] < groups[p - 1]) {
      throw std::invalid_argument("cell list: the points must be grouped cell by cell");
    }
  }
  exact_shifts_ = true;
  for (int axis = 0; axis < 3; ++axis) {
    const double period = box.length_um[axis];
    periodic_[axis] = period > 0.0;
    period_um_[axis] = period;
    if (periodic_[axis]) {
      if (period < reach_um) {
        throw std::invalid_argument("cell list: a period shorter than the reach");
      }
      bins_per_axis_[axis] = static_cast<int>(std::floor(period / reach_um));
      origin_um_[axis] = 0.0;
      side_um_[axis] = period / bins_per_axis_[axis];
      exact_shifts_ = exact_shifts_ && bins_per_axis_[axis] >= 3;
      continue;
    }
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (const Vec3& point : points_um) {
      low = std::min(low, point[axis]);
      high = std::max(high, point[axis]);
    }
    if (points_um.empty()) low = high = 0.0;
    origin_um_[axis] = low;
    side_um_[axis] = reach_um;
    bins_per_axis_[axis] = std::max(1, static_cast<int>(std::floor((high - low) / reach_um)) + 1);
  }
  const std::size_t bins = static_cast<std::size_t>(bins_per_axis_[0]) * bins_per_axis_[1] *
                           static_cast<std::size_t>(bins_per_axis_[2]);
  wrapped_um_.assign(points_um.begin(), points_um.end());
  for (Vec3& point : wrapped_um_) {
    for (int axis = 0; axis < 3; ++axis) {
      if (periodic_[axis])
        point[axis] -= period_um_[axis] * std::floor(point[axis] / period_um_[axis]);
    }
  }
  // A counting sort: points enter their bin in increasing index.
  std::vector<std::size_t> bin_of(points_um.size());
  bin_start_.assign(bins + 1, 0);
  for (std::size_t p = 0; p < points_um.size(); ++p) {
    const auto c = bin_coordinates(points_um[p]);
    bin_of[p] =
        (static_cast<std::size_t>(c[2]) * bins_per_axis_[1] + static_cast<std::size_t>(c[1])) *
            bins_per_axis_[0] +
        static_cast<std::size_t>(c[0]);
    ++bin_start_[bin_of[p] + 1];
  }
  for (std::size_t b = 0; b < bins; ++b) bin_start_[b + 1] += bin_start_[b];
  bin_points_.resize(points_um.size());
  std::vector<std::uint32_t> fill(bin_start_.begin(), bin_start_.end() - 1);
  for (std::size_t p = 0; p < points_um.size(); ++p) {
    bin_points_[fill[bin_of[p]]++] = static_cast<std::uint32_t>(p);
  }
  // Runs of one group within each bin (its points are in increasing index, so in group order).
  run_start_.assign(bins + 1, 0);
  runs_.clear();
  for (std::size_t b = 0; b < bins; ++b) {
    for (std::uint32_t k = bin_start_[b]; k < bin_start_[b + 1]; ++k) {
      const std::uint32_t group = groups.empty() ? 0 : groups[bin_points_[k]];
      if (k == bin_start_[b] || runs_.back().group != group) runs_.push_back({group, k, k});
      runs_.back().end = k + 1;
    }
    run_start_[b + 1] = static_cast<std::uint32_t>(runs_.size());
  }
}

std::array<int, 3> CellList::bin_coordinates(const Vec3& point_um) const {
  std::array<int, 3> coordinates{};
  for (int axis = 0; axis < 3; ++axis) {
    const int bins = bins_per_axis_[axis];
    const int raw =
        static_cast<int>(std::floor((point_um[axis] - origin_um_[axis]) / side_um_[axis]));
    coordinates[axis] =
        periodic_[axis] ? ((raw % bins) + bins) % bins : std::clamp(raw, 0, bins - 1);
  }
  return coordinates;
}

CellList::Neighbours CellList::neighbours_of_bin(std::size_t b) const {
  const auto nx = static_cast<std::size_t>(bins_per_axis_[0]);
  const auto ny = static_cast<std::size_t>(bins_per_axis_[1]);
  return neighbours_of_coordinates(
      {static_cast<int>(b % nx), static_cast<int>((b / nx) % ny), static_cast<int>(b / (nx * ny))});
}

CellList::Neighbours CellList::neighbours_of_coordinates(const std::array<int, 3>& centre) const {
  // Per axis the distinct bin coordinates within one bin of the centre's (fewer than three when
  // the axis has fewer bins, so that no bin is visited twice), ascending.
  std::array<std::array<int, 3>, 3> along{};
  std::array<std::array<double, 3>, 3> shift{};  // periods to add along each axis
  std::array<int, 3> count{};
  for (int axis = 0; axis < 3; ++axis) {
    const int bins = bins_per_axis_[axis];
    for (int offset = -1; offset <= 1; ++offset) {
      int coordinate = centre[axis] + offset;
      double periods = 0.0;
      if (periodic_[axis]) {
        periods = coordinate < 0 ? -1.0 : coordinate >= bins ? 1.0 : 0.0;
        coordinate = ((coordinate % bins) + bins) % bins;
      } else if (coordinate < 0 || coordinate >= bins) {
        continue;
      }
      const auto end = along[axis].begin() + count[axis];
      if (std::find(along[axis].begin(), end, coordinate) == end) {
        shift[axis][count[axis]] = periods * period_um_[axis];
        along[axis][count[axis]++] = coordinate;
      }
    }
    // Ascending (at most three values; std::sort here trips GCC 12's -Warray-bounds).
    auto& values = along[axis];
    for (int a = 1; a < count[axis]; ++a) {
      for (int b = a; b > 0 && values[b - 1] > values[b]; --b) {
        std::swap(values[b - 1], values[b]);
        std::swap(shift[axis][b - 1], shift[axis][b]);
      }
    }
  }
  Neighbours neighbours;
  for (int k = 0; k < count[2]; ++k) {
    for (int j = 0; j < count[1]; ++j) {
      for (int i = 0; i < count[0]; ++i) {
        neighbours.shift_um[neighbours.count] = Vec3(shift[0][i], shift[1][j], shift[2][k]);
        neighbours.bins[neighbours.count++] =
            (static_cast<std::size_t>(along[2][k]) * bins_per_axis_[1] +
             static_cast<std::size_t>(along[1][j])) *
                bins_per_axis_[0] +
            static_cast<std::size_t>(along[0][i]);
      }
    }
  }
  return neighbours;
}

}  // namespace rbcsim::contact
