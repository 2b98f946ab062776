// Sets the OpenMP thread count for its lifetime, then restores the previous one: the benchmarks
// measure at a given thread count without changing the caller's. Header-only; include it only
// from targets built with OpenMP.
#pragma once

#include <omp.h>

namespace rbcsim {

class ThreadCountScope {
 public:
  explicit ThreadCountScope(int threads) : previous_threads_(omp_get_max_threads()) {
    omp_set_num_threads(threads);
  }
  ~ThreadCountScope() { omp_set_num_threads(previous_threads_); }
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;

 private:
  int previous_threads_;
};

}  // namespace rbcsim
