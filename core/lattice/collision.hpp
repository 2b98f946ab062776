// Collision models, chosen by name (`lattice.collision`) from one table. Both registered models are
// two-relaxation-time operators (Ginzburg, Verhaeghe & d'Humieres 2008): the populations' even
// (symmetric) part relaxes at omega_even, which sets the viscosity nu = (1/omega_even - 1/2)/3, and
// the odd part at omega_odd. BGK is the special case omega_odd = omega_even, so one kernel serves
// both and adding a model of this family is one table row in collision.cpp.
#pragma once

#include <span>
#include <string_view>

namespace rbcsim::lattice {

struct CollisionParameters {
  double tau = 1.0;  // relaxation time of the even part, lattice units; must exceed 1/2
  // TRT "magic" parameter Lambda = (tau_even - 1/2)(tau_odd - 1/2). 3/16 puts half-way bounce-back
  // walls exactly half-way for Poiseuille flow, whatever tau (Ginzburg & d'Humieres 2003).
  double magic_parameter = 3.0 / 16.0;
};

struct RelaxationRates {
  double even = 1.0;  // omega+ = 1/tau
  double odd = 1.0;   // omega-
};

struct CollisionModel {
  std::string_view name;
  std::string_view summary;
  RelaxationRates (*rates)(const CollisionParameters&);
};

// Every registered model, in the order of the table.
std::span<const CollisionModel> collision_models();

// The rates of the named model. Throws rbcsim::InputError naming `lattice.collision` (and the known
// names) for an unknown model, `lattice.relaxation_time` for tau <= 1/2, `lattice.trt_magic` for
// Lambda <= 0.
RelaxationRates relaxation_rates(std::string_view model, const CollisionParameters& parameters);

}  // namespace rbcsim::lattice
