// The optimised kernel against the reference kernel, thread-count independence, and mass
// conservation, on random-ish states with solids, force fields, every boundary kind and every wall
// rule, with one viscosity everywhere and with per-node viscosity classes that change from node to
// node.
#include "lattice/fluid_solver.hpp"

#include <omp.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace rbcsim::lattice {
namespace {

struct Scenario {
  bool sliding = false;       // Lees-Edwards in y (else periodic or walls in y)
  bool open_channel = false;  // walls in y (top one moving), inlet at x = 0, outlet at x = nx - 1
  bool moving_obstacles = true;  // obstacle nodes with random wall velocities (break mass balance)
  std::string collision = "trt";
  std::string wall_rule = "halfway";  // other rules get random wall fractions on every wall link
  double viscosity_ratio = 1.0;       // other ratios get a random viscosity class at every node
};

const LatticeGrid kGrid(20, 16, 14);  // above the threshold at which kernels use threads

std::array<double, 3> random_vector(std::mt19937& random, double magnitude) {
  std::uniform_real_distribution<double> uniform(-magnitude, magnitude);
  return {uniform(random), uniform(random), uniform(random)};
}

// Every link from a fluid node into a wall gets a fraction in (0, 1], some exactly 1/2 and 1, so
// that every form of the interpolated rule and its half-way fallback are exercised.
void set_random_wall_fractions(FluidSolver& solver) {
  const LatticeGrid& grid = solver.grid();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<WallLink> links;
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    for (int i = 1; i < kDirections; ++i) {
      const double draw = unit(random);
      const double fraction = draw < 0.1 ? 0.5 : (draw < 0.2 ? 1.0 : 1.0 - unit(random));
      links.push_back({node, i, fraction});
    }
  }
  solver.set_wall_links(links);
}

void build_geometry(const Scenario& scenario, FluidSolver& solver) {
  const LatticeGrid& grid = solver.grid();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    const auto [x, y, z] = grid.coordinates(node);
    if (scenario.open_channel && (y == 0 || y == grid.ny() - 1)) {
      solver.set_wall(node, y == 0 ? std::array<double, 3>{0.0, 0.0, 0.0}
                                   : std::array<double, 3>{0.03, 0.0, 0.01});
    } else if (scenario.open_channel && x == 0) {
      solver.set_velocity_inlet(node, {0.02 * (1.0 + 0.1 * y), 0.001 * z, 0.0});
    } else if (scenario.open_channel && x == grid.nx() - 1) {
      solver.set_pressure_outlet(node, 1.0 + 0.001 * z);
    } else if (y >= 1 && y <= grid.ny() - 2) {
      // Random obstacles off the sliding planes, some next to them: an interpolated link there
      // has no fluid node behind it, across the plane.
      const double draw = unit(random);
      if (draw < 0.08) {
        solver.set_wall(node);
      } else if (draw < 0.12 && scenario.moving_obstacles) {
        solver.set_wall(node, random_vector(random, 0.03));
      } else if (draw < 0.13 && scenario.moving_obstacles) {
        solver.set_pressure_outlet(node, 1.0 + 0.02 * unit(random));
      }
    }
  }
  if (scenario.wall_rule != "halfway") {
    set_random_wall_fractions(solver);
  }
}

// Every class 0..255 somewhere, neighbours unrelated: the sharpest contrast the kernels can meet.
void set_random_viscosity_classes(FluidSolver& solver) {
  std::mt19937 random(17);
  std::uniform_int_distribution<int> draw(0, kViscosityClasses - 1);
  for (ViscosityClass& node_class : solver.viscosity_classes()) {
    node_class = static_cast<ViscosityClass>(draw(random));
  }
}

// Equilibrium at random density and velocity plus random non-equilibrium parts.
std::vector<double> random_populations(std::size_t node_count) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> populations(kDirections * node_count);
  for (std::size_t node = 0; node < node_count; ++node) {
    const double density = 1.0 + 0.03 * unit(random);
    const auto velocity = random_vector(random, 0.04);
    for (int i = 0; i < kDirections; ++i) {
      populations[i * node_count + node] =
          equilibrium(i, density, velocity) + 0.01 * kWeights[i] * unit(random);
    }
  }
  return populations;
}

