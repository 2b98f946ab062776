#include "geometry/tube_wall.hpp"

#include "geometry/shape_parameters.hpp"

namespace rbcsim::geometry {

TubeWall::TubeWall(const TubeParameters& parameters, std::string_view source)
    : parameters_(parameters) {
  require_positive_length(parameters.diameter_um, source, "diameter_um");
  require_positive_length(parameters.length_um, source, "length_um");
}

}  // namespace rbcsim::geometry
