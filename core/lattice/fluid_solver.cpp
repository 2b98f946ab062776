#include "lattice/fluid_solver.hpp"

#include "common/errors.hpp"
#include "lattice/lees_edwards.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace rbcsim::lattice {

FluidSolver::FluidSolver(LatticeGrid grid, FluidParameters parameters)
    : setup_{grid, BoundaryMap(grid.node_count()), parameters.lees_edwards_velocity,
             &find_wall_rule(parameters.wall_rule)},
      parameters_(std::move(parameters)),
      rates_(lattice::relaxation_rates(parameters_.collision, parameters_.collision_parameters)),
      arrays_(grid.node_count(), parameters_.precision) {
  find_fluid_kernel(parameters_.kernel);
  if (arrays_.single() && parameters_.kernel != "optimised") {
    throw InputError("lattice.precision",
                     "single precision is a storage of the optimised kernel; set "
                     "lattice.kernel=optimised (the reference kernel is the double-precision "
                     "definition it is tested against)");
  }
  if (parameters_.inner_viscosity_ratio != 1.0) {
    class_rates_ = viscosity_class_rates(parameters_.collision, parameters_.collision_parameters,
                                         parameters_.inner_viscosity_ratio);
    viscosity_classes_.assign(grid.node_count(), ViscosityClass{0});
  }
  initialise_equilibrium(1.0, {0.0, 0.0, 0.0});
}

FluidSolver::~FluidSolver() = default;

void FluidSolver::require_geometry_editable() const {
  if (kernel_) {
    throw std::logic_error("lattice: the geometry is fixed once the fluid has stepped");
  }
}

void FluidSolver::mark_boundary_node(std::size_t node) {
  const auto wall_velocity = setup_.boundaries.wall_velocity(node);
  arrays_.density[node] = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    arrays_.velocity[axis][node] = wall_velocity[axis];
  }
}

void FluidSolver::set_wall(std::size_t node, const std::array<double, 3>& wall_velocity) {
  require_geometry_editable();
  setup_.boundaries.set_wall(node, wall_velocity);
  mark_boundary_node(node);
}

void FluidSolver::set_velocity_inlet(std::size_t node, const std::array<double, 3>& velocity) {
  set_wall(node, velocity);
}

void FluidSolver::set_pressure_outlet(std::size_t node, double density) {
  require_geometry_editable();
  setup_.boundaries.set_pressure_outlet(node, density);
  mark_boundary_node(node);
}

std::size_t FluidSolver::set_wall_links(std::span<const WallLink> links) {
  require_geometry_editable();
  const LatticeGrid& g = grid();
  std::size_t taken = 0;
  for (std::size_t k = 0; k < links.size(); ++k) {
    const WallLink& link = links[k];
    const auto problem = [&](const std::string& what) {
      return InputError("lattice wall links", "link " + std::to_string(k) + " (node " +
                                                  std::to_string(link.node) + ", direction " +
                                                  std::to_string(link.direction) + "): " + what);
    };
    if (link.node >= g.node_count()) {
      throw problem("the node lies outside the grid of " + std::to_string(g.node_count()) +
                    " nodes");
    }
    if (link.direction < 1 || link.direction >= kDirections) {
      throw problem("the direction must be a moving D3Q19 direction, 1 to 18");
    }
    if (!(link.fraction > 0.0 && link.fraction <= 1.0)) {
      throw problem("the wall fraction must lie in (0, 1], got " + std::to_string(link.fraction));
    }
    const std::size_t end = g.periodic_neighbour(link.node, kVelocities[link.direction]);
    if (setup_.boundaries.is_fluid(link.node) && setup_.boundaries.kind(end) == NodeKind::wall) {
      setup_.boundaries.set_wall_fraction(link);
      ++taken;
    }
  }
  return taken;
}

void FluidSolver::initialise_equilibrium(double density, const std::array<double, 3>& velocity) {
  const std::size_t node_count = grid().node_count();
  initialise_equilibrium(
      std::vector<double>(node_count, density),
      {std::vector<double>(node_count, velocity[0]), std::vector<double>(node_count, velocity[1]),
       std::vector<double>(node_count, velocity[2])});
}

