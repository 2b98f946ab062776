#include "distributed_cases.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "ibm/delta_kernels.hpp"
#include "ibm/grid_view.hpp"
#include "ibm/interpolation_stencil.hpp"
#include "ibm/transfer.hpp"
#include "parallel/distributed_ibm.hpp"

namespace rbcsim::parallel::testing {

namespace {

bool channel_wall(int /*x*/, int y, int /*z*/) { return y == 0 || y == kCaseNy - 1; }

// The channel with a block across it that straddles block and slab faces (z 3-6: the faces at 4
// and 6 of blocks of 2 planes), so that links along z and diagonal ones meet walls in ghost planes.
bool obstructed_channel_wall(int x, int y, int z) {
  return channel_wall(x, y, z) || (x >= 1 && x <= 3 && y >= 2 && y <= 4 && z >= 3 && z <= 6);
}

WallPredicate case_walls(const DistributedCase& flow) {
  if (!flow.walls) return {};
  return flow.obstacle ? WallPredicate(obstructed_channel_wall) : WallPredicate(channel_wall);
}

// A start that varies along every axis, z above all (a flow uniform in z would hide a halo that
// mixes up planes).
DistributedFluid::NodeState initial_state(int x, int y, int z) {
  const double phase = 2.0 * std::numbers::pi * z / kCaseNz;
  return {1.0 + 0.01 * std::cos(phase + 0.2 * x),
          {0.02 * std::sin(phase) + 0.003 * y, 0.01 * std::cos(2.0 * phase),
           0.015 * std::sin(phase + x)}};
}

// The viscosity classes of the contrast cases: an ellipsoidal blob across z 2-9 (the faces of
// blocks of 2 planes and of every slab), its class falling from 255 at the centre to 0 at the
// edge, so that neighbouring nodes relax at different rates.
lattice::ViscosityClass blob_class(int x, int y, int z) {
  const double r2 =
      std::pow((x - 2.5) / 2.5, 2) + std::pow((y - 3.0) / 2.5, 2) + std::pow((z - 5.5) / 4.0, 2);
  return lattice::viscosity_class(std::max(0.0, 1.0 - r2));
}

std::vector<lattice::ViscosityClass> blob_classes(const lattice::LatticeGrid& grid) {
  std::vector<lattice::ViscosityClass> classes(grid.node_count());
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) classes[grid.index(x, y, z)] = blob_class(x, y, z);
    }
  }
  return classes;
}

// A force density that differs at every node and step, the same wherever it is computed.
std::array<double, 3> test_force(int x, int y, int z, std::size_t step) {
  const double phase = 0.3 * x + 0.7 * y + 1.1 * z + 0.05 * static_cast<double>(step);
  return {1e-5 * std::sin(phase), 2e-5 * std::cos(1.3 * phase), -1e-5 * std::sin(0.7 * phase)};
}

}  // namespace

std::vector<DistributedCase> distributed_cases() {
  std::vector<DistributedCase> cases;
  lattice::FluidParameters channel;
  channel.body_force = {1e-5, 0.0, 2e-6};
  cases.push_back({"aa_double_channel", channel, true, false});
  lattice::FluidParameters single = channel;
  single.precision = lattice::Precision::single_precision;
  cases.push_back({"aa_single_channel", single, true, false});
  lattice::FluidParameters reference = channel;
  reference.kernel = "reference";
  cases.push_back({"reference_channel", reference, true, false});
  cases.push_back({"aa_force_field", channel, true, true});
  DistributedCase obstructed{"aa_obstacle_across_slabs", channel, true, true};
  obstructed.obstacle = true;
  cases.push_back(obstructed);
  lattice::FluidParameters sheared;
  sheared.lees_edwards_velocity = 0.02;
  cases.push_back({"aa_lees_edwards", sheared, false, false});
  lattice::FluidParameters contrast = channel;
  contrast.inner_viscosity_ratio = 5.0;
  DistributedCase cytoplasm{"aa_viscosity_contrast", contrast, true, true};
  cytoplasm.viscosity_classes = true;
  cases.push_back(cytoplasm);
  // The reference twin of the AA kernel's crossing-populations halo.
  const std::size_t aa_cases = cases.size();
  for (std::size_t k = 0; k < aa_cases; ++k) {
    if (cases[k].parameters.kernel != "optimised" || cases[k].parameters.lees_edwards_velocity) {
      continue;  // the full state already
    }
    DistributedCase full = cases[k];
    full.name += "_full_state_halo";
    full.scheme = HaloScheme::full_state;
    cases.push_back(full);
  }
  return cases;
}

DistributedCase case_named(std::string_view name) {
  for (const auto& flow : distributed_cases()) {
    if (flow.name == name) return flow;
  }
  throw std::logic_error("no distributed case named " + std::string(name));
}

