#include "coupling/benchmark.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <unistd.h>

#include "common/errors.hpp"
#include "common/fastest_batch.hpp"
#include "common/thread_count_scope.hpp"
#include "lattice/d3q19.hpp"

namespace rbcsim::coupling {
namespace {

constexpr double kBytesPerGigabyte = 1e9;
// STREAM's count for the triad: read b and c, write a.
constexpr double kTriadBytesPerElement = 3 * sizeof(double);
// The coupled benchmark's fluid starts as a shear wave of this amplitude (lattice units): a real
// flow that moves and deforms the cell, slow enough to stay stable for the whole measurement.
constexpr double kShearWaveAmplitude_lu = 0.005;
constexpr BatchTiming kCoupledStepBatches{5, 3, 0.5};

std::string first_line_after(const std::filesystem::path& path, std::string_view prefix) {
  std::ifstream file(path);
  for (std::string line; std::getline(file, line);) {
    if (line.starts_with(prefix)) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line
                                        : line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  }
  return {};
}

// "32768K" -> bytes.
std::size_t cache_size_bytes(const std::string& text) {
  if (text.empty()) return 0;
  std::size_t factor = 1;
  if (text.back() == 'K') factor = 1024;
  if (text.back() == 'M') factor = 1024 * 1024;
  return static_cast<std::size_t>(std::stoull(text)) * factor;
}

std::string read_first_line(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  return line;
}

// The largest cache of the highest level glibc reads from the CPU itself (CPUID), for machines
// whose /sys lists no caches (seen on a 2-core EPYC VM); 0 if it knows none either.
std::size_t last_level_cache_bytes_from_libc() {
  for (const int name : {_SC_LEVEL4_CACHE_SIZE, _SC_LEVEL3_CACHE_SIZE, _SC_LEVEL2_CACHE_SIZE}) {
    const long size = sysconf(name);
    if (size > 0) return static_cast<std::size_t>(size);
  }
  return 0;
}

// The largest cache of the highest level listed for CPU 0 in /sys, else what glibc reads.
std::size_t last_level_cache_bytes() {
  int best_level = 0;
  std::size_t best_size = 0;
  const std::filesystem::path caches = "/sys/devices/system/cpu/cpu0/cache";
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(caches, error)) {
    if (!entry.path().filename().string().starts_with("index")) continue;
    const std::string level_text = read_first_line(entry.path() / "level");
    if (level_text.empty()) continue;
    const int level = std::stoi(level_text);
    const std::size_t size = cache_size_bytes(read_first_line(entry.path() / "size"));
    if (level > best_level || (level == best_level && size > best_size)) {
      best_level = level;
      best_size = size;
    }
  }
  return best_size > 0 ? best_size : last_level_cache_bytes_from_libc();
}

std::unique_ptr<lattice::FluidSolver> shear_wave_fluid(const std::array<int, 3>& extent,
                                                       double relaxation_time,
                                                       double cytoplasm_viscosity_ratio) {
  lattice::FluidParameters parameters;
  parameters.collision_parameters.tau = relaxation_time;
  parameters.inner_viscosity_ratio = cytoplasm_viscosity_ratio;
  auto fluid = std::make_unique<lattice::FluidSolver>(
      lattice::LatticeGrid(extent[0], extent[1], extent[2]), parameters);
  const auto& grid = fluid->grid();
  const std::size_t node_count = grid.node_count();
  lattice::VectorField velocity{std::vector<double>(node_count, 0.0),
                                std::vector<double>(node_count, 0.0),
                                std::vector<double>(node_count, 0.0)};
  for (std::size_t node = 0; node < node_count; ++node) {
    const double phase = 2.0 * std::numbers::pi * grid.coordinates(node)[1] / grid.ny();
    velocity[0][node] = kShearWaveAmplitude_lu * std::sin(phase);
  }
  fluid->initialise_equilibrium(std::vector<double>(node_count, 1.0), velocity);
  return fluid;
}

// The mesh's vertices moved so that their mean sits at the centre of a box of `extent` nodes
// whose first node is `first_node_um`.
std::vector<Vec3> centred_in_box(const mesh::TriangleMesh& cell_mesh,
                                 const std::array<int, 3>& extent, double dx_um,
                                 const Vec3& first_node_um = Vec3::Zero()) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& position : cell_mesh.positions_um) mean += position;
  mean /= static_cast<double>(cell_mesh.vertex_count());
  const Vec3 centre_um =
      first_node_um + 0.5 * dx_um * Vec3(extent[0] - 1.0, extent[1] - 1.0, extent[2] - 1.0);
  std::vector<Vec3> positions;
  for (const Vec3& position : cell_mesh.positions_um)
    positions.push_back(position - mean + centre_um);
  return positions;
}