void FluidSolver::initialise_equilibrium(const std::vector<double>& density,
                                         const VectorField& velocity) {
  const std::size_t node_count = grid().node_count();
  if (density.size() != node_count || velocity[0].size() != node_count ||
      velocity[1].size() != node_count || velocity[2].size() != node_count) {
    throw std::invalid_argument("lattice: initial fields must have one value per node");
  }
  for (std::size_t node = 0; node < node_count; ++node) {
    if (!setup_.boundaries.is_fluid(node)) {
      mark_boundary_node(node);
      continue;
    }
    const std::array<double, 3> u = {velocity[0][node], velocity[1][node], velocity[2][node]};
    for (int i = 0; i < kDirections; ++i) {
      arrays_.set_population(i, i * arrays_.population_stride + node,
                             equilibrium(i, density[node], u));
    }
    arrays_.density[node] = density[node];
    for (int axis = 0; axis < 3; ++axis) {
      arrays_.velocity[axis][node] = u[axis];
    }
  }
  arrays_.layout = PopulationLayout::natural;
}

void FluidSolver::initialise_populations(const std::vector<double>& populations) {
  const std::size_t node_count = grid().node_count();
  if (populations.size() != kDirections * node_count) {
    throw std::invalid_argument("lattice: initial populations must have 19 values per node");
  }
  unpack_populations(populations, arrays_);
  arrays_.layout = PopulationLayout::natural;
  for (std::size_t node = 0; node < node_count; ++node) {
    if (!setup_.boundaries.is_fluid(node)) {
      mark_boundary_node(node);
      continue;
    }
    double density = 0.0;
    std::array<double, 3> momentum = parameters_.body_force;
    for (int axis = 0; axis < 3; ++axis) {
      momentum[axis] = 0.5 * (momentum[axis] + arrays_.force_density[axis][node]);
    }
    for (int i = 0; i < kDirections; ++i) {
      const double f = populations[i * node_count + node];
      density += f;
      for (int axis = 0; axis < 3; ++axis) {
        momentum[axis] += f * kVelocities[i][axis];
      }
    }
    arrays_.density[node] = density;
    for (int axis = 0; axis < 3; ++axis) {
      arrays_.velocity[axis][node] = momentum[axis] / density;
    }
  }
}

VectorField& FluidSolver::force_density() {
  // Once handed out, the field is read and zeroed every step: the caller may keep the reference.
  force_field_active_ = true;
  return arrays_.force_density;
}

void FluidSolver::ensure_kernel() {
  if (!kernel_) {
    kernel_ = make_fluid_kernel(parameters_.kernel, setup_);
  }
}

void FluidSolver::find_forced_spans() {
  const auto rows = static_cast<std::int64_t>(grid().row_count());
  const auto nx = static_cast<std::uint32_t>(grid().nx());
  forced_spans_.resize(static_cast<std::size_t>(rows));
  const double* const fx = arrays_.force_density[0].data();
  const double* const fy = arrays_.force_density[1].data();
  const double* const fz = arrays_.force_density[2].data();
  // A node counts as forced when any bit of its force is set: a NaN does, and so does -0.0
  // (harmless: the row is then read as before).
  const auto bits = [&](std::size_t node) {
    return std::bit_cast<std::uint64_t>(fx[node]) | std::bit_cast<std::uint64_t>(fy[node]) |
           std::bit_cast<std::uint64_t>(fz[node]);
  };
#pragma omp parallel for schedule(static) if (grid().worth_threads())
  for (std::int64_t row = 0; row < rows; ++row) {
    const std::size_t first = static_cast<std::size_t>(row) * nx;
    // Most rows are zero: one pass without branches says so.
    std::uint64_t any = 0;
    for (std::uint32_t x = 0; x < nx; ++x) any |= bits(first + x);
    ForcedSpan span;
    if (any != 0) {
      while (bits(first + span.begin) == 0) ++span.begin;
      span.end = nx;
      while (bits(first + span.end - 1) == 0) --span.end;
    }
    forced_spans_[static_cast<std::size_t>(row)] = span;
  }
}

void FluidSolver::zero_forced_spans() {
  const auto rows = static_cast<std::int64_t>(grid().row_count());
  const auto nx = static_cast<std::size_t>(grid().nx());
#pragma omp parallel for schedule(static) if (grid().worth_threads())
  for (std::int64_t row = 0; row < rows; ++row) {
    const ForcedSpan span = forced_spans_[static_cast<std::size_t>(row)];
    const std::size_t first = static_cast<std::size_t>(row) * nx + span.begin;
    for (auto& component : arrays_.force_density) {
      std::fill_n(component.data() + first, span.end - span.begin, 0.0);
    }
  }
}

