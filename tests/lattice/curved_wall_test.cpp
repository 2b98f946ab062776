// Interpolated (curved-wall) bounce-back, the "bouzidi" wall rule (boundaries.hpp): exact for
// linear flow with walls anywhere along the links, the predicted second-order closure error for
// parabolic flow, Poiseuille flow in circular pipes set up from core/geometry as fluid_solver.hpp
// describes, and the mass the rule does not conserve.
#include "common/errors.hpp"
#include "flow_helpers.hpp"
#include "geometry/tube_wall.hpp"
#include "geometry/voxelise.hpp"
#include "geometry/wall_links.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rbcsim::lattice {
namespace {

using testing::relative_l2_error_x;

constexpr double kWallFlowPeakVelocity = 0.01;

FluidParameters bouzidi_trt(double tau) {
  FluidParameters parameters;
  parameters.collision = "trt";
  parameters.collision_parameters.tau = tau;
  parameters.wall_rule = "bouzidi";
  return parameters;
}

// Walls at the nodes y = 0 and y = ny - 1, cut by the planes y = 1 - bottom_fraction and
// y = ny - 2 + top_fraction: every link from the first or last fluid row into a wall has
// |c_y| = 1 and so meets its plane at that fraction of its length.
void add_plane_walls(FluidSolver& solver, double bottom_fraction, double top_fraction,
                     const std::array<double, 3>& top_velocity = {0.0, 0.0, 0.0}) {
  testing::add_channel_walls(solver, top_velocity);
  const LatticeGrid& grid = solver.grid();
  std::vector<WallLink> links;
  for (int z = 0; z < grid.nz(); ++z) {
    for (int x = 0; x < grid.nx(); ++x) {
      for (int i = 1; i < kDirections; ++i) {
        if (kVelocities[i][1] == -1) {
          links.push_back({grid.index(x, 1, z), i, bottom_fraction});
        } else if (kVelocities[i][1] == 1) {
          links.push_back({grid.index(x, grid.ny() - 2, z), i, top_fraction});
        }
      }
    }
  }
  ASSERT_EQ(solver.set_wall_links(links), links.size());
}

TEST(WallRules, UnknownNameIsAnInputErrorNamingTheOption) {
  EXPECT_EQ(find_wall_rule("halfway").name, "halfway");
  EXPECT_EQ(find_wall_rule("bouzidi").name, "bouzidi");
  FluidParameters parameters;
  parameters.wall_rule = "quadratic";
  try {
    FluidSolver solver(LatticeGrid(2, 2, 2), parameters);
    FAIL() << "an unknown wall rule must be refused";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("lattice.wall_rule"), std::string::npos) << message;
    EXPECT_NE(message.find("bouzidi"), std::string::npos) << message;
  }
}

// A fluid at rest stays at rest against a resting wall only if the weights of the populations sum
// to one; at q = 1/2 both forms are half-way bounce-back, and so is the fallback.
TEST(WallRules, BouzidiIsConsistentAndMeetsHalfwayAtOneHalf) {
  const auto& bouzidi = *find_wall_rule("bouzidi").weights;
  for (const double q : {1e-9, 0.1, 0.3, 0.4999, 0.5, 0.7, 1.0}) {
    for (const bool behind_is_fluid : {true, false}) {
      const WallLinkWeights w = bouzidi(q, behind_is_fluid);
      EXPECT_NEAR(w.here + w.away + w.behind, 1.0, 1e-15) << q;
    }
  }
  EXPECT_EQ(bouzidi(0.5, true), kHalfwayWeights);
  EXPECT_EQ(bouzidi(0.3, false), kHalfwayWeights);
  EXPECT_EQ(find_wall_rule("halfway").weights(0.3, true), kHalfwayWeights);
}

