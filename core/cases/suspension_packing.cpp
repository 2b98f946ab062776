#include "cases/suspension_packing.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "cases/wall_repulsion.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "contact/cell_repulsion.hpp"
#include "mesh/geometry.hpp"
#include "mesh/transform.hpp"

namespace rbcsim::cases {
namespace {

// Per iteration a cell moves at most this fraction of the cell gap (and its farthest vertex
// turns at most as far): small enough that no surface can pass through another between two
// overlap checks.
constexpr double kStepFraction = 0.1;
constexpr double kPushReach = 1.25;

struct RigidCell {
  std::size_t prototype = 0;
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Vec3 centre_um = Vec3::Zero();
};

// A prototype centred on its solid centroid, with its largest vertex distance from there.
struct Prototype {
  std::vector<Vec3> offsets_um;
  double reach_um = 0.0;
  double volume_um3 = 0.0;
};

Prototype centred(const mesh::TriangleMesh& mesh) {
  Prototype prototype;
  const Vec3 centroid = mesh::solid_centroid_um(mesh);
  for (const Vec3& position : mesh.positions_um) {
    prototype.offsets_um.push_back(position - centroid);
    prototype.reach_um = std::max(prototype.reach_um, (position - centroid).norm());
  }
  prototype.volume_um3 = mesh::enclosed_volume_um3(mesh);
  return prototype;
}

// Shoemake's uniformly random rotation from three uniform numbers.
Eigen::Quaterniond random_orientation(std::mt19937& generator) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double u1 = unit(generator);
  const double u2 = unit(generator);
  const double u3 = unit(generator);
  const double two_pi = 2.0 * std::numbers::pi;
  return Eigen::Quaterniond(
      std::sqrt(u1) * std::cos(two_pi * u3), std::sqrt(1.0 - u1) * std::sin(two_pi * u2),
      std::sqrt(1.0 - u1) * std::cos(two_pi * u2), std::sqrt(u1) * std::sin(two_pi * u3));
}

// What the packing needs of its space: the periodic box, the volume, the walls, random places.
contact::PeriodicBox periodic_box(const PackingSpace& space) {
  if (const auto* slab = std::get_if<PackingSlab>(&space)) {
    return {{slab->length_um, 0.0, slab->width_um}};
  }
  return {{std::get<PackingTube>(space).length_um, 0.0, 0.0}};
}

double volume_um3(const PackingSpace& space) {
  if (const auto* slab = std::get_if<PackingSlab>(&space)) {
    return slab->gap_um * slab->length_um * slab->width_um;
  }
  const auto& tube = std::get<PackingTube>(space);
  return std::numbers::pi * tube.radius_um * tube.radius_um * tube.length_um;
}

WallDistance wall_distance(const PackingSpace& space, const Vec3& position_um) {
  if (const auto* slab = std::get_if<PackingSlab>(&space)) {
    return slab_wall_distance(position_um, 0.5 * slab->gap_um);
  }
  return tube_wall_distance(position_um, std::get<PackingTube>(space).radius_um);
}

std::string walls_of(const PackingSpace& space) {
  if (const auto* slab = std::get_if<PackingSlab>(&space)) {
    return "the walls (gap " + format_number(slab->gap_um) + " um)";
  }
  return "the wall (radius " + format_number(std::get<PackingTube>(space).radius_um) + " um)";
}

// Centres wrapped into the space's periodic ranges.
void wrap(const PackingSpace& space, Vec3& centre_um) {
  const auto box = periodic_box(space);
  for (int axis = 0; axis < 3; ++axis) {
    const double length = box.length_um[static_cast<std::size_t>(axis)];
    if (length > 0.0) centre_um[axis] -= length * std::floor(centre_um[axis] / length);
  }
}

// A point at position x along the flow, uniformly random over the cross-section points that keep
// clear_radius_um from the walls (the tube's disc; the slab's gap times its width).
Vec3 random_off_axis(std::mt19937& generator, const PackingSpace& space, double clear_radius_um,
                     double x) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  if (const auto* slab = std::get_if<PackingSlab>(&space)) {
    const double half_um = std::max(0.5 * slab->gap_um - clear_radius_um, 0.0);
    const double y = half_um * (2.0 * unit(generator) - 1.0);
    return {x, y, slab->width_um * unit(generator)};
  }
  const auto& tube = std::get<PackingTube>(space);
  const double r = std::max(tube.radius_um - clear_radius_um, 0.0) * std::sqrt(unit(generator));
  const double angle = 2.0 * std::numbers::pi * unit(generator);
  return {x, r * std::cos(angle), r * std::sin(angle)};
}