// Times steps of `simulation` after one warm-up step (which sizes the stencils and the kernels'
// buffers): ms per step and the phases of the fastest batch.
template <typename Timing>
void time_steps(CoupledSimulation& simulation, Timing& timing) {
  simulation.step();
  simulation.reset_phase_times();
  timing.ms_per_step = 1e3 * fastest_batch_seconds_per_call(
                                 [&] { simulation.step(); }, kCoupledStepBatches,
                                 [&](bool fastest) {
                                   if (fastest)
                                     timing.fastest_batch_phases = simulation.phase_times();
                                   simulation.reset_phase_times();
                                 });
}

}  // namespace

MachineDescription describe_machine() {
  MachineDescription machine;
  machine.cpu_model = first_line_after("/proc/cpuinfo", "model name");
  if (machine.cpu_model.empty()) machine.cpu_model = "unknown";
  machine.logical_cpus = static_cast<int>(std::thread::hardware_concurrency());
  machine.openmp_max_threads = omp_get_max_threads();
  const char* wait_policy = std::getenv("OMP_WAIT_POLICY");
  machine.omp_wait_policy = wait_policy != nullptr ? wait_policy : "unset";
  // The first three fields: the load over 1, 5 and 15 minutes.
  std::istringstream load(read_first_line("/proc/loadavg"));
  std::string one, five, fifteen;
  load >> one >> five >> fifteen;
  machine.load_average = one.empty() ? "" : one + " " + five + " " + fifteen;
  machine.last_level_cache_bytes = last_level_cache_bytes();
  return machine;
}

std::array<int, 3> lattice_beyond_cache(std::size_t last_level_cache_bytes) {
  constexpr int kCrossSection = 128;
  // Populations, density, velocity and force density.
  constexpr std::size_t kFluidBytesPerNode = (lattice::kDirections + 1 + 3 + 3) * sizeof(double);
  if (last_level_cache_bytes == 0) return {2 * kCrossSection, kCrossSection, kCrossSection};
  const std::size_t nodes = 2 * last_level_cache_bytes / kFluidBytesPerNode;
  const std::size_t row_nodes = std::size_t{kCrossSection} * kCrossSection;
  const std::size_t nx = (nodes + row_nodes - 1) / row_nodes;
  const std::size_t rounded = std::max<std::size_t>(kCrossSection, (nx + 7) / 8 * 8);
  return {static_cast<int>(rounded), kCrossSection, kCrossSection};
}

double measure_triad_bandwidth_GB_per_s(std::size_t elements, int threads) {
  if (threads < 1) throw std::invalid_argument("triad bandwidth: threads must be >= 1");
  if (elements == 0) throw std::invalid_argument("triad bandwidth: no elements");
  const ThreadCountScope thread_count(threads);
  auto a = std::make_unique_for_overwrite<double[]>(elements);
  auto b = std::make_unique_for_overwrite<double[]>(elements);
  auto c = std::make_unique_for_overwrite<double[]>(elements);
  const auto count = static_cast<std::ptrdiff_t>(elements);
  // First touch by the threads that will stream the same ranges.
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    a[i] = 0.0;
    b[i] = 1.0;
    c[i] = 2.0;
  }
  constexpr double scalar = 3.0;
  const auto triad = [&] {
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < count; ++i) a[i] = b[i] + scalar * c[i];
  };
  triad();
  const double seconds = fastest_batch_seconds_per_call(triad, {1, 5, 0.0});
  // Reading the result keeps the compiler from dropping the passes, and checks them.
  if (a[elements / 2] != 1.0 + scalar * 2.0) throw std::logic_error("triad: wrong result");
  return kTriadBytesPerElement * static_cast<double>(elements) / seconds / kBytesPerGigabyte;
}

