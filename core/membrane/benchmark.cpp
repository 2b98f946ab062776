#include "membrane/benchmark.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/fastest_batch.hpp"
#include "common/thread_count_scope.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/cell_shapes.hpp"

namespace rbcsim::membrane {
namespace {

// Batches of about 0.5 ms, timed for at least 0.3 s: on a shared machine a short batch more often
// runs without its threads being preempted, and the fastest batch is the measurement.
constexpr double kBatchSeconds = 0.0005;
constexpr double kBudgetSeconds = 0.3;
constexpr int kMinimumBatches = 5;

}  // namespace

double measure_membrane_force_us(int vertex_count_level, int threads, std::string_view kernel) {
  if (threads < 1) {
    throw InputError("membrane benchmark",
                     "needs at least one thread, got " + std::to_string(threads));
  }
  const auto mesh = mesh::generate_cell("discocyte", vertex_count_level);
  MembraneParameters parameters;
  parameters.kernel = std::string(kernel);
  const MembraneModel model(mesh, parameters);
  std::vector<Vec3> positions_um = mesh.positions_um;
  for (auto& p : positions_um) p = p.cwiseProduct(Vec3(1.01, 1.0, 0.99));

  const ThreadCountScope scope(threads);
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  const auto evaluate = [&] {
    model.compute(positions_um, workspace, forces, ForceDetail::totals);
  };
  // Warm-up (caches, OpenMP threads), then a single-call estimate sizes the batches.
  const double single_s = fastest_batch_seconds_per_call(
      evaluate, {.calls_per_batch = 1, .minimum_batches = 5, .minimum_duration_s = 0.0});
  const int batch = std::max(1, static_cast<int>(kBatchSeconds / single_s));
  const double best_s =
      fastest_batch_seconds_per_call(evaluate, {.calls_per_batch = batch,
                                                .minimum_batches = kMinimumBatches,
                                                .minimum_duration_s = kBudgetSeconds});
  return best_s * 1e6;
}

}  // namespace rbcsim::membrane