double length_um(const PackingSpace& space) {
  return std::visit([](const auto& shape) { return shape.length_um; }, space);
}

Vec3 random_place(std::mt19937& generator, const PackingSpace& space, double clear_radius_um) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  return random_off_axis(generator, space, clear_radius_um, length_um(space) * unit(generator));
}

// The seeded start of PackingOrientation::axial: cell c at slot slots[c] of N along the axis.
struct AxialStart {
  Eigen::Quaterniond orientation;
  Vec3 centre_um;
};

AxialStart axial_start(std::mt19937& generator, const PackingSpace& space, double clear_radius_um,
                       std::size_t slot, std::size_t slots) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double spacing_um = length_um(space) / static_cast<double>(slots);
  const double x = spacing_um * (static_cast<double>(slot) + 0.5 + 0.5 * (unit(generator) - 0.5));
  const Vec3 centre_um = random_off_axis(generator, space, clear_radius_um, x);
  const double spin = 2.0 * std::numbers::pi * unit(generator);
  return {(Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), Vec3::UnitX()) *
           Eigen::Quaterniond(Eigen::AngleAxisd(spin, Vec3::UnitZ())))
              .normalized(),
          centre_um};
}

// A seeded random order of 0 .. count-1 (Fisher-Yates on the generator's uniform numbers, so
// that the order does not depend on the standard library's shuffle).
std::vector<std::size_t> random_order(std::mt19937& generator, std::size_t count) {
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = count; i > 1; --i) {
    const auto j =
        std::min(i - 1, static_cast<std::size_t>(unit(generator) * static_cast<double>(i)));
    std::swap(order[i - 1], order[j]);
  }
  return order;
}

Eigen::Quaterniond orientation_of(const CellPose& pose) {
  const double spin_rad = pose.spin_deg * std::numbers::pi / 180.0;
  return (Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), pose.axis.normalized()) *
          Eigen::Quaterniond(Eigen::AngleAxisd(spin_rad, Vec3::UnitZ())))
      .normalized();
}

class Packer {
 public:
  // Cells at seeded random places and orientations (`poses` empty) or at the poses given.
  Packer(std::span<const mesh::TriangleMesh> meshes, std::span<const std::size_t> cell_prototypes,
         const PackingSpace& space, const PackingSettings& settings,
         std::span<const CellPose> poses = {})
      : space_(space), settings_(settings) {
    for (const auto& mesh : meshes) prototypes_.push_back(centred(mesh));
    std::mt19937 generator(settings.seed);
    const bool axial = settings.orientation == PackingOrientation::axial;
    const auto slots = axial && poses.empty() ? random_order(generator, cell_prototypes.size())
                                              : std::vector<std::size_t>{};
    for (std::size_t c = 0; c < cell_prototypes.size(); ++c) {
      const std::size_t p = cell_prototypes[c];
      RigidCell cell;
      cell.prototype = p;
      const double clear_radius_um = kStartScale * prototypes_.at(p).reach_um;
      if (poses.empty() && axial) {
        const auto start =
            axial_start(generator, space, clear_radius_um, slots[c], cell_prototypes.size());
        cell.orientation = start.orientation;
        cell.centre_um = start.centre_um;
      } else if (poses.empty()) {
        cell.orientation = random_orientation(generator);
        cell.centre_um = random_place(generator, space, clear_radius_um);
      } else {
        cell.orientation = orientation_of(poses[c]);
        cell.centre_um = poses[c].centre_um;
      }
      cells_.push_back(cell);
      for (std::size_t v = 0; v < prototypes_[p].offsets_um.size(); ++v) {
        owners_.push_back(static_cast<std::uint32_t>(cells_.size() - 1));
      }
    }
  }

