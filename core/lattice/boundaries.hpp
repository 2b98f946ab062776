// Boundaries of the lattice fluid, as small named pieces shared by the reference and the optimised
// kernels. Every boundary is a rule for one link: a fluid node x misses the population f_i that
// would stream in from x - c_i whenever that node is not fluid (or lies across the Lees-Edwards
// plane), and the rule supplies it from the post-collision populations f* of x itself.
//
//   periodic          the default: x - c_i wraps around the box.
//   wall              half-way bounce-back, optionally moving (Ladd, J. Fluid Mech. 271, 285
//                     (1994)):
//                       f_i(x) = f*_opp(i)(x) + 2 w_i rho(x) c_i.u_w / c_s^2.
//                     Written with the direction that enters the fluid; with the direction that
//                     hits the wall it reads -2 w_i rho c_i.u_w / c_s^2. The wall sits half-way
//                     between x and x - c_i. A velocity inlet is a wall whose velocity points into
//                     the fluid (the bounce-back-with-velocity inlet), with one velocity per node
//                     so that a Poiseuille profile can be imposed.
//   curved wall       interpolated bounce-back, chosen by name (`lattice.wall_rule`, one table,
//                     wall_rules()) for walls that cut the link x - c_i -> x at a fraction q of
//                     its length from x (wall_link.hpp; q = 1/2 unless set). Every rule of the
//                     table is a member of the linear family (Ginzburg & d'Humieres, Phys. Rev. E
//                     68, 066614 (2003)); with h = opp(i) the direction that hits the wall,
//                       f_i(x) = k_here f*_h(x) + k_away f*_i(x) + k_behind f*_h(x + c_i)
//                                + k_wall 2 w_i rho(x) c_i.u_w / c_s^2,
//                     all at the previous time step; half-way bounce-back is (1, 0, 0, 1).
//   pressure outlet   anti-bounce-back at a given density (Ginzburg, Verhaeghe & d'Humieres,
//                     Commun. Comput. Phys. 3, 427 (2008); Krueger et al., "The Lattice
//                     Boltzmann Method", 2017, ch. 5):
//                       f_i(x) = -f*_opp(i)(x) + 2 w_i rho_out (1 + (c_i.u)^2 / (2 c_s^4)
//                                                                 - u.u / (2 c_s^2)),
//                     with u the velocity of x: in a developed outflow du/dn = 0, so this is the
//                     wall velocity to second order.
//   Lees-Edwards      sliding periodic images in y (lees_edwards.hpp).
#pragma once

#include "lattice/d3q19.hpp"
#include "lattice/wall_link.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace rbcsim::lattice {

// The value of the solid mask at one node.
enum class NodeKind : std::uint8_t { fluid = 0, wall = 1, pressure_outlet = 2 };

// Which nodes are not fluid and what each imposes. Resting walls need no entry in the maps.
class BoundaryMap {
 public:
  explicit BoundaryMap(std::size_t node_count);

  void set_wall(std::size_t node, const std::array<double, 3>& wall_velocity = {0.0, 0.0, 0.0});
  void set_pressure_outlet(std::size_t node, double density);

  NodeKind kind(std::size_t node) const { return static_cast<NodeKind>(kinds_[node]); }
  bool is_fluid(std::size_t node) const { return kinds_[node] == 0; }
  // The solid mask: one NodeKind per node.
  const std::vector<std::uint8_t>& kinds() const { return kinds_; }
  std::size_t fluid_node_count() const;

  std::array<double, 3> wall_velocity(std::size_t node) const;
  double outlet_density(std::size_t node) const;
  // What is set beyond resting half-way walls, for a solver that runs only those (core/parallel).
  bool has_moving_walls() const { return !wall_velocity_.empty(); }
  bool has_pressure_outlets() const { return !outlet_density_.empty(); }
  bool has_wall_fractions() const { return !wall_fraction_.empty(); }

  // Where the wall cuts the link from fluid node `link.node` along c_direction (WallLink). Links
  // never set are cut half-way, q = 1/2. The caller checks the link (FluidSolver::set_wall_links).
  void set_wall_fraction(const WallLink& link);
  double wall_fraction(std::size_t node, int direction) const;

 private:
  std::vector<std::uint8_t> kinds_;
  std::unordered_map<std::size_t, std::array<double, 3>> wall_velocity_;
  std::unordered_map<std::size_t, double> outlet_density_;
  std::unordered_map<std::size_t, double> wall_fraction_;  // key: node * kDirections + direction
};

// 2 w_i c_i.u_w / c_s^2: the moving-wall term of the bounce-back rule, per unit density.
constexpr double wall_momentum_coefficient(int direction,
                                           const std::array<double, 3>& wall_velocity) {
  return 2.0 * kWeights[direction] * kInverseSoundSpeedSquared *
         dot_velocity(direction, wall_velocity);
}

constexpr double bounce_back(double reflected, double density, double wall_coefficient) {
  return reflected + density * wall_coefficient;
}

// The coefficients of one wall link in the linear family above.
struct WallLinkWeights {
  double here = 1.0;    // of f*_h(x), the population that hits the wall
  double away = 0.0;    // of f*_i(x), the population leaving the wall
  double behind = 0.0;  // of f*_h(x + c_i), the one hitting the wall from the next fluid node
  double wall = 1.0;    // of the moving-wall term 2 w_i rho(x) c_i.u_w / c_s^2
  friend constexpr bool operator==(const WallLinkWeights&, const WallLinkWeights&) = default;
};

inline constexpr WallLinkWeights kHalfwayWeights{};

// The part of an interpolated bounce-back that only needs the node itself. Kernels add
// weights.behind * f*_h(x + c_i) to it, so that the optimised kernel can add it once the
// neighbour's population is in place.
constexpr double wall_link_local_part(const WallLinkWeights& weights, double hitting,
                                      double leaving, double density, double wall_coefficient) {
  return weights.here * hitting + weights.away * leaving +
         weights.wall * density * wall_coefficient;
}

// A rule of `lattice.wall_rule`: the weights of a link cut at fraction q, given whether the next
// node x + c_i is plain fluid (not a boundary and not across a sliding plane).
struct WallRule {
  std::string_view name;
  std::string_view summary;
  WallLinkWeights (*weights)(double fraction, bool behind_is_fluid);
};

std::span<const WallRule> wall_rules();

// Throws rbcsim::InputError naming `lattice.wall_rule` (and the known names) for an unknown rule.
const WallRule& find_wall_rule(std::string_view name);

constexpr double anti_bounce_back(int direction, double reflected, double outlet_density,
                                  const std::array<double, 3>& velocity) {
  const double cu = dot_velocity(direction, velocity);
  const double uu =
      velocity[0] * velocity[0] + velocity[1] * velocity[1] + velocity[2] * velocity[2];
  return -reflected +
         2.0 * kWeights[direction] * outlet_density *
             (1.0 + kHalfInverseSoundSpeedFourth * cu * cu - 0.5 * kInverseSoundSpeedSquared * uu);
}

}  // namespace rbcsim::lattice