CoupledStepTiming measure_coupled_step(const mesh::TriangleMesh& cell_mesh,
                                       const membrane::MembraneParameters& membrane_parameters,
                                       const units::UnitConverter& units,
                                       const std::array<int, 3>& extent,
                                       std::string_view ibm_kernel, int threads,
                                       const CytoplasmSettings& cytoplasm) {
  const ThreadCountScope thread_count(threads);
  CouplingParameters coupling;
  coupling.kernel = std::string(ibm_kernel);
  coupling.cytoplasm_update_lu = cytoplasm.update_lu;
  CoupledSimulation simulation(
      shear_wave_fluid(extent, units.relaxation_time(), cytoplasm.viscosity_ratio), units,
      coupling);
  const auto positions_um = centred_in_box(cell_mesh, extent, simulation.frame().dx_um);
  simulation.add_cell(membrane::MembraneModel(cell_mesh, membrane_parameters), positions_um);
  CoupledStepTiming timing;
  timing.vertex_count = cell_mesh.vertex_count();
  time_steps(simulation, timing);
  return timing;
}

std::array<int, 3> suspension_block_nodes(const mesh::TriangleMesh& cell_mesh, double dx_um,
                                          double contact_range_um) {
  Vec3 low = cell_mesh.positions_um.front();
  Vec3 high = low;
  for (const Vec3& position : cell_mesh.positions_um) {
    low = low.cwiseMin(position);
    high = high.cwiseMax(position);
  }
  const Vec3 size_um = high - low;
  constexpr int kMarginNodes = 2;
  return {static_cast<int>(std::ceil((size_um.x() + 0.5 * contact_range_um) / dx_um)),
          static_cast<int>(std::ceil(size_um.y() / dx_um)) + 2 * kMarginNodes,
          static_cast<int>(std::ceil(size_um.z() / dx_um)) + 2 * kMarginNodes};
}

SuspensionStepTiming measure_suspension_step(
    const mesh::TriangleMesh& cell_mesh, const membrane::MembraneParameters& membrane_parameters,
    const units::UnitConverter& units, const contact::ContactParameters& contact,
    std::size_t cell_count, std::string_view ibm_kernel, int threads) {
  if (cell_count == 0) throw InputError("bench", "a suspension needs at least one cell");
  const ThreadCountScope thread_count(threads);
  const double dx_um = 1e6 * units.dx_m();
  const auto block = suspension_block_nodes(cell_mesh, dx_um, contact.range_um);
  const std::array<int, 3> extent = {block[0] * static_cast<int>(cell_count), block[1], block[2]};
  CouplingParameters coupling;
  coupling.kernel = std::string(ibm_kernel);
  CoupledSimulation simulation(shear_wave_fluid(extent, units.relaxation_time(), 1.0), units,
                               coupling);
  for (std::size_t k = 0; k < cell_count; ++k) {
    const Vec3 first_node_um(dx_um * block[0] * static_cast<double>(k), 0.0, 0.0);
    simulation.add_cell(membrane::MembraneModel(cell_mesh, membrane_parameters),
                        centred_in_box(cell_mesh, block, dx_um, first_node_um));
  }
  simulation.set_cell_contact(contact, "suspension.contact_force_pN");
  SuspensionStepTiming timing;
  timing.cell_count = cell_count;
  timing.vertex_count = cell_count * cell_mesh.vertex_count();
  timing.lattice = extent;
  time_steps(simulation, timing);
  timing.contact_pairs = simulation.contact_statistics().pairs_in_range;
  return timing;
}

}  // namespace rbcsim::coupling
