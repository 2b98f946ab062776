// A straight circular tube along x: the pipe of the Poiseuille tests.
#pragma once

#include <string_view>

#include "geometry/axisymmetric_wall.hpp"

namespace rbcsim::geometry {

struct TubeParameters {
  double diameter_um = 0.0;
  double length_um = 0.0;
};

class TubeWall final : public AxisymmetricWall {
 public:
  // Throws rbcsim::InputError naming source.<parameter> for a non-positive length.
  explicit TubeWall(const TubeParameters& parameters, std::string_view source = "tube");

  double lumen_radius_um(double /*x_um*/) const override { return parameters_.diameter_um / 2.0; }
  double largest_radius_um() const override { return parameters_.diameter_um / 2.0; }
  double length_um() const override { return parameters_.length_um; }
  const TubeParameters& parameters() const { return parameters_; }

 private:
  TubeParameters parameters_;
};

}  // namespace rbcsim::geometry