struct Trajectory {
  std::vector<std::vector<double>> fields;  // per step: density, then u_x, u_y, u_z
  std::vector<double> populations;          // pre-collision, at the end
  double initial_mass = 0.0;
  double final_mass = 0.0;
  bool force_zero_after_every_step = true;
};

// Where the force field is non-zero at each step: everywhere (random), at a few scattered nodes
// (the rest exactly zero, as around one cell; some rows forced at one end or both, and a -0.0),
// or nowhere (the field handed out but zero). The optimised kernel skips the forcing terms where
// a row is zero; the reference kernel reads every node.
enum class ForceLayout { everywhere, sparse, zero };

void set_sparse_force(std::mt19937& random, VectorField& force) {
  const LatticeGrid& grid = kGrid;
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<std::size_t> node(0, grid.node_count() - 1);
  for (int k = 0; k < 30; ++k) {
    const std::size_t n = node(random);
    for (auto& component : force) component[n] = 1e-4 * unit(random);
  }
  const std::size_t row = node(random) / grid.nx() * grid.nx();
  force[0][row] = 1e-4;                   // the row's first node
  force[2][row + grid.nx() - 1] = -1e-4;  // and its last
  // Forced by its bits though it adds nothing: a span search that disagreed with the row's test
  // about it would run past the row's end.
  force[1][grid.index(3, 5, 7)] = -0.0;
}

// zero_classes: keep every node in viscosity class 0 (the outer fluid) despite a ratio.
Trajectory run(const Scenario& scenario, const std::string& kernel, std::size_t steps, int threads,
               bool zero_classes = false, ForceLayout layout = ForceLayout::everywhere,
               bool body_force = true) {
  const int previous_threads = omp_get_max_threads();
  omp_set_num_threads(threads);
  FluidParameters parameters;
  parameters.kernel = kernel;
  parameters.collision = scenario.collision;
  parameters.wall_rule = scenario.wall_rule;
  parameters.collision_parameters.tau = 0.8;
  if (body_force) parameters.body_force = {2e-5, -1e-5, 3e-6};
  if (scenario.sliding) {
    parameters.lees_edwards_velocity = 0.04;
  }
  parameters.inner_viscosity_ratio = scenario.viscosity_ratio;
  FluidSolver solver(kGrid, parameters);
  build_geometry(scenario, solver);
  if (solver.has_viscosity_contrast() && !zero_classes) {
    set_random_viscosity_classes(solver);
  }
  solver.initialise_populations(random_populations(kGrid.node_count()));
  Trajectory trajectory;
  trajectory.initial_mass = solver.total_mass();
  std::mt19937 random(13);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (std::size_t s = 0; s < steps; ++s) {
    VectorField& force = solver.force_density();
    if (layout == ForceLayout::everywhere) {
      for (auto& component : force) {
        for (double& value : component) {
          value = 1e-4 * unit(random);
        }
      }
    } else if (layout == ForceLayout::sparse) {
      set_sparse_force(random, force);
    }
    solver.step();
    for (const auto& component : force) {
      trajectory.force_zero_after_every_step =
          trajectory.force_zero_after_every_step &&
          std::all_of(component.begin(), component.end(), [](double f) { return f == 0.0; });
    }
    std::vector<double> fields = solver.density();
    for (const auto& component : solver.velocity()) {
      fields.insert(fields.end(), component.begin(), component.end());
    }
    trajectory.fields.push_back(std::move(fields));
  }
  trajectory.populations = solver.pre_collision_populations();
  trajectory.final_mass = solver.total_mass();
  omp_set_num_threads(previous_threads);
  return trajectory;
}