std::unique_ptr<lattice::FluidSolver> make_undivided(const DistributedCase& flow) {
  const lattice::LatticeGrid grid(kCaseNx, kCaseNy, kCaseNz);
  auto solver = std::make_unique<lattice::FluidSolver>(grid, flow.parameters);
  for (int z = 0; z < kCaseNz; ++z) {
    for (int y = 0; y < kCaseNy; ++y) {
      for (int x = 0; x < kCaseNx; ++x) {
        if (flow.walls && case_walls(flow)(x, y, z)) solver->set_wall(grid.index(x, y, z));
      }
    }
  }
  std::vector<double> density(grid.node_count());
  lattice::VectorField velocity;
  for (auto& component : velocity) component.resize(grid.node_count());
  for (int z = 0; z < kCaseNz; ++z) {
    for (int y = 0; y < kCaseNy; ++y) {
      for (int x = 0; x < kCaseNx; ++x) {
        const auto state = initial_state(x, y, z);
        density[grid.index(x, y, z)] = state.density;
        for (int axis = 0; axis < 3; ++axis) {
          velocity[axis][grid.index(x, y, z)] = state.velocity[axis];
        }
      }
    }
  }
  solver->initialise_equilibrium(density, velocity);
  if (flow.viscosity_classes) {
    const auto classes = blob_classes(grid);
    std::copy(classes.begin(), classes.end(), solver->viscosity_classes().begin());
  }
  return solver;
}

void advance_undivided(const DistributedCase& flow, lattice::FluidSolver& solver,
                       std::size_t steps) {
  const lattice::LatticeGrid& grid = solver.grid();
  for (std::size_t s = 0; s < steps; ++s) {
    const std::size_t step = solver.time();
    if (flow.force_field) {
      auto& force = solver.force_density();
      for (int z = 0; z < kCaseNz; ++z) {
        for (int y = 0; y < kCaseNy; ++y) {
          for (int x = 0; x < kCaseNx; ++x) {
            const auto f = test_force(x, y, z, step);
            for (int axis = 0; axis < 3; ++axis) force[axis][grid.index(x, y, z)] += f[axis];
          }
        }
      }
    }
    solver.step();
  }
}

std::unique_ptr<DistributedFluid> make_distributed(const DistributedCase& flow,
                                                   const Communicator& communicator) {
  const WallPredicate walls = case_walls(flow);
  auto fluid = std::make_unique<DistributedFluid>(communicator,
                                                  lattice::LatticeGrid(kCaseNx, kCaseNy, kCaseNz),
                                                  2, flow.parameters, walls, flow.scheme);
  fluid->initialise_equilibrium(initial_state);
  if (flow.viscosity_classes) {
    fluid->set_viscosity_classes(blob_classes(lattice::LatticeGrid(kCaseNx, kCaseNy, kCaseNz)));
  }
  return fluid;
}

void advance_distributed(const DistributedCase& flow, DistributedFluid& fluid, std::size_t steps) {
  for (std::size_t s = 0; s < steps; ++s) {
    const std::size_t step = fluid.local().time();
    if (flow.force_field) {
      auto& force = fluid.force_density();
      for (int z = fluid.z_begin(); z < fluid.z_end(); ++z) {
        for (int y = 0; y < kCaseNy; ++y) {
          for (int x = 0; x < kCaseNx; ++x) {
            const auto f = test_force(x, y, z, step);
            for (int axis = 0; axis < 3; ++axis) force[axis][fluid.local_node(x, y, z)] += f[axis];
          }
        }
      }
    }
    fluid.step();
  }
}

std::vector<double> run_undivided(const DistributedCase& flow) {
  auto solver = make_undivided(flow);
  advance_undivided(flow, *solver, kCaseSteps);
  return solver->stored_populations(0, solver->grid().node_count());
}

std::vector<double> run_distributed(const DistributedCase& flow, const Communicator& communicator) {
  auto fluid = make_distributed(flow, communicator);
  advance_distributed(flow, *fluid, kCaseSteps);
  fluid->require_finite_velocity();
  return fluid->gather_stored_populations();
}

namespace {

constexpr std::size_t kPoints = 48;

std::vector<Vec3> starting_points() {
  std::vector<Vec3> points;
  for (std::size_t k = 0; k < kPoints; ++k) {
    const double t = static_cast<double>(k);
    // Spread over the box, some next to the walls, some beyond the periodic seam in z.
    points.emplace_back(std::fmod(0.37 * t * t + 0.5, kCaseNx),
                        0.7 + std::fmod(1.91 * t, kCaseNy - 2.4),
                        -1.5 + std::fmod(2.73 * t + 0.2, kCaseNz + 3.0));
  }
  return points;
}

std::vector<Vec3> spring_forces(const std::vector<Vec3>& points, const std::vector<Vec3>& anchors) {
  std::vector<Vec3> forces;
  for (std::size_t k = 0; k < points.size(); ++k) {
    forces.push_back(-2e-3 * (points[k] - anchors[k]) + Vec3(0.0, 0.0, 4e-4));
  }
  return forces;
}

std::vector<double> flat(const std::vector<Vec3>& points) {
  std::vector<double> values;
  for (const Vec3& p : points) values.insert(values.end(), {p.x(), p.y(), p.z()});
  return values;
}

DistributedCase coupled_channel() {
  DistributedCase flow = distributed_cases().front();  // the AA kernel in a channel
  flow.parameters.body_force = {0.0, 0.0, 0.0};
  return flow;
}

}  // namespace

