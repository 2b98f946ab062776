#include "lattice/reference_kernel.hpp"

#include "lattice/lees_edwards.hpp"

#include <cstdint>
#include <stdexcept>

namespace rbcsim::lattice {
namespace {

double guo_source(int direction, const std::array<double, 3>& velocity,
                  const std::array<double, 3>& force) {
  const auto& c = kVelocities[direction];
  const double cu = dot_velocity(direction, velocity);
  double source = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    source += ((c[axis] - velocity[axis]) * kInverseSoundSpeedSquared +
               cu * c[axis] * 2.0 * kHalfInverseSoundSpeedFourth) *
              force[axis];
  }
  return kWeights[direction] * source;
}

std::array<double, 3> node_force(const FluidArrays& arrays, const StepParameters& parameters,
                                 std::size_t node) {
  std::array<double, 3> force = parameters.body_force;
  if (parameters.force_field_active) {
    for (int axis = 0; axis < 3; ++axis) {
      force[axis] += arrays.force_density[axis][node];
    }
  }
  return force;
}

std::array<double, 3> node_velocity(const FluidArrays& arrays, std::size_t node) {
  return {arrays.velocity[0][node], arrays.velocity[1][node], arrays.velocity[2][node]};
}

}  // namespace

void collide_node_reference(std::array<double, kDirections>& f, const std::array<double, 3>& force,
                            const RelaxationRates& rates, double& density,
                            std::array<double, 3>& velocity) {
  density = 0.0;
  std::array<double, 3> momentum = {0.0, 0.0, 0.0};
  for (int i = 0; i < kDirections; ++i) {
    density += f[i];
    for (int axis = 0; axis < 3; ++axis) {
      momentum[axis] += f[i] * kVelocities[i][axis];
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    velocity[axis] = (momentum[axis] + 0.5 * force[axis]) / density;
  }

  std::array<double, kDirections> f_eq{};
  std::array<double, kDirections> source{};
  for (int i = 0; i < kDirections; ++i) {
    f_eq[i] = equilibrium(i, density, velocity);
    source[i] = guo_source(i, velocity, force);
  }

  std::array<double, kDirections> post{};
  for (int i = 0; i < kDirections; ++i) {
    const int o = kOpposite[i];
    const double even_deviation = 0.5 * (f[i] + f[o]) - 0.5 * (f_eq[i] + f_eq[o]);
    const double odd_deviation = 0.5 * (f[i] - f[o]) - 0.5 * (f_eq[i] - f_eq[o]);
    const double even_source = 0.5 * (source[i] + source[o]);
    const double odd_source = 0.5 * (source[i] - source[o]);
    post[i] = f[i] - rates.even * even_deviation - rates.odd * odd_deviation +
              (1.0 - 0.5 * rates.even) * even_source + (1.0 - 0.5 * rates.odd) * odd_source;
  }
  f = post;
}

void collide_reference(const LatticeSetup& setup, FluidArrays& arrays,
                       const StepParameters& parameters) {
  const std::size_t stride = arrays.population_stride;
  const auto signed_count = static_cast<std::int64_t>(setup.grid.node_count());
#pragma omp parallel for schedule(static) if (setup.grid.worth_threads())
  for (std::int64_t signed_node = 0; signed_node < signed_count; ++signed_node) {
    const auto node = static_cast<std::size_t>(signed_node);
    if (!setup.boundaries.is_fluid(node)) {
      continue;
    }
    std::array<double, kDirections> f{};
    for (int i = 0; i < kDirections; ++i) {
      f[i] = arrays.populations[i * stride + node];
    }
    double density = 0.0;
    std::array<double, 3> velocity{};
    const RelaxationRates& rates = parameters.viscosity_classes != nullptr
                                       ? parameters.class_rates[parameters.viscosity_classes[node]]
                                       : parameters.rates;
    collide_node_reference(f, node_force(arrays, parameters, node), rates, density, velocity);
    for (int i = 0; i < kDirections; ++i) {
      arrays.populations[i * stride + node] = f[i];
    }
    arrays.density[node] = density;
    for (int axis = 0; axis < 3; ++axis) {
      arrays.velocity[axis][node] = velocity[axis];
    }
  }
}

void stream_reference(const LatticeSetup& setup, const FluidArrays& arrays,
                      const std::vector<double>& post, std::vector<double>& pre,
                      std::size_t arrival_time, std::size_t stride) {
  const LatticeGrid& grid = setup.grid;
  const bool sliding = setup.lees_edwards_velocity.has_value();
  const double velocity_difference = setup.lees_edwards_velocity.value_or(0.0);
  const auto planes = lees_edwards_planes(
      grid.ny(), lees_edwards_offset(velocity_difference, arrival_time, grid.nx()),
      velocity_difference);

  const auto signed_count = static_cast<std::int64_t>(grid.node_count());
#pragma omp parallel for schedule(static) if (grid.worth_threads())
  for (std::int64_t signed_node = 0; signed_node < signed_count; ++signed_node) {
    const auto node = static_cast<std::size_t>(signed_node);
    if (!setup.boundaries.is_fluid(node)) {
      continue;
    }
    const auto [x, y, z] = grid.coordinates(node);
    for (int i = 0; i < kDirections; ++i) {
      const auto& c = kVelocities[i];
      const int o = kOpposite[i];
      double& streamed = pre[i * stride + node];
      const int source_y = y - c[1];
      if (sliding && (source_y < 0 || source_y >= grid.ny())) {
        const auto& plane = planes[source_y < 0 ? 0 : 1];
        streamed = lees_edwards_population(grid, plane, i, x, z, arrays, [&](std::size_t source) {
          return post[i * stride + source];
        });
        continue;
      }
      const std::size_t source = grid.periodic_neighbour(node, {-c[0], -c[1], -c[2]});
      const double reflected = post[o * stride + node];
      switch (setup.boundaries.kind(source)) {
        case NodeKind::fluid:
          streamed = post[i * stride + source];
          break;
        case NodeKind::wall: {
          const WallLinkWeights weights = wall_link_weights(setup, node, i);
          streamed = wall_link_local_part(
              weights, reflected, post[i * stride + node], arrays.density[node],
              wall_momentum_coefficient(i, setup.boundaries.wall_velocity(source)));
          if (weights.behind != 0.0) {
            const std::size_t behind = grid.periodic_neighbour(node, c);
            streamed += weights.behind * post[o * stride + behind];
          }
          break;
        }
        case NodeKind::pressure_outlet:
          streamed = anti_bounce_back(i, reflected, setup.boundaries.outlet_density(source),
                                      node_velocity(arrays, node));
          break;
      }
    }
  }
}

ReferenceKernel::ReferenceKernel(const LatticeSetup& setup)
    : setup_(setup), streamed_(kDirections * population_stride(setup.grid.node_count()), 0.0) {}

void ReferenceKernel::step(FluidArrays& arrays, const StepParameters& parameters) {
  if (arrays.layout != PopulationLayout::natural) {
    throw std::logic_error("lattice: the reference kernel needs populations in natural layout");
  }
  if (arrays.single()) {
    throw std::logic_error("lattice: the reference kernel stores populations in double only");
  }
  collide_reference(setup_, arrays, parameters);
  stream_reference(setup_, arrays, arrays.populations, streamed_, parameters.time + 1,
                   arrays.population_stride);
  arrays.populations.swap(streamed_);
}

}  // namespace rbcsim::lattice