  // At the packing's scale (full size unless they grow in the flow): the first problem of cells
  // placed by hand (closer than the gap to another cell, to their own image across a period, or
  // to a wall), or nothing.
  std::optional<std::string> placement_problem() {
    place(settings_.scale);
    const auto box = periodic_box(space_);
    std::size_t offset = 0;
    for (std::size_t c = 0; c < cells_.size(); ++c) {
      const auto count = prototypes_[cells_[c].prototype].offsets_um.size();
      Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
      WallShortfall worst{-std::numeric_limits<double>::infinity()};
      for (std::size_t v = offset; v < offset + count; ++v) {
        low = low.cwiseMin(positions_[v]);
        high = high.cwiseMax(positions_[v]);
        const auto wall = wall_shortfall(c, v);
        if (wall.shortfall_um > worst.shortfall_um) worst = wall;
      }
      offset += count;
      if (worst.shortfall_um > 0.0 && worst.once_grown) {
        return "cell " + std::to_string(c) + " reaches " + format_number(worst.shortfall_um) +
               " um through " + walls_of(space_) + " once grown to full size (from " +
               format_number(settings_.scale) + ", suspension.packing_scale)";
      }
      if (worst.shortfall_um > 0.0) {
        return "cell " + std::to_string(c) + " comes within " +
               format_number(settings_.wall_gap_um - worst.shortfall_um) + " um of " +
               walls_of(space_) + ": closer to the wall than the wall repulsion's range, " +
               format_number(settings_.wall_gap_um) + " um";
      }
      for (int axis = 0; axis < 3; ++axis) {
        const double period = box.length_um[static_cast<std::size_t>(axis)];
        const double extent = high[axis] - low[axis];
        if (period > 0.0 && extent + settings_.cell_gap_um > period) {
          return "cell " + std::to_string(c) + " is " + format_number(extent) + " um long along " +
                 std::string(1, static_cast<char>('x' + axis)) +
                 ": it meets its own image across the period (" + format_number(period) + " um)";
        }
      }
    }
    std::vector<Vec3> ignored(positions_.size(), Vec3::Zero());
    const auto statistics = contact::add_cell_contact_forces(
        positions_, owners_, {1.0, settings_.cell_gap_um}, box, ignored, contact_workspace_);
    if (statistics.pairs_in_range == 0) return std::nullopt;
    for (std::size_t v = 0; v < positions_.size(); ++v) {
      if (ignored[v] == Vec3::Zero()) continue;
      return "cell " + std::to_string(owners_[v]) +
             " comes closer to another cell than the contact range, " +
             format_number(settings_.cell_gap_um) + " um (the closest vertices of two cells are " +
             format_number(statistics.closest_um) + " um apart)";
    }
    return "two cells' vertices coincide";
  }

  // One push of every overlapping cell; whether any overlapped.
  bool push_apart(double scale) {
    place(scale);
    std::vector<Vec3> pushes(positions_.size(), Vec3::Zero());
    // The pushes reach a little beyond the gap, so that a pair just inside it is still pushed
    // firmly (the contact law vanishes at its range).
    const auto statistics = contact::add_cell_contact_forces(
        positions_, owners_, {1.0, kPushReach * settings_.cell_gap_um}, periodic_box(space_),
        pushes, contact_workspace_);
    bool overlap = statistics.closest_um < settings_.cell_gap_um;
    for (std::size_t v = 0; v < positions_.size(); ++v) {
      const auto wall = wall_shortfall(owners_[v], v);
      if (wall.shortfall_um <= 0.0) continue;
      overlap = true;
      pushes[v] += (wall.shortfall_um / settings_.wall_gap_um + 0.1) * wall.inward;
    }
    if (overlap) move(scale, pushes);
    return overlap;
  }