TEST(WallLinks, SolverTakesWallLinksOnlyAndRefusesBadOnes) {
  FluidSolver solver(LatticeGrid(3, 4, 1), bouzidi_trt(1.0));
  const LatticeGrid& grid = solver.grid();
  solver.set_wall(grid.index(1, 0, 0));
  const std::size_t node = grid.index(1, 1, 0);
  // Direction 4 is (0, -1, 0): into the wall node. Direction 3 points to fluid.
  const std::vector<WallLink> links = {{node, 4, 0.3}, {node, 3, 0.3}};
  EXPECT_EQ(solver.set_wall_links(links), 1u);
  EXPECT_DOUBLE_EQ(solver.boundaries().wall_fraction(node, 4), 0.3);
  EXPECT_DOUBLE_EQ(solver.boundaries().wall_fraction(node, 3), kHalfwayFraction);
  for (const WallLink& bad :
       {WallLink{node, 0, 0.3}, WallLink{node, 19, 0.3}, WallLink{node, 4, 0.0},
        WallLink{node, 4, 1.5}, WallLink{node, 4, std::nan("")}, WallLink{99, 4, 0.3}}) {
    EXPECT_THROW(solver.set_wall_links(std::vector<WallLink>{bad}), InputError);
  }
}

// Linear interpolation is exact for populations linear in space, which simple shear has: the
// profile is exact wherever the walls cut the links, moving wall included, on both forms of the
// rule (q < 1/2 and q >= 1/2) and for BGK as well as TRT.
TEST(CurvedWalls, CouetteIsExactWithWallsOffTheHalfwayPositions) {
  const int width = 16;
  const double wall_speed = 0.02;
  for (const char* collision : {"bgk", "trt"}) {
    for (const auto& [bottom, top] : {std::pair{0.3, 0.7}, std::pair{0.85, 0.15}}) {
      FluidParameters parameters = bouzidi_trt(0.8);
      parameters.collision = collision;
      FluidSolver solver(LatticeGrid(1, width + 2, 1), parameters);
      add_plane_walls(solver, bottom, top, {wall_speed, 0.0, 0.0});
      ASSERT_TRUE(solver.run_to_steady_state({1e-10, 200, 200000}).converged);
      const double bottom_y = 1.0 - bottom;
      const double top_y = width + top;
      const double error = relative_l2_error_x(solver, [&](int, int y, int) {
        return wall_speed * (y - bottom_y) / (top_y - bottom_y);
      });
      EXPECT_LT(error, 1e-8) << collision << " q " << bottom << ", " << top;
    }
  }
}

// The slip of Bouzidi's rule for a parabolic profile u'' = -F/nu with TRT at Lambda = 3/16.
// From the exact steady TRT solution of unidirectional flow (its non-equilibrium parts are
// n+ = -tau+ a u' and n- = const along each link, a = 3 w c_x), the rule differs from the bulk
// solution continued to the node beyond the wall by -a u'' g(q), so the discrete solution is the
// exact parabola plus a slip u_s = F g / (2 nu k) at the wall, k being the rule's weight of the
// moving-wall term (Lambda+ = tau - 1/2):
//   q <  1/2:  g = (1 - 2q) Lambda+ + 1/4 - q^2,                k = 1
//   q >= 1/2:  g = (2q - 1) / (2q) (Lambda+ - (1 + 2q) / 4),     k = 1 / (2q)
// Both vanish at q = 1/2, where the magic Lambda makes bounce-back exact; elsewhere the slip is
// O(dx^2) against u ~ F H^2 / nu, the second order of the rule.
double bouzidi_poiseuille_slip(double q, double force, double tau) {
  const double lambda_even = tau - 0.5;
  const double viscosity = lambda_even / 3.0;
  const double g = q < 0.5 ? (1.0 - 2.0 * q) * lambda_even + 0.25 - q * q
                           : (2.0 * q - 1.0) / (2.0 * q) * (lambda_even - (1.0 + 2.0 * q) / 4.0);
  const double k = q < 0.5 ? 1.0 : 1.0 / (2.0 * q);
  return force * g / (2.0 * viscosity * k);
}