void FluidSolver::step() {
  ensure_kernel();
  if (force_field_active_) find_forced_spans();
  const bool contrast = has_viscosity_contrast();
  kernel_->step(arrays_, {.rates = rates_,
                          .body_force = parameters_.body_force,
                          .force_field_active = force_field_active_,
                          .forced_spans = force_field_active_ ? forced_spans_.data() : nullptr,
                          .time = time_,
                          .viscosity_classes = contrast ? viscosity_classes_.data() : nullptr,
                          .class_rates = contrast ? class_rates_.data() : nullptr});
  ++time_;
  if (force_field_active_) zero_forced_spans();
}

void FluidSolver::advance(std::size_t steps) {
  for (std::size_t s = 0; s < steps; ++s) {
    step();
  }
}

double relative_velocity_change(const VelocityChangeSquared& maxima) {
  const double change = std::sqrt(maxima.change);
  const double speed = std::sqrt(maxima.speed);
  return speed > 0.0 ? change / speed
                     : (change > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
}

VelocityChangeSquared FluidSolver::velocity_change_since(VectorField& previous,
                                                         std::size_t node_begin,
                                                         std::size_t node_end) const {
  const auto begin = static_cast<std::int64_t>(node_begin);
  const auto end = static_cast<std::int64_t>(node_end);
  const auto& kinds = setup_.boundaries.kinds();
  double largest_change_squared = 0.0;
  double largest_speed_squared = 0.0;
#pragma omp parallel for schedule(static) if (grid().worth_threads()) \
    reduction(max                                                     \
              : largest_change_squared, largest_speed_squared)
  for (std::int64_t node = begin; node < end; ++node) {
    if (kinds[node] != 0) {
      continue;
    }
    double change_squared = 0.0;
    double speed_squared = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      const double u = arrays_.velocity[axis][node];
      change_squared += (u - previous[axis][node]) * (u - previous[axis][node]);
      speed_squared += u * u;
      previous[axis][node] = u;
    }
    largest_change_squared = std::max(largest_change_squared, change_squared);
    largest_speed_squared = std::max(largest_speed_squared, speed_squared);
  }
  return {largest_change_squared, largest_speed_squared};
}

SteadyStateResult run_until_steady(const SteadyStateCriterion& criterion,
                                   const std::function<void(std::size_t)>& advance,
                                   const std::function<double()>& measure) {
  SteadyStateResult result;
  while (result.steps < criterion.max_steps) {
    const std::size_t chunk =
        std::min(criterion.check_interval, criterion.max_steps - result.steps);
    advance(chunk);
    result.steps += chunk;
    result.relative_velocity_change = measure();
    if (result.relative_velocity_change <= criterion.relative_velocity_change) {
      result.converged = true;
      break;
    }
  }
  return result;
}

SteadyStateResult FluidSolver::run_to_steady_state(const SteadyStateCriterion& criterion) {
  VectorField previous = arrays_.velocity;
  return run_until_steady(
      criterion, [this](std::size_t steps) { advance(steps); },
      [this, &previous] {
        require_finite_velocity();
        return relative_velocity_change(velocity_change_since(previous, 0, grid().node_count()));
      });
}

void FluidSolver::require_finite_velocity() const {
  const auto node_count = static_cast<std::int64_t>(grid().node_count());
  const auto& kinds = setup_.boundaries.kinds();
  std::int64_t first_bad = node_count;
#pragma omp parallel for schedule(static) if (grid().worth_threads()) reduction(min : first_bad)
  for (std::int64_t node = 0; node < node_count; ++node) {
    if (kinds[node] == 0 &&
        !(std::isfinite(arrays_.velocity[0][node]) && std::isfinite(arrays_.velocity[1][node]) &&
          std::isfinite(arrays_.velocity[2][node]))) {
      first_bad = std::min(first_bad, node);
    }
  }
  if (first_bad < node_count) {
    const auto [x, y, z] = grid().coordinates(static_cast<std::size_t>(first_bad));
    throw RuntimeFailure("lattice: non-finite fluid velocity at node (" + std::to_string(x) + ", " +
                         std::to_string(y) + ", " + std::to_string(z) + ") after step " +
                         std::to_string(time_) +
                         "; the flow is unstable (lattice velocity too high or tau too close "
                         "to 1/2)");
  }
}

