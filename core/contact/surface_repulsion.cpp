#include "contact/surface_repulsion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rbcsim::contact {
namespace {

// One vertex's push from one other cell.
struct SurfaceContact {
  std::uint32_t vertex = 0;
  std::uint32_t other_cell = 0;
  std::uint32_t triangle = 0;
  std::array<double, 3> weights{};
  Vec3 force_pN = Vec3::Zero();
  double distance_um = 0.0;
  bool capped = false;  // held at ContactParameters::force_cap_pN
};

// The nearest point so far of one other cell's surface.
struct Nearest {
  double distance_um = std::numeric_limits<double>::infinity();
  std::uint32_t triangle = 0;
  std::array<double, 3> weights{};
  Vec3 from_surface_um = Vec3::Zero();  // x_i - c
};

// The longest edge, from the positions as they are: a cell's vertices travel together (never
// wrapped one by one), so an edge needs no minimum image; were one wrapped, its edge would come
// out a period long and the search only wider, never missing a triangle. Squared lengths, one
// root: this runs over every triangle each step.
double longest_edge_um(std::span<const Vec3> positions_um, const ContactSurfaces& surfaces) {
  double longest_squared = 0.0;
  for (const auto& t : surfaces.triangles) {
    const Vec3& a = positions_um[t[0]];
    const Vec3& b = positions_um[t[1]];
    const Vec3& c = positions_um[t[2]];
    longest_squared = std::max(
        {longest_squared, (a - b).squaredNorm(), (b - c).squaredNorm(), (c - a).squaredNorm()});
  }
  return std::sqrt(longest_squared);
}

// The side of a surface a point lies on, from its nearest point c on triangle t (barycentric
// weights w): the sign of (x - c) . N with N the angle-weighted pseudo-normal of the feature c lies
// on (Baerentzen & Aanaes 2005, IEEE TVCG 11:243): the face's normal inside the face, the sum of
// the two faces' unit normals on an edge, and the sum of the incident faces' unit normals weighted
// by their angles at a vertex. One face's normal alone misjudges a point beyond a sharp edge or
// corner: the tie between the faces that share c keeps the first, whose normal can point away
// from x. Corners are taken by minimum image around c's first vertex.
Vec3 pseudo_normal(std::span<const Vec3> positions_um, const ContactSurfaces& surfaces,
                   const PeriodicBox& box, std::uint32_t t, const std::array<double, 3>& w) {
  const auto& triangle = surfaces.triangles[t];
  std::array<std::uint32_t, 3> on{};
  std::size_t count = 0;
  for (std::size_t c = 0; c < 3; ++c) {
    if (w[c] > 0.0) on[count++] = triangle[c];
  }
  const Vec3 origin = positions_um[on[0]];
  const auto corner = [&](std::uint32_t v) {
    return Vec3(origin + box.minimum_image(positions_um[v] - origin));
  };
  const auto unit_normal = [&](std::uint32_t face) {
    const auto& f = surfaces.triangles[face];
    const Vec3 a = corner(f[0]);
    return Vec3((corner(f[1]) - a).cross(corner(f[2]) - a).normalized());
  };
  if (count == 3) return unit_normal(t);
  Vec3 sum = Vec3::Zero();
  for (std::uint32_t r = surfaces.vertex_triangle_offsets[on[0]];
       r < surfaces.vertex_triangle_offsets[on[0] + 1]; ++r) {
    const std::uint32_t face = surfaces.vertex_triangles[r];
    const auto& f = surfaces.triangles[face];
    if (count == 2) {
      if (std::find(f.begin(), f.end(), on[1]) != f.end()) sum += unit_normal(face);
      continue;
    }
    // The face's angle at the vertex.
    const auto at = static_cast<std::size_t>(std::find(f.begin(), f.end(), on[0]) - f.begin());
    const Vec3 to_next = corner(f[(at + 1) % 3]) - origin;
    const Vec3 to_previous = corner(f[(at + 2) % 3]) - origin;
    const double angle = std::atan2(to_next.cross(to_previous).norm(), to_next.dot(to_previous));
    sum += angle * unit_normal(face);
  }
  return sum;
}

// For candidate k of the workspace (vertex i = candidates[k]), the nearest point of each other
// cell's surface among the triangles of that cell's vertices within the reach: the cell list's
// runs of one cell are taken or skipped whole, and the separations come from the list's wrapped
// positions and shifts (no rounding per pair where they are exact).
struct NearestSurfaceSearch {
  std::span<const Vec3> positions_um;
  std::span<const std::uint32_t> owner;
  const ContactSurfaces& surfaces;
  const PeriodicBox& box;
  const ContactWorkspace& workspace;
  double reach_squared;

