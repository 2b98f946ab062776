#include "membrane/benchmark.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/cell_shapes.hpp"

namespace rbcsim::membrane {
namespace {

// Short batches, repeated until a time budget is spent: on a shared machine a short batch more
// often runs without its threads being preempted, and the fastest batch is the measurement.
constexpr double kBatchSeconds = 0.0005;
constexpr double kBudgetSeconds = 0.3;
constexpr int kMinimumBatches = 5;

// Sets the OpenMP thread count for its lifetime and restores the previous one after.
class ThreadCountScope {
 public:
  explicit ThreadCountScope(int threads) : previous_(omp_get_max_threads()) {
    omp_set_num_threads(threads);
  }
  ~ThreadCountScope() { omp_set_num_threads(previous_); }
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;

 private:
  int previous_;
};

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
  using Clock = std::chrono::steady_clock;
  const auto run = [&](long evaluations) {
    const auto start = Clock::now();
    for (long i = 0; i < evaluations; ++i) {
      model.compute(positions_um, workspace, forces, ForceDetail::totals);
    }
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  run(3);  // warm-up: caches, OpenMP threads
  double single_s = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 5; ++i) single_s = std::min(single_s, run(1));
  const long batch = std::max(1L, static_cast<long>(kBatchSeconds / single_s));
  double best_s = std::numeric_limits<double>::infinity();
  const auto deadline = Clock::now() + std::chrono::duration<double>(kBudgetSeconds);
  for (int b = 0; b < kMinimumBatches || Clock::now() < deadline; ++b) {
    best_s = std::min(best_s, run(batch) / static_cast<double>(batch));
  }
  return best_s * 1e6;
}

}  // namespace rbcsim::membrane