  Packing result(std::size_t iterations) const {
    Packing packing;
    packing.iterations = iterations;
    double volume_um3 = 0.0;
    std::size_t offset = 0;
    for (const auto& cell : cells_) {
      const auto count = prototypes_[cell.prototype].offsets_um.size();
      packing.positions_um.emplace_back(
          positions_.begin() + static_cast<std::ptrdiff_t>(offset),
          positions_.begin() + static_cast<std::ptrdiff_t>(offset + count));
      offset += count;
      volume_um3 += prototypes_[cell.prototype].volume_um3;
    }
    packing.hematocrit = volume_um3 / lumen_volume_um3();
    packing.scale = settings_.scale;
    return packing;
  }

  double lumen_volume_um3() const { return volume_um3(space_); }

  double hematocrit_at(double scale) const {
    double volume_um3 = 0.0;
    for (const auto& cell : cells_) volume_um3 += prototypes_[cell.prototype].volume_um3;
    return scale * scale * scale * volume_um3 / lumen_volume_um3();
  }

  void place(double scale) {
    positions_.clear();
    for (const auto& cell : cells_) {
      const Eigen::Matrix3d rotation = cell.orientation.toRotationMatrix();
      for (const Vec3& offset : prototypes_[cell.prototype].offsets_um) {
        positions_.push_back(cell.centre_um + scale * (rotation * offset));
      }
    }
  }

 private:
  // Each cell moves along its net push and turns about its net torque, both limited to
  // kStepFraction of the gap at its farthest vertex.
  void move(double scale, const std::vector<Vec3>& pushes) {
    const double step_um = kStepFraction * settings_.cell_gap_um;
    std::size_t offset = 0;
    for (auto& cell : cells_) {
      const auto& prototype = prototypes_[cell.prototype];
      Vec3 force = Vec3::Zero();
      Vec3 torque = Vec3::Zero();
      std::size_t pushed = 0;
      for (std::size_t v = 0; v < prototype.offsets_um.size(); ++v) {
        const Vec3& push = pushes[offset + v];
        if (push == Vec3::Zero()) continue;
        ++pushed;
        force += push;
        torque += (positions_[offset + v] - cell.centre_um).cross(push);
      }
      offset += prototype.offsets_um.size();
      if (pushed == 0) continue;
      // A net push of one full-strength pair or more moves the cell a whole step; a weaker one
      // proportionally less, so that balanced cells settle instead of jittering.
      cell.centre_um += step_um * force / std::max(1.0, force.norm());
      wrap(space_, cell.centre_um);
      const double arm_um = scale * prototype.reach_um;
      const double torque_pushes = torque.norm() / arm_um;
      const double angle = step_um / arm_um * std::min(1.0, torque_pushes);
      if (angle > 0.0) {
        cell.orientation =
            (Eigen::AngleAxisd(angle, torque.normalized()) * cell.orientation).normalized();
      }
    }
  }

  // How much closer to the wall than allowed vertex v of cell c is (<= 0: not), and the way in.
  // Allowed: the wall gap at the current scale and, for cells packed smaller than their size
  // (settings.scale < 1), no vertex through the wall once the cell has grown by 1 / settings.scale
  // about its centre, as it will in the flow. Inside the wall's range the flow's wall repulsion
  // pushes a grown vertex out; through the wall nothing brings it back (the stability checks stop
  // the run). The whole gap at full size would be too strict: in a 10 um tube a full-size
  // discocyte with the 1 um gap would have to stand exactly across the axis, and in the flow the
  // cells deform away from the wall instead. Checked from the packing's start, so that a cell near
  // the wall is steered inward while there is room.
  struct WallShortfall {
    double shortfall_um = 0.0;
    Vec3 inward = Vec3::Zero();
    bool once_grown = false;  // the grown vertex through the wall is the larger shortfall
  };
  WallShortfall wall_shortfall(std::size_t c, std::size_t v) const {
    const auto now = wall_distance(space_, positions_[v]);
    WallShortfall shortfall{settings_.wall_gap_um - now.distance_um, now.inward, false};
    if (settings_.scale < 1.0) {
      const Vec3& centre = cells_[c].centre_um;
      const auto grown = wall_distance(space_, centre + (positions_[v] - centre) / settings_.scale);
      if (-grown.distance_um > shortfall.shortfall_um) {
        shortfall = {-grown.distance_um, grown.inward, true};
      }
    }
    return shortfall;
  }