std::span<ViscosityClass> FluidSolver::viscosity_classes() {
  const auto classes = std::as_const(*this).viscosity_classes();
  return {viscosity_classes_.data(), classes.size()};
}

std::span<const ViscosityClass> FluidSolver::viscosity_classes() const {
  if (!has_viscosity_contrast()) {
    throw std::logic_error("lattice: viscosity classes need a viscosity ratio other than 1");
  }
  return viscosity_classes_;
}

double FluidSolver::viscosity() const { return (1.0 / rates_.even - 0.5) * kSoundSpeedSquared; }

double FluidSolver::lees_edwards_offset() const {
  return setup_.lees_edwards_velocity
             ? lattice::lees_edwards_offset(*setup_.lees_edwards_velocity, time_, grid().nx())
             : 0.0;
}

void FluidSolver::pre_collision_moments(std::span<const std::size_t> nodes,
                                        std::span<double> density,
                                        std::span<Vec3> momentum) const {
  if (!populations_natural()) {
    throw std::logic_error("FluidSolver::pre_collision_moments: the populations are swapped");
  }
  const std::size_t stride = arrays_.population_stride;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    double mass = 0.0;
    Vec3 sum = Vec3::Zero();
    for (int i = 0; i < kDirections; ++i) {
      const double f = arrays_.population(i, static_cast<std::size_t>(i) * stride + nodes[k]);
      const auto& c = kVelocities[i];
      mass += f;
      sum += f * Vec3(c[0], c[1], c[2]);
    }
    density[k] = mass;
    momentum[k] = sum;
  }
}

void FluidSolver::add_momentum(std::span<const std::size_t> nodes, std::span<const Vec3> momentum) {
  if (!populations_natural()) {
    throw std::logic_error("FluidSolver::add_momentum: the populations are in swapped layout");
  }
  const std::size_t stride = arrays_.population_stride;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const std::size_t node = nodes[k];
    const Vec3& p = momentum[k];
    for (int i = 1; i < kDirections; ++i) {
      const auto& c = kVelocities[i];
      const std::size_t slot = static_cast<std::size_t>(i) * stride + node;
      arrays_.set_population(i, slot,
                             arrays_.population(i, slot) + kInverseSoundSpeedSquared * kWeights[i] *
                                                               (c[0] * p.x() + c[1] * p.y() +
                                                                c[2] * p.z()));
    }
    for (int axis = 0; axis < 3; ++axis) {
      arrays_.velocity[axis][node] += p[axis] / arrays_.density[node];
    }
  }
}

std::array<double, 3> FluidSolver::velocity_at(std::size_t node) const {
  return {arrays_.velocity[0][node], arrays_.velocity[1][node], arrays_.velocity[2][node]};
}

namespace {
void require_node_range(const LatticeGrid& grid, std::size_t first_node, std::size_t count) {
  if (first_node > grid.node_count() || count > grid.node_count() - first_node) {
    throw std::out_of_range("lattice: node range [" + std::to_string(first_node) + ", " +
                            std::to_string(first_node + count) + ") past the grid's " +
                            std::to_string(grid.node_count()) + " nodes");
  }
}

constexpr std::array<int, kDirections> kEverySlot = {0,  1,  2,  3,  4,  5,  6,  7,  8, 9,
                                                     10, 11, 12, 13, 14, 15, 16, 17, 18};

std::span<const int> slots_or_all(std::span<const int> slots) {
  for (const int slot : slots) {
    if (slot < 0 || slot >= kDirections) {
      throw std::out_of_range("lattice: population slot " + std::to_string(slot));
    }
  }
  return slots.empty() ? std::span<const int>(kEverySlot) : slots;
}
}  // namespace

