// OpenMP loop over elements for the membrane kernels. Every body writes only its own element's
// slots, so results do not depend on the thread count; included by .cpp files only (the pragma
// needs the OpenMP flags this library is built with).
#pragma once

#include <cstddef>

namespace rbcsim::membrane {

template <class Body>
void parallel_for(std::size_t count, const Body& body) {
  const auto signed_count = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < signed_count; ++i) body(static_cast<std::size_t>(i));
}

}  // namespace rbcsim::membrane