  // `tried_by[t] == k` marks triangle t as tried for this vertex: a triangle is met once from
  // each of its vertices in reach, and only the first meeting can be the nearest (ties keep the
  // first), so the others are skipped without changing the result.
  void find(std::size_t k, std::span<std::size_t> tried_by,
            std::vector<std::pair<std::uint32_t, Nearest>>& nearest) const {
    const CellList& list = workspace.list;
    const std::uint32_t i = workspace.candidates[k];
    const Vec3& x_wrapped = list.wrapped(k);
    list.for_each_candidate_run(
        workspace.candidate_positions_um[k], [&](const CellList::Run& run, const Vec3& shift_um) {
          if (run.group == owner[i]) return;
          Nearest* entry = nullptr;
          for (std::uint32_t p = run.begin; p < run.end; ++p) {
            const std::uint32_t m = list.points()[p];
            const std::uint32_t j = workspace.candidates[m];
            // x_i placed next to x_j. A vertex beyond the reach has no triangle within the range
            // that another vertex in reach lacks.
            const Vec3 offset = list.has_exact_shifts()
                                    ? Vec3(x_wrapped - (list.wrapped(m) + shift_um))
                                    : box.minimum_image(positions_um[i] - positions_um[j]);
            if (!(offset.squaredNorm() < reach_squared)) continue;
            if (entry == nullptr) entry = &entry_of(nearest, run.group);
            try_triangles_of(j, positions_um[j] + offset, k, tried_by, *entry);
          }
        });
  }

  static Nearest& entry_of(std::vector<std::pair<std::uint32_t, Nearest>>& nearest,
                           std::uint32_t cell) {
    auto entry = std::find_if(nearest.begin(), nearest.end(),
                              [cell](const auto& e) { return e.first == cell; });
    if (entry != nearest.end()) return entry->second;
    nearest.push_back({cell, Nearest{}});
    return nearest.back().second;
  }

  // The triangles of vertex j not yet tried, taken around x_j's own position.
  void try_triangles_of(std::uint32_t j, const Vec3& here, std::size_t k,
                        std::span<std::size_t> tried_by, Nearest& entry) const {
    for (std::uint32_t r = surfaces.vertex_triangle_offsets[j];
         r < surfaces.vertex_triangle_offsets[j + 1]; ++r) {
      const std::uint32_t t = surfaces.vertex_triangles[r];
      if (tried_by[t] == k) continue;
      tried_by[t] = k;
      const auto& triangle = surfaces.triangles[t];
      std::array<Vec3, 3> corner;
      for (std::size_t c = 0; c < 3; ++c) {
        corner[c] =
            positions_um[j] + box.minimum_image(positions_um[triangle[c]] - positions_um[j]);
      }
      const auto w = nearest_on_triangle(here, corner[0], corner[1], corner[2]);
      const Vec3 point = w[0] * corner[0] + w[1] * corner[1] + w[2] * corner[2];
      const double distance = (here - point).norm();
      // Ties (a shared edge or vertex) keep the first triangle met: a fixed order.
      if (distance < entry.distance_um) entry = {distance, t, w, here - point};
    }
  }
};

// The records of every vertex, in the order of (vertex, other cell).
std::vector<SurfaceContact> flattened(const std::vector<std::vector<SurfaceContact>>& found) {
  std::vector<SurfaceContact> contacts;
  for (const auto& of_vertex : found)
    contacts.insert(contacts.end(), of_vertex.begin(), of_vertex.end());
  return contacts;
}

// A record as values that travel between processes exactly (indices below 2^32 are exact in a
// double).
constexpr std::size_t kRecordValues = 11;

void append_record(std::vector<double>& values, const SurfaceContact& contact) {
  values.insert(values.end(),
                {static_cast<double>(contact.vertex), static_cast<double>(contact.other_cell),
                 static_cast<double>(contact.triangle), contact.weights[0], contact.weights[1],
                 contact.weights[2], contact.force_pN.x(), contact.force_pN.y(),
                 contact.force_pN.z(), contact.distance_um, contact.capped ? 1.0 : 0.0});
}

SurfaceContact record_at(std::span<const double> v) {
  return {static_cast<std::uint32_t>(v[0]),
          static_cast<std::uint32_t>(v[1]),
          static_cast<std::uint32_t>(v[2]),
          {v[3], v[4], v[5]},
          Vec3(v[6], v[7], v[8]),
          v[9],
          v[10] != 0.0};
}

// Every process's records, in the order of (vertex, other cell): the order one process adds them
// in, whichever process found them.
std::vector<SurfaceContact> shared_contacts(const std::vector<std::vector<SurfaceContact>>& found,
                                            const ContactSplit& split) {
  std::vector<double> mine;
  for (const auto& of_vertex : found) {
    for (const auto& contact : of_vertex) append_record(mine, contact);
  }
  const std::vector<double> all = split.share(mine);
  if (all.size() % kRecordValues != 0) {
    throw std::logic_error("surface contact: shared records of " + std::to_string(all.size()) +
                           " values");
  }
  std::vector<SurfaceContact> contacts;
  for (std::size_t r = 0; r < all.size(); r += kRecordValues) {
    contacts.push_back(record_at(std::span<const double>(all).subspan(r, kRecordValues)));
  }
  std::sort(contacts.begin(), contacts.end(), [](const auto& a, const auto& b) {
    return a.vertex != b.vertex ? a.vertex < b.vertex : a.other_cell < b.other_cell;
  });
  return contacts;
}

}  // namespace