std::vector<double> FluidSolver::stored_populations(std::size_t first_node, std::size_t count,
                                                    std::span<const int> slots) const {
  require_node_range(grid(), first_node, count);
  const std::span<const int> taken = slots_or_all(slots);
  std::vector<double> values(taken.size() * count);
  for (std::size_t s = 0; s < taken.size(); ++s) {
    const std::size_t slot = taken[s] * arrays_.population_stride + first_node;
    double* const out = values.data() + s * count;
    if (arrays_.single()) {
      std::copy_n(arrays_.single_populations.begin() + slot, count, out);
    } else {
      std::copy_n(arrays_.populations.begin() + slot, count, out);
    }
  }
  return values;
}

void FluidSolver::replace_stored_populations(std::size_t first_node, std::size_t count,
                                             std::span<const double> values,
                                             std::span<const int> slots) {
  require_node_range(grid(), first_node, count);
  const std::span<const int> taken = slots_or_all(slots);
  if (values.size() != taken.size() * count) {
    throw std::out_of_range("lattice: " + std::to_string(values.size()) +
                            " stored populations for " + std::to_string(taken.size()) +
                            " slots of " + std::to_string(count) + " nodes");
  }
  for (std::size_t s = 0; s < taken.size(); ++s) {
    const std::size_t slot = taken[s] * arrays_.population_stride + first_node;
    const double* const in = values.data() + s * count;
    if (arrays_.single()) {
      for (std::size_t k = 0; k < count; ++k) {
        arrays_.single_populations[slot + k] = static_cast<float>(in[k]);
      }
    } else {
      std::copy_n(in, count, arrays_.populations.begin() + slot);
    }
  }
}

double FluidSolver::total_mass() const {
  const LatticeGrid& g = grid();
  const auto rows = static_cast<std::int64_t>(g.row_count());
  std::vector<double> row_mass(g.row_count(), 0.0);
#pragma omp parallel for schedule(static) if (grid().worth_threads())
  for (std::int64_t row = 0; row < rows; ++row) {
    const std::size_t row_start = static_cast<std::size_t>(row) * g.nx();
    double mass = 0.0;
    for (std::size_t node = row_start; node < row_start + g.nx(); ++node) {
      if (!setup_.boundaries.is_fluid(node)) {
        continue;
      }
      for (int i = 0; i < kDirections; ++i) {
        mass += arrays_.population(i, i * arrays_.population_stride + node);
      }
    }
    row_mass[row] = mass;
  }
  double total = 0.0;
  for (const double mass : row_mass) {
    total += mass;
  }
  return total;
}

std::vector<double> FluidSolver::pre_collision_populations() const {
  return lattice::pre_collision_populations(setup_, arrays_, time_);
}

namespace {

std::string velocity_array_name(int axis) { return std::string("fluid.velocity_") + "xyz"[axis]; }

PopulationLayout population_layout_from(StateArchive& archive) {
  const double code = archive.take_number("fluid.layout");
  if (code == 0.0) return PopulationLayout::natural;
  if (code == 1.0) return PopulationLayout::swapped;
  throw InputError(archive.source(), "fluid.layout must be 0 (natural) or 1 (swapped)");
}

}  // namespace

// The population array is saved as the kernel holds it (less the padding between the arrays), with
// its layout, and restored as is: streaming a swapped (post-collision, AA) array here would round
// differently from the kernel's own next step at Lees-Edwards and wall links, and the resumed run
// would agree only to rounding.
void FluidSolver::save_state(StateArchive& archive) const {
  archive.put("fluid.populations", lattice::stored_populations(arrays_));
  archive.put("fluid.layout", {arrays_.layout == PopulationLayout::swapped ? 1.0 : 0.0});
  archive.put("fluid.density", arrays_.density);
  for (int axis = 0; axis < 3; ++axis) {
    archive.put(velocity_array_name(axis), arrays_.velocity[axis]);
  }
  archive.put("fluid.time", {static_cast<double>(time_)});
}

void FluidSolver::restore_state(StateArchive& archive) {
  const std::size_t node_count = grid().node_count();
  restore_stored_populations(archive.take("fluid.populations", kDirections * node_count), arrays_);
  arrays_.layout = population_layout_from(archive);
  arrays_.density = archive.take("fluid.density", node_count);
  for (int axis = 0; axis < 3; ++axis) {
    arrays_.velocity[axis] = archive.take(velocity_array_name(axis), node_count);
  }
  time_ = static_cast<std::size_t>(archive.take_number("fluid.time"));
}

}  // namespace rbcsim::lattice