CoupledState run_coupled_undivided(std::string_view kernel, std::size_t steps) {
  const DistributedCase flow = coupled_channel();
  auto solver = make_undivided(flow);
  const ibm::GridView grid{kCaseNx, kCaseNy, kCaseNz, true, true, true};
  std::vector<std::uint8_t> solid(solver->grid().node_count());
  for (std::size_t node = 0; node < solid.size(); ++node) {
    solid[node] = solver->boundaries().is_fluid(node) ? 0 : 1;
  }
  const std::vector<Vec3> anchors = starting_points();
  std::vector<Vec3> points = anchors;
  std::vector<Vec3> velocities(points.size());
  ibm::InterpolationStencil stencil;
  const ibm::DeltaKernel& delta = ibm::find_delta_kernel(kernel);
  for (std::size_t step = 0; step < steps; ++step) {
    stencil.build(delta, grid, points, solid.data());
    auto& force = solver->force_density();
    ibm::spread_forces(stencil, spring_forces(points, anchors), grid, force[0].data(),
                       force[1].data(), force[2].data());
    solver->step();
    const auto& u = solver->velocity();
    ibm::interpolate_velocity(stencil, grid, u[0].data(), u[1].data(), u[2].data(), velocities);
    for (std::size_t k = 0; k < points.size(); ++k) points[k] += velocities[k];
  }
  return {solver->stored_populations(0, solver->grid().node_count()), flat(points)};
}

CoupledState run_coupled_distributed(std::string_view kernel, std::size_t steps,
                                     const Communicator& communicator) {
  const DistributedCase flow = coupled_channel();
  auto fluid = make_distributed(flow, communicator);
  DistributedImmersedBoundary boundary(*fluid, kernel);
  const std::vector<Vec3> anchors = starting_points();
  std::vector<Vec3> points = anchors;
  for (std::size_t step = 0; step < steps; ++step) {
    boundary.build(points);
    boundary.spread(spring_forces(points, anchors), *fluid);
    fluid->step();
    const std::vector<Vec3> velocities = boundary.interpolate(*fluid);
    for (std::size_t k = 0; k < points.size(); ++k) points[k] += velocities[k];
  }
  CoupledState state{fluid->gather_stored_populations(), {}};
  if (communicator.is_root()) state.positions = flat(points);
  return state;
}

std::unique_ptr<lattice::FluidSolver> make_tube_channel(const std::string& kernel,
                                                        const std::string& wall_rule,
                                                        std::size_t steps) {
  const lattice::LatticeGrid grid(8, 6, 12);
  lattice::FluidParameters parameters;
  parameters.kernel = kernel;
  parameters.wall_rule = wall_rule;
  auto whole = std::make_unique<lattice::FluidSolver>(grid, parameters);
  std::vector<lattice::WallLink> links;
  for (int z = 0; z < grid.nz(); ++z) {
    for (int x = 0; x < grid.nx(); ++x) {
      whole->set_wall(grid.index(x, 0, z));
      whole->set_wall(grid.index(x, grid.ny() - 1, z), {0.004, 0.0, 0.001});
      for (int i = 1; i < lattice::kDirections; ++i) {
        const int c_y = lattice::kVelocities[i][1];
        if (c_y == -1) links.push_back({grid.index(x, 1, z), i, 0.3});
        if (c_y == 1) links.push_back({grid.index(x, grid.ny() - 2, z), i, 0.7});
      }
    }
    for (int y = 1; y < grid.ny() - 1; ++y) {
      whole->set_velocity_inlet(grid.index(0, y, z),
                                {0.01 * y * (grid.ny() - 1 - y) / 4.0, 0.0, 0.0});
      whole->set_pressure_outlet(grid.index(grid.nx() - 1, y, z), 1.0);
    }
  }
  if (whole->set_wall_links(links) == 0) throw std::logic_error("tube channel: no wall links");
  whole->initialise_equilibrium(1.0, {0.005, 0.0, 0.0});
  whole->advance(steps);
  return whole;
}

std::vector<double> at_fluid_nodes(const lattice::FluidSolver& solver,
                                   std::span<const double> stored_populations) {
  const std::size_t nodes = solver.grid().node_count();
  std::vector<double> kept;
  for (std::size_t k = 0; k < stored_populations.size(); ++k) {
    if (solver.boundaries().is_fluid(k % nodes)) kept.push_back(stored_populations[k]);
  }
  return kept;
}

std::filesystem::path checkpoint_file(const Communicator& world, const std::string& prefix) {
  double root_pid = static_cast<double>(::getpid());
  world.broadcast_from_root(std::span<double>(&root_pid, 1));
  return std::filesystem::temp_directory_path() /
         (prefix + std::to_string(static_cast<long>(root_pid)) + ".bin");
}

}  // namespace rbcsim::parallel::testing