  PackingSpace space_;
  PackingSettings settings_;
  std::vector<Prototype> prototypes_;
  std::vector<RigidCell> cells_;
  std::vector<std::uint32_t> owners_;
  std::vector<Vec3> positions_;
  contact::ContactWorkspace contact_workspace_;
};

}  // namespace

bool surface_contains(std::span<const Vec3> positions_um, std::span<const mesh::Triangle> triangles,
                      const Vec3& point_um) {
  // Van Oosterom & Strackee's solid angle of each triangle seen from the point.
  double solid_angle = 0.0;
  for (const auto& triangle : triangles) {
    const Vec3 a = positions_um[triangle[0]] - point_um;
    const Vec3 b = positions_um[triangle[1]] - point_um;
    const Vec3 c = positions_um[triangle[2]] - point_um;
    const double la = a.norm();
    const double lb = b.norm();
    const double lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    solid_angle += 2.0 * std::atan2(numerator, denominator);
  }
  return std::abs(solid_angle) > 2.0 * std::numbers::pi;
}

std::vector<std::optional<std::size_t>> find_pierced_cells(
    std::span<const std::vector<Vec3>> positions_um,
    std::span<const std::span<const mesh::Triangle>> triangles, const contact::PeriodicBox& box) {
  const auto count = positions_um.size();
  // Each cell's centre, reach (farthest vertex from the centre) and bounding box.
  std::vector<Vec3> centres, lows, highs;
  std::vector<double> reaches;
  for (const auto& positions : positions_um) {
    Vec3 centre = Vec3::Zero();
    Vec3 low = positions.front(), high = low;
    for (const Vec3& position : positions) {
      centre += position;
      low = low.cwiseMin(position);
      high = high.cwiseMax(position);
    }
    centre /= static_cast<double>(positions.size());
    double reach = 0.0;
    for (const Vec3& position : positions) reach = std::max(reach, (position - centre).norm());
    centres.push_back(centre);
    lows.push_back(low);
    highs.push_back(high);
    reaches.push_back(reach);
  }
  std::vector<std::optional<std::size_t>> pierced(count);
  const auto signed_count = static_cast<std::ptrdiff_t>(count);
  // Only the vertices of A within reach of B's centre and inside B's bounding box can be in B.
  // A's vertices are moved next to B (by the periodic shift of B's image nearest to A) rather
  // than B's to A: nothing is copied.
#pragma omp parallel for schedule(dynamic)
  for (std::ptrdiff_t a = 0; a < signed_count; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    for (std::size_t b = 0; b < count && !pierced[ua]; ++b) {
      if (ua == b) continue;
      const Vec3 shift = centres[ua] - centres[b] - box.minimum_image(centres[ua] - centres[b]);
      if ((centres[ua] - centres[b] - shift).norm() > reaches[ua] + reaches[b]) continue;
      for (const Vec3& vertex : positions_um[ua]) {
        const Vec3 point = vertex - shift;
        if ((point - centres[b]).norm() > reaches[b]) continue;
        if ((point.array() < lows[b].array()).any() || (point.array() > highs[b].array()).any())
          continue;
        if (surface_contains(positions_um[b], triangles[b], point)) {
          pierced[ua] = b;
          break;
        }
      }
    }
  }
  return pierced;
}

// A vertex of one cell inside another: a surface through another one. `what` names the option.
void require_no_pierced_cells(const Packing& packing,
                              std::span<const mesh::TriangleMesh> prototypes,
                              std::span<const std::size_t> cell_prototypes,
                              const PackingSpace& space, bool by_hand) {
  std::vector<std::span<const mesh::Triangle>> triangles;
  for (const std::size_t prototype : cell_prototypes) {
    triangles.emplace_back(prototypes[prototype].triangles);
  }
  const auto pierced = find_pierced_cells(packing.positions_um, triangles, periodic_box(space));
  for (std::size_t a = 0; a < pierced.size(); ++a) {
    if (!pierced[a]) continue;
    const std::string problem =
        "cell " + std::to_string(a) + " pierces cell " + std::to_string(*pierced[a]);
    if (by_hand) throw InputError("suspension.cells", problem);
    throw RuntimeFailure("packing: " + problem);
  }
}

