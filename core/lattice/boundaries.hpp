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

#include <array>
#include <cstddef>
#include <cstdint>
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

 private:
  std::vector<std::uint8_t> kinds_;
  std::unordered_map<std::size_t, std::array<double, 3>> wall_velocity_;
  std::unordered_map<std::size_t, double> outlet_density_;
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