// Largest difference over the fluid nodes (solid nodes' populations are not part of the state).
double largest_fluid_difference(const std::vector<double>& a, const std::vector<double>& b,
                                const FluidSolver& geometry) {
  const std::size_t node_count = kGrid.node_count();
  double largest = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (geometry.boundaries().is_fluid(k % node_count)) {
      largest = std::max(largest, std::abs(a[k] - b[k]));
    }
  }
  return largest;
}

const std::vector<Scenario> kScenarios = {{true, false, true, "trt"},
                                          {false, true, true, "trt"},
                                          {true, false, true, "bgk"},
                                          {true, false, true, "trt", "bouzidi"},
                                          {false, true, true, "bgk", "bouzidi"},
                                          {true, false, true, "trt", "halfway", 5.0},
                                          {false, true, true, "trt", "bouzidi", 5.0},
                                          {true, false, true, "bgk", "bouzidi", 0.3}};

// The padding between population arrays (fluid_kernel.hpp): every array holds its nodes, starts
// on a cache line, and the stride is an odd number of lines, so that 19 arrays never share their
// cache sets, also when the node count is a power of two (128^3).
TEST(PopulationStride, IsAnOddNumberOfCacheLinesHoldingEveryNode) {
  for (const std::size_t node_count :
       {std::size_t{1}, std::size_t{8}, std::size_t{16}, std::size_t{40 * 40 * 20},
        std::size_t{128 * 128 * 128}, std::size_t{127 * 129 * 131}}) {
    const std::size_t stride = population_stride(node_count);
    EXPECT_GE(stride, node_count) << node_count;
    EXPECT_LT(stride, node_count + 16) << node_count;  // at most two lines of padding
    EXPECT_EQ(stride % 8, 0u) << node_count;
    EXPECT_EQ((stride / 8) % 2, 1u) << node_count;
  }
}

// With padding, the kernels and the solver's packed interface still address every node: a state
// written packed reads back packed unchanged.
TEST(PopulationStride, PackedPopulationsRoundTrip) {
  FluidArrays arrays(kGrid.node_count());
  ASSERT_GT(arrays.population_stride, kGrid.node_count());  // the test needs real padding
  const auto packed = random_populations(kGrid.node_count());
  unpack_populations(packed, arrays);
  EXPECT_EQ(packed_populations(arrays), packed);
}

// Seven steps: the AA kernel is compared after local and after streaming steps, whose
// populations are recovered from the swapped layout.
TEST(KernelEquivalence, OptimisedMatchesReferenceWithEveryBoundary) {
  for (const auto& scenario : kScenarios) {
    FluidSolver geometry(kGrid, {});
    build_geometry(scenario, geometry);
    for (const std::size_t steps : {6u, 7u}) {
      const Trajectory reference = run(scenario, "reference", steps, 1);
      const Trajectory optimised = run(scenario, "optimised", steps, 1);
      for (std::size_t s = 0; s < steps; ++s) {
        EXPECT_LT(largest_fluid_difference(reference.fields[s], optimised.fields[s], geometry),
                  1e-13)
            << "step " << s << (scenario.sliding ? " sliding " : " open channel ")
            << scenario.wall_rule << " viscosity ratio " << scenario.viscosity_ratio;
      }
      EXPECT_LT(largest_fluid_difference(reference.populations, optimised.populations, geometry),
                1e-13)
          << steps << " steps" << (scenario.sliding ? " sliding " : " open channel ")
          << scenario.wall_rule << " viscosity ratio " << scenario.viscosity_ratio;
    }
  }
}