struct PlaneResult {
  double error;            // against the exact parabola
  double predicted_error;  // against the parabola with the predicted slips
};

PlaneResult plane_poiseuille(int width, double bottom, double top, const std::string& rule,
                             double tau) {
  FluidParameters parameters = bouzidi_trt(tau);
  parameters.wall_rule = rule;
  const double bottom_y = 1.0 - bottom;
  const double top_y = width + top;
  const double gap = top_y - bottom_y;
  const double viscosity = (tau - 0.5) / 3.0;
  const double force = 8.0 * viscosity * kWallFlowPeakVelocity / (gap * gap);
  parameters.body_force = {force, 0.0, 0.0};
  FluidSolver solver(LatticeGrid(1, width + 2, 1), parameters);
  add_plane_walls(solver, bottom, top);
  const auto steady = solver.run_to_steady_state({1e-10, 200, 400000});
  EXPECT_TRUE(steady.converged) << steady.relative_velocity_change;
  const auto exact = [&](double y) {
    return force / (2.0 * viscosity) * (y - bottom_y) * (top_y - y);
  };
  const double bottom_slip = bouzidi_poiseuille_slip(bottom, force, tau);
  const double top_slip = bouzidi_poiseuille_slip(top, force, tau);
  return {relative_l2_error_x(solver, [&](int, int y, int) { return exact(y); }),
          relative_l2_error_x(solver, [&](int, int y, int) {
            return exact(y) + bottom_slip + (top_slip - bottom_slip) * (y - bottom_y) / gap;
          })};
}

// tau = 1 (Lambda = 3/16). The walls sit at 0.3 and 0.8 of the links, 0.2 and 0.3 off the
// half-way positions the staircase assumes.
TEST(CurvedWalls, PlanePoiseuilleHasThePredictedSecondOrderSlip) {
  const double tau = 1.0;
  for (const auto& [bottom, top] : {std::pair{0.3, 0.3}, std::pair{0.3, 0.8}}) {
    const PlaneResult coarse = plane_poiseuille(20, bottom, top, "bouzidi", tau);
    const PlaneResult fine = plane_poiseuille(40, bottom, top, "bouzidi", tau);
    const PlaneResult staircase = plane_poiseuille(20, bottom, top, "halfway", tau);
    const double order = std::log2(coarse.error / fine.error);
    std::printf(
        "plane Poiseuille q = %.1f, %.1f, tau %.1f: L2 error bouzidi 20 nodes %.3e, 40 nodes "
        "%.3e, order %.3f (against the predicted slip %.1e, %.1e); half-way 20 nodes %.3e\n",
        bottom, top, tau, coarse.error, fine.error, order, coarse.predicted_error,
        fine.predicted_error, staircase.error);
    // Converged to 1e-10 per 200 steps: the solution is the predicted one to about 1e-9.
    EXPECT_LT(coarse.predicted_error, 1e-8);
    EXPECT_LT(fine.predicted_error, 1e-8);
    EXPECT_LT(coarse.error, 0.01);
    EXPECT_NEAR(order, 2.0, 0.05);
    // Half-way bounce-back puts these walls 0.2 to 0.3 dx off: an O(dx) error, ten times larger.
    EXPECT_GT(staircase.error, 5.0 * coarse.error);
  }
}

struct PipeCase {
  double diameter;  // lattice units
  double offset_y;  // of the lattice against the pipe axis, lattice units
  double offset_z;
};

