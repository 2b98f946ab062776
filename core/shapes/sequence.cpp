#include "shapes/sequence.hpp"

#include <vector>

namespace rbcsim::shapes {
namespace {

// Delta a0 of each class: measured on rbcsim's own sequence (docs/physics.md), each in the middle
// of the range where the minimum at 2562 vertices has the class's defining measures.
std::vector<SequenceShape> sequence_entries() {
  return {
      {"stomatocyte-III", "a cup with a deep introversion", -6.0},
      {"stomatocyte-II", "a cup with a deep invagination", -3.0},
      {"stomatocyte-I", "a shelvy cup", 0.0},
      {"discocyte", "the biconcave disc", 1.0},
      {"echinocyte-I", "a disc with irregularities on its rim", 6.0},
      {"echinocyte-II", "an elliptical body with spicules over its surface", 10.0},
      {"echinocyte-III", "a sphere with regularly spaced sharp spicules, about 30-50", 14.0},
  };
}

}  // namespace

const Registry<SequenceShape>& shape_sequence() {
  static const Registry<SequenceShape> sequence("sequence shape", sequence_entries());
  return sequence;
}

}  // namespace rbcsim::shapes