// Where the force field is zero the optimised kernel leaves the forcing terms out, row by row
// (with the body force too where there is none): the same flow as the reference kernel's, which
// forces every node, and the field zero again after every step.
TEST(KernelEquivalence, OptimisedMatchesReferenceWhereTheForceIsSparseOrZero) {
  for (const auto& scenario : kScenarios) {
    FluidSolver geometry(kGrid, {});
    build_geometry(scenario, geometry);
    for (const ForceLayout layout : {ForceLayout::sparse, ForceLayout::zero}) {
      for (const bool body_force : {false, true}) {
        const std::size_t steps = 7;
        const Trajectory reference =
            run(scenario, "reference", steps, 1, false, layout, body_force);
        const Trajectory optimised =
            run(scenario, "optimised", steps, 1, false, layout, body_force);
        const std::string label = std::string(layout == ForceLayout::sparse ? "sparse" : "zero") +
                                  (body_force ? " with" : " without") + " body force, " +
                                  scenario.collision + " " + scenario.wall_rule +
                                  (scenario.sliding ? " sliding" : " open channel");
        for (std::size_t s = 0; s < steps; ++s) {
          EXPECT_LT(largest_fluid_difference(reference.fields[s], optimised.fields[s], geometry),
                    1e-13)
              << "step " << s << ", " << label;
        }
        EXPECT_LT(largest_fluid_difference(reference.populations, optimised.populations, geometry),
                  1e-13)
            << label;
        EXPECT_TRUE(optimised.force_zero_after_every_step) << label;
        EXPECT_TRUE(reference.force_zero_after_every_step) << label;
      }
    }
  }
}

// A sparse force on one and two threads: the same bits.
TEST(KernelEquivalence, SparseForcingIsBitIdenticalOnOneAndTwoThreads) {
  for (const auto& scenario : kScenarios) {
    const Trajectory one = run(scenario, "optimised", 5, 1, false, ForceLayout::sparse, false);
    const Trajectory two = run(scenario, "optimised", 5, 2, false, ForceLayout::sparse, false);
    EXPECT_TRUE(one.fields == two.fields) << scenario.collision << " " << scenario.wall_rule;
    EXPECT_TRUE(one.populations == two.populations);
  }
}

TEST(KernelEquivalence, OneAndTwoThreadsAreBitIdentical) {
  for (const char* kernel : {"optimised", "reference"}) {
    for (const auto& scenario : kScenarios) {
      const Trajectory one = run(scenario, kernel, 5, 1);
      const Trajectory two = run(scenario, kernel, 5, 2);
      EXPECT_TRUE(one.fields == two.fields) << kernel;
      EXPECT_TRUE(one.populations == two.populations) << kernel;
      EXPECT_EQ(one.final_mass, two.final_mass) << kernel;
    }
  }
}

// With a viscosity ratio but every node in class 0 (outside every cell), both kernels take the
// per-node path and must give exactly the uniform kernels' bits: class 0 holds the plain rates.
TEST(KernelEquivalence, EveryNodeInClassZeroIsTheUniformKernelBitForBit) {
  for (const char* kernel : {"optimised", "reference"}) {
    for (const auto& scenario : kScenarios) {
      if (scenario.viscosity_ratio != 1.0) continue;
      Scenario contrast = scenario;
      contrast.viscosity_ratio = 5.0;
      const auto steps = 5u;
      const Trajectory uniform = run(scenario, kernel, steps, 1);
      const Trajectory per_node = run(contrast, kernel, steps, 1, /*zero_classes=*/true);
      EXPECT_TRUE(uniform.fields == per_node.fields) << kernel << " " << scenario.collision;
      EXPECT_TRUE(uniform.populations == per_node.populations) << kernel;
    }
  }
}

// Periodic, Lees-Edwards and resting bounce-back walls with forcing exchange no mass: what is
// left is round-off, about 1e-16 per population and step.
TEST(MassConservation, RoundOffOnlyWithPeriodicSlidingAndBounceBack) {
  for (const char* kernel : {"optimised", "reference"}) {
    for (const bool sliding : {false, true}) {
      const Scenario scenario{sliding, false, false, "trt"};
      const Trajectory trajectory = run(scenario, kernel, 100, 1);
      const double relative_change =
          std::abs(trajectory.final_mass - trajectory.initial_mass) / trajectory.initial_mass;
      EXPECT_LT(relative_change, 1e-12) << kernel << (sliding ? " sliding" : " periodic");
    }
  }
}

}  // namespace
}  // namespace rbcsim::lattice
