#include "cases/suspension_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace rbcsim::cases {
namespace {

struct Point2 {
  double y, z;
};

double cross(const Point2& u, const Point2& v) { return u.y * v.z - u.z * v.y; }

// The edge function of p against the edge from u to v: > 0 on its left.
double edge_function(const Point2& u, const Point2& v, const Point2& p) {
  return cross({v.y - u.y, v.z - u.z}, {p.y - u.y, p.z - u.z});
}

// Top-left rule for a counter-clockwise triangle: a point exactly on an edge belongs to the
// triangle when the edge is a "top" edge (horizontal, pointing to -y) or a "left" edge (pointing
// to -z). Of the two triangles sharing an edge, which see it in opposite directions, exactly one
// owns it.
bool owns_edge(const Point2& u, const Point2& v) {
  const double dy = v.y - u.y;
  const double dz = v.z - u.z;
  return (dz == 0.0 && dy < 0.0) || dz < 0.0;
}

bool covers(double w, const Point2& u, const Point2& v) {
  return w > 0.0 || (w == 0.0 && owns_edge(u, v));
}

// The grid's lines: their (y, z) and ring.
struct Lines {
  std::size_t per_side = 0;  // lines along y and along z (2 lines_per_radius)
  double spacing_um = 0.0;
  double radius_um = 0.0;
  Point2 at(std::size_t i, std::size_t j) const {
    return {(static_cast<double>(i) + 0.5) * spacing_um - radius_um,
            (static_cast<double>(j) + 0.5) * spacing_um - radius_um};
  }
};

}  // namespace

std::vector<double> radial_volume_fraction(
    std::span<const std::vector<Vec3>> positions_um,
    std::span<const std::span<const mesh::Triangle>> triangles, const RadialProfileGrid& grid) {
  if (!(grid.radius_um > 0.0) || !(grid.length_um > 0.0) || grid.rings == 0 ||
      2 * grid.rings > grid.lines_per_radius) {
    throw std::invalid_argument(
        "radial_volume_fraction: positive sizes and rings <= lines per "
        "radius / 2 (every ring holds a line)");
  }
  const Lines lines{2 * grid.lines_per_radius,
                    grid.radius_um / static_cast<double>(grid.lines_per_radius), grid.radius_um};
  const double ring_width_um = grid.radius_um / static_cast<double>(grid.rings);
  std::vector<double> inside_um(grid.rings, 0.0);
  std::vector<std::size_t> line_counts(grid.rings, 0);
  for (std::size_t i = 0; i < lines.per_side; ++i) {
    for (std::size_t j = 0; j < lines.per_side; ++j) {
      const Point2 p = lines.at(i, j);
      const double r = std::hypot(p.y, p.z);
      if (r < grid.radius_um)
        ++line_counts[std::min(grid.rings - 1, static_cast<std::size_t>(r / ring_width_um))];
    }
  }
  const auto to_index = [&](double coordinate_um) {
    return (coordinate_um + grid.radius_um) / lines.spacing_um - 0.5;
  };
  std::vector<std::pair<std::size_t, double>> crossings;  // (line i * per_side + j, x)
  for (std::size_t c = 0; c < positions_um.size(); ++c) {
    crossings.clear();
    const auto& x = positions_um[c];
    for (const auto& triangle : triangles[c]) {
      Vec3 a = x[static_cast<std::size_t>(triangle[0])];
      Vec3 b = x[static_cast<std::size_t>(triangle[1])];
      Vec3 t = x[static_cast<std::size_t>(triangle[2])];
      Point2 pa{a.y(), a.z()}, pb{b.y(), b.z()}, pc{t.y(), t.z()};
      const double area = edge_function(pa, pb, pc);
      if (area == 0.0) continue;  // edge-on: a line through it meets its neighbours' edges
      if (area < 0.0) {           // counter-clockwise, for the top-left rule
        std::swap(b, t);
        std::swap(pb, pc);
      }
      const double low_y = std::min({pa.y, pb.y, pc.y}), high_y = std::max({pa.y, pb.y, pc.y});
      const double low_z = std::min({pa.z, pb.z, pc.z}), high_z = std::max({pa.z, pb.z, pc.z});
      const auto first = [&](double low) {
        return static_cast<std::ptrdiff_t>(std::max(0.0, std::ceil(to_index(low))));
      };
      const auto last = [&](double high) {
        return std::min(static_cast<std::ptrdiff_t>(lines.per_side) - 1,
                        static_cast<std::ptrdiff_t>(std::floor(to_index(high))));
      };
      for (std::ptrdiff_t i = first(low_y); i <= last(high_y); ++i) {
        for (std::ptrdiff_t j = first(low_z); j <= last(high_z); ++j) {
          const Point2 p = lines.at(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
          const double wa = edge_function(pb, pc, p);  // weight of a: the edge opposite it
          const double wb = edge_function(pc, pa, p);
          const double wc = edge_function(pa, pb, p);
          if (!covers(wa, pb, pc) || !covers(wb, pc, pa) || !covers(wc, pa, pb)) continue;
          const double crossing_x = (wa * a.x() + wb * b.x() + wc * t.x()) / (wa + wb + wc);
          crossings.emplace_back(
              static_cast<std::size_t>(i) * lines.per_side + static_cast<std::size_t>(j),
              crossing_x);
        }
      }
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k < crossings.size();) {
      std::size_t end = k;
      while (end < crossings.size() && crossings[end].first == crossings[k].first) ++end;
      if ((end - k) % 2 != 0) {
        throw std::logic_error("radial_volume_fraction: cell " + std::to_string(c) +
                               " is crossed an odd number of times: not a closed surface");
      }
      double length_um = 0.0;
      for (std::size_t m = k; m < end; m += 2)
        length_um += crossings[m + 1].second - crossings[m].second;
      const auto line = crossings[k].first;
      const Point2 p = lines.at(line / lines.per_side, line % lines.per_side);
      const double r = std::hypot(p.y, p.z);
      if (r < grid.radius_um) {
        inside_um[std::min(grid.rings - 1, static_cast<std::size_t>(r / ring_width_um))] +=
            length_um;
      }
      k = end;
    }
  }
  std::vector<double> fraction(grid.rings);
  for (std::size_t ring = 0; ring < grid.rings; ++ring) {
    fraction[ring] = inside_um[ring] / (static_cast<double>(line_counts[ring]) * grid.length_um);
  }
  return fraction;
}

}  // namespace rbcsim::cases