std::array<double, 3> nearest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  return {1.0 - v - w, v, w};
}

ContactStatistics add_surface_contact_forces(
    std::span<const Vec3> positions_um, std::span<const std::uint32_t> owner,
    const ContactSurfaces& surfaces, const ContactParameters& parameters, const PeriodicBox& box,
    std::span<Vec3> forces_pN, ContactWorkspace& workspace, const ContactSplit* split) {
  if (owner.size() != positions_um.size() || forces_pN.size() != positions_um.size() ||
      surfaces.vertex_triangle_offsets.size() != positions_um.size() + 1) {
    throw std::invalid_argument("surface contact: one owner, force and triangle row per position");
  }
  ContactStatistics statistics;
  if (parameters.force_at_contact_pN == 0.0) return statistics;
  const double range = parameters.range_um;
  if (!(range > 0.0)) throw std::invalid_argument("surface contact: the range must be > 0");
  if (!(parameters.force_cap_pN > 0.0)) {
    throw std::invalid_argument("surface contact: the force cap must be > 0");
  }
  // Every point of a triangle lies within L / sqrt(3) of one of its vertices, L its longest edge
  // (the circumradius of an acute triangle, L / (2 sin of its largest angle >= 60 deg); in any
  // other the farthest point lies on an edge, within half of it of an end). So a triangle with a
  // point within the range of x_i has a vertex within range + L / sqrt(3): those vertices are
  // found, and their triangles tried.
  const double reach =
      (range + longest_edge_um(positions_um, surfaces) / std::sqrt(3.0)) * (1.0 + 1e-9);
  select_candidates(positions_um, owner, reach, box, workspace);
  // Every process has the same candidates: all return here, or none.
  if (workspace.candidates.empty()) return statistics;
  const std::span<const std::uint32_t> kept = workspace.candidates;
  const std::span<const std::uint32_t> kept_owner = workspace.candidate_owners;
  CellList& list = workspace.list;
  list.build(workspace.candidate_positions_um, reach, box, kept_owner);

  const auto count = static_cast<std::ptrdiff_t>(kept.size());
  const NearestSurfaceSearch search{positions_um, owner, surfaces, box, workspace, reach * reach};
  std::vector<std::vector<SurfaceContact>> found(kept.size());
#pragma omp parallel
  {
    // Which vertex last tried each triangle (NearestSurfaceSearch::find).
    std::vector<std::size_t> tried_by(surfaces.triangles.size(), kept.size());
#pragma omp for schedule(dynamic, 64)
    for (std::ptrdiff_t signed_k = 0; signed_k < count; ++signed_k) {
      const auto k = static_cast<std::size_t>(signed_k);
      const std::uint32_t i = kept[k];
      if (split != nullptr && !split->searches_cell(owner[i])) continue;
      // Per other cell (in order of first meeting), its nearest surface point.
      std::vector<std::pair<std::uint32_t, Nearest>> nearest;
      search.find(k, tried_by, nearest);
      for (const auto& [cell, near] : nearest) {
        if (!(near.distance_um < range)) continue;
        const double d = std::max(near.distance_um, 0.01 * range);
        const double excess = range / d - 1.0;
        const double law = parameters.force_at_contact_pN * excess * excess;
        const bool capped = law > parameters.force_cap_pN;
        const double magnitude = capped ? parameters.force_cap_pN : law;
        const Vec3 outward =
            pseudo_normal(positions_um, surfaces, box, near.triangle, near.weights);
        Vec3 direction = near.distance_um > 0.0 ? Vec3(near.from_surface_um / near.distance_um)
                                                : Vec3(outward.normalized());
        // On the inner side of the surface: already through, pushed back out.
        if (direction.dot(outward) < 0.0) direction = -direction;
        found[k].push_back({i, cell, near.triangle, near.weights, magnitude * direction,
                            near.distance_um, capped});
      }
      std::sort(found[k].begin(), found[k].end(),
                [](const auto& a, const auto& b) { return a.other_cell < b.other_cell; });
    }
  }
  const std::vector<SurfaceContact> contacts =
      split != nullptr ? shared_contacts(found, *split) : flattened(found);
  // Serially, in the order of (vertex, other cell): each vertex's push and its reaction on the
  // other surface's triangle.
  for (const auto& contact : contacts) {
    forces_pN[contact.vertex] += contact.force_pN;
    const auto& triangle = surfaces.triangles[contact.triangle];
    for (std::size_t c = 0; c < 3; ++c)
      forces_pN[triangle[c]] -= contact.weights[c] * contact.force_pN;
    ++statistics.pairs_in_range;
    if (contact.distance_um < 0.25 * range) ++statistics.close_pairs;
    if (contact.capped) ++statistics.capped_pushes;
    statistics.closest_um = std::min(statistics.closest_um, contact.distance_um);
  }
  return statistics;
}

}  // namespace rbcsim::contact