// Poiseuille flow along x, u = F / (4 nu) (R^2 - r^2), in a geometry::TubeWall one node long (x
// is periodic), set up as fluid_solver.hpp describes; the solver starts at rest.
class PipeFlow {
 public:
  PipeFlow(const PipeCase& pipe, const std::string& rule, double tau, double peak_velocity)
      : tube_({pipe.diameter, 1.0}), grid_um_(geometry::lattice_around(tube_, 1.0)) {
    grid_um_.origin_um += Vec3(0.0, pipe.offset_y, pipe.offset_z);
    const geometry::SolidMask mask = geometry::voxelise(tube_, grid_um_);
    FluidParameters parameters = bouzidi_trt(tau);
    parameters.wall_rule = rule;
    const double viscosity = (tau - 0.5) / 3.0;
    radius_ = 0.5 * pipe.diameter;
    velocity_per_radial_squared_ = peak_velocity / (radius_ * radius_);
    parameters.body_force = {4.0 * viscosity * velocity_per_radial_squared_, 0.0, 0.0};
    solver_ = std::make_unique<FluidSolver>(LatticeGrid(grid_um_.nx, grid_um_.ny, grid_um_.nz),
                                            parameters);
    for (std::size_t node = 0; node < mask.size(); ++node) {
      if (mask[node] == geometry::kSolid) {
        solver_->set_wall(node);
      }
    }
    solver_->set_wall_links(geometry::wall_link_fractions(tube_, grid_um_, mask));
  }

  FluidSolver& solver() { return *solver_; }

  double exact_velocity(int x, int y, int z) const {
    const Vec3 position = grid_um_.node_position_um(x, y, z);
    const double radial_squared = position.y() * position.y() + position.z() * position.z();
    return velocity_per_radial_squared_ * (radius_ * radius_ - radial_squared);
  }

  // Equilibrium at the exact profile: the steady state is the same as from rest, and the run
  // starts within the discretisation error of it.
  void start_at_exact_profile() {
    const LatticeGrid& grid = solver_->grid();
    VectorField velocity{std::vector<double>(grid.node_count(), 0.0),
                         std::vector<double>(grid.node_count(), 0.0),
                         std::vector<double>(grid.node_count(), 0.0)};
    for (std::size_t node = 0; node < grid.node_count(); ++node) {
      const auto [x, y, z] = grid.coordinates(node);
      velocity[0][node] = exact_velocity(x, y, z);
    }
    solver_->initialise_equilibrium(std::vector<double>(grid.node_count(), 1.0), velocity);
  }

  double relative_l2_error() const {
    return relative_l2_error_x(*solver_,
                               [&](int x, int y, int z) { return exact_velocity(x, y, z); });
  }

 private:
  geometry::TubeWall tube_;
  geometry::LatticeGrid grid_um_;
  double radius_ = 0.0;
  double velocity_per_radial_squared_ = 0.0;  // F / (4 nu)
  std::unique_ptr<FluidSolver> solver_;
};

// Steady within 2e-6 of the peak velocity per 200 steps: the slowest mode decays by e in
// R^2 / (5.78 nu) steps (415 at D = 40, tau = 1), so the run ends within ~5e-6 of steady, far
// below the errors measured (>= 3e-4).
double pipe_poiseuille_error(const PipeCase& pipe, double tau) {
  PipeFlow flow(pipe, "bouzidi", tau, kWallFlowPeakVelocity);
  flow.start_at_exact_profile();
  const auto steady = flow.solver().run_to_steady_state({2e-6, 200, 100000});
  EXPECT_TRUE(steady.converged) << steady.relative_velocity_change;
  return flow.relative_l2_error();
}