Packing place_cells(std::span<const mesh::TriangleMesh> prototypes,
                    std::span<const std::size_t> cell_prototypes, std::span<const CellPose> poses,
                    const PackingSpace& space, const PackingSettings& settings) {
  if (poses.size() != cell_prototypes.size() || poses.empty()) {
    throw std::invalid_argument("place_cells: one pose per cell, and a cell at least");
  }
  Packer packer(prototypes, cell_prototypes, space, settings, poses);
  if (const auto problem = packer.placement_problem()) {
    throw InputError("suspension.cells", *problem);
  }
  auto packing = packer.result(0);
  require_no_pierced_cells(packing, prototypes, cell_prototypes, space, true);
  return packing;
}

Packing place_cells_in_tube(std::span<const mesh::TriangleMesh> prototypes,
                            std::span<const std::size_t> cell_prototypes,
                            std::span<const CellPose> poses, const PackingTube& tube,
                            const PackingSettings& settings) {
  return place_cells(prototypes, cell_prototypes, poses, tube, settings);
}

Packing pack_cells(std::span<const mesh::TriangleMesh> prototypes,
                   std::span<const std::size_t> cell_prototypes, const PackingSpace& space,
                   const PackingSettings& settings) {
  if (!(settings.scale > 0.0 && settings.scale <= 1.0)) {
    throw std::invalid_argument("pack_cells: scale outside (0, 1]");
  }
  Packer packer(prototypes, cell_prototypes, space, settings);
  double scale = std::min(kStartScale, settings.scale);
  double clear_scale = 0.0;  // the largest at which no cell overlapped
  std::size_t iteration = 0;
  for (; iteration < settings.max_iterations; ++iteration) {
    throw_if_interrupted();  // packing a large suspension takes a while
    if (packer.push_apart(scale)) continue;
    clear_scale = scale;
    if (scale == settings.scale) break;
    scale = std::min(settings.scale, scale + kScaleStep);
  }
  if (iteration == settings.max_iterations) {
    throw InputError(
        "suspension.hematocrit",
        "could not pack " + std::to_string(cell_prototypes.size()) + " cells into the " +
            (std::holds_alternative<PackingSlab>(space) ? "gap" : "tube") + ": after " +
            std::to_string(iteration) + " iterations they were clear only at " +
            format_number(clear_scale) + " of their size, hematocrit " +
            format_number(packer.hematocrit_at(clear_scale)) + " (the " +
            std::to_string(cell_prototypes.size()) + " cells at full size: " +
            format_number(packer.hematocrit_at(1.0)) + "); lower the hematocrit or enlarge the " +
            (std::holds_alternative<PackingSlab>(space) ? "gap" : "tube") +
            (settings.scale == 1.0 ? std::string(", pack smaller cells that grow to full size in "
                                                 "the flow (suspension.packing_scale)")
                                   : std::string()) +
            (settings.orientation == PackingOrientation::random
                 ? std::string(", or start the cells lined up along the axis "
                               "(suspension.packing_orientation=axial)")
                 : std::string()));
  }
  packer.place(settings.scale);
  auto packing = packer.result(iteration);
  // The packing moved a surface through another one.
  require_no_pierced_cells(packing, prototypes, cell_prototypes, space, false);
  return packing;
}

Packing pack_cells_in_tube(std::span<const mesh::TriangleMesh> prototypes,
                           std::span<const std::size_t> cell_prototypes, const PackingTube& tube,
                           const PackingSettings& settings) {
  return pack_cells(prototypes, cell_prototypes, tube, settings);
}

}  // namespace rbcsim::cases
