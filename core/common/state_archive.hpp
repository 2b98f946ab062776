// What a checkpoint holds (docs/architecture.md: long runs checkpoint and resume): named arrays of
// doubles that each stateful part of a simulation puts when saved and takes back when restored.
// Counts (steps) are stored as doubles, exact up to 2^53. A restore checks every array's size
// against what the receiving object needs, so a checkpoint of another setup is refused with the
// array that differs, never half-loaded silently. The file format is coupling/checkpoint.hpp's.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/vec3.hpp"

namespace rbcsim {

class StateArchive {
 public:
  // `source` names the archive in diagnostics (the checkpoint file).
  explicit StateArchive(std::string source = "checkpoint") : source_(std::move(source)) {}

  void put(const std::string& name, std::vector<double> values);
  void put(const std::string& name, std::span<const Vec3> vectors);

  // Removes and returns the array; throws InputError(source, ...) if it is missing or, when
  // expected_size is given, has another size.
  std::vector<double> take(const std::string& name, std::optional<std::size_t> expected_size);
  double take_number(const std::string& name);
  // Fills `vectors` (its size is the one expected).
  void take(const std::string& name, std::span<Vec3> vectors);

  // Throws InputError naming the first array nobody took: the checkpoint holds more than the
  // simulation it is restored into (another cell count, another stop criterion, ...).
  void require_all_taken() const;

  const std::map<std::string, std::vector<double>>& arrays() const { return arrays_; }
  const std::string& source() const { return source_; }

 private:
  std::string source_;
  std::map<std::string, std::vector<double>> arrays_;
};

}  // namespace rbcsim