// TRT, tau = 1 (Lambda = 3/16). Bouzidi's slip differs from link to link with q (see the plane
// test), so the error depends on how the lattice cuts the circle and the order observed between
// two grids scatters about 2. Measured, D -> 2 D with the axis offset against the lattice by:
//   D = 20   (0.30, 0.17)  0.200 % -> 0.038 %, order 2.39
//   D = 20   (0.13, 0.29)  0.168 % -> 0.042 %, order 2.01
//   D = 20   (0.41, 0.08)  0.142 % -> 0.034 %, order 2.07
//   D = 21.4 (0.41, 0.08)  0.132 % -> 0.030 %, order 2.12
//   D = 20   (0.50, 0.50)  0.219 % -> 0.036 %, order 2.61   axis on a node
//   D = 20   (0.00, 0.00)  0.171 % -> 0.055 %, order 1.63   axis midway between nodes
// The last two are lattice-symmetric: the cut repeats in all four quadrants, so one q distribution
// is not averaged out, and the last is the one grid measured below order 1.8 (at tau = 0.8 the
// orders scatter as much, 1.74 to 2.48, over other grids). Staircase (half-way) walls give 2.4 %
// to 2.8 % at D = 20 on these grids. Tested: under 1 % at 20 nodes on every grid, order above 1.8
// on generic placements, including another diameter, and above 1.5 on the symmetric outlier.
TEST(CurvedWalls, PipePoiseuilleUnderOnePercentAtTwentyNodesAndSecondOrder) {
  const double tau = 1.0;
  struct Expectation {
    PipeCase pipe;
    double minimum_order;
  };
  for (const auto& [pipe, minimum_order] :
       {Expectation{{20.0, 0.3, 0.17}, 1.8}, Expectation{{20.0, 0.13, 0.29}, 1.8},
        Expectation{{21.4, 0.41, 0.08}, 1.8}, Expectation{{20.0, 0.0, 0.0}, 1.5}}) {
    const double coarse = pipe_poiseuille_error(pipe, tau);
    const double fine =
        pipe_poiseuille_error({2.0 * pipe.diameter, pipe.offset_y, pipe.offset_z}, tau);
    const double order = std::log2(coarse / fine);
    std::printf(
        "pipe Poiseuille bouzidi, tau %.1f, D %.1f, axis offset (%.2f, %.2f): L2 error %.3e, "
        "at 2 D %.3e, order %.2f\n",
        tau, pipe.diameter, pipe.offset_y, pipe.offset_z, coarse, fine, order);
    EXPECT_LT(coarse, 0.01) << pipe.diameter;
    EXPECT_GT(order, minimum_order) << pipe.diameter << " " << pipe.offset_y;
  }
}

// Interpolated bounce-back is not conservative: the population a link returns differs from the
// one it received by, for q < 1/2, (1 - 2q) (f*_h(x + c_i) - f*_h(x)). In the pipe the parts
// linear in u cancel between the links (c_x, c_y, c_z) and (-c_x, c_y, c_z), which have the same
// q; what is left comes from the quadratic terms of the equilibrium, so the drift is quadratic in
// the velocity. Measured from rest at u_max = 0.01 (Ma = 0.017), D = 20: -6e-9 of the mass per
// step (and ~8 times less at D = 40: the leak per link falls like (u / R)^2, the links per node
// like 1 / R). Bound: 1e-8 per step, i.e. under 0.1 % over 10^5 steps; half-way walls lose none.
TEST(CurvedWalls, MassDriftIsSmallAndQuadraticInTheVelocity) {
  const PipeCase pipe{20.0, 0.3, 0.17};
  const std::size_t steps = 2000;
  const auto relative_drift = [&](const std::string& rule, double peak_velocity) {
    PipeFlow flow(pipe, rule, 1.0, peak_velocity);
    const double initial_mass = flow.solver().total_mass();
    flow.solver().advance(steps);
    return (flow.solver().total_mass() - initial_mass) / initial_mass;
  };
  const double slow = relative_drift("bouzidi", kWallFlowPeakVelocity);
  const double fast = relative_drift("bouzidi", 2.0 * kWallFlowPeakVelocity);
  std::printf("pipe mass drift per step, bouzidi: %.2e at u_max %.2f, %.2e at %.2f\n", slow / steps,
              kWallFlowPeakVelocity, fast / steps, 2.0 * kWallFlowPeakVelocity);
  EXPECT_LT(std::abs(slow) / steps, 1e-8);
  // Quadratic: the next terms are O(u^4), 4e-4 relative at u_max = 0.02.
  EXPECT_NEAR(fast / slow, 4.0, 0.02);
  EXPECT_LT(std::abs(relative_drift("halfway", kWallFlowPeakVelocity)), 1e-12);
}

}  // namespace
}  // namespace rbcsim::lattice
