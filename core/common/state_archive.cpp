#include "common/state_archive.hpp"

#include <utility>

#include "common/errors.hpp"

namespace rbcsim {

void StateArchive::put(const std::string& name, std::vector<double> values) {
  arrays_[name] = std::move(values);
}

void StateArchive::put(const std::string& name, std::span<const Vec3> vectors) {
  std::vector<double> values;
  values.reserve(3 * vectors.size());
  for (const auto& v : vectors) values.insert(values.end(), {v.x(), v.y(), v.z()});
  put(name, std::move(values));
}

std::vector<double> StateArchive::take(const std::string& name,
                                       std::optional<std::size_t> expected_size) {
  const auto found = arrays_.find(name);
  if (found == arrays_.end()) {
    throw InputError(source_, "no '" + name + "' in it: written by a different simulation setup");
  }
  if (expected_size && found->second.size() != *expected_size) {
    throw InputError(source_, "'" + name + "' has " + std::to_string(found->second.size()) +
                                  " values, this simulation needs " +
                                  std::to_string(*expected_size) +
                                  ": written by a different setup (grid, mesh, cells)");
  }
  auto values = std::move(found->second);
  arrays_.erase(found);
  return values;
}

double StateArchive::take_number(const std::string& name) { return take(name, 1)[0]; }

void StateArchive::take(const std::string& name, std::span<Vec3> vectors) {
  const auto values = take(name, 3 * vectors.size());
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    vectors[i] = Vec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
  }
}

void StateArchive::require_all_taken() const {
  if (!arrays_.empty()) {
    throw InputError(source_, "'" + arrays_.begin()->first +
                                  "' has no counterpart in this simulation: written by a "
                                  "different setup");
  }
}

}  // namespace rbcsim
