// Collision models, chosen by name (`lattice.collision`) from one table. Both registered models are
// two-relaxation-time operators (Ginzburg, Verhaeghe & d'Humieres 2008): the populations' even
// (symmetric) part relaxes at omega_even, which sets the viscosity nu = (1/omega_even - 1/2)/3, and
// the odd part at omega_odd. BGK is the special case omega_odd = omega_even, so one kernel serves
// both and adding a model of this family is one table row in collision.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

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

// Per-node viscosity (a viscosity contrast, e.g. the cytoplasm of cells): every node carries a
// class k = 0..255 standing for the indicator H = k / 255 in [0, 1] (0: the outer fluid, 1: the
// inner one), and relaxes at the rates of its class,
//   tau+(H) - 1/2 = (tau - 1/2) [1 + (ratio - 1) H],
// i.e. the kinematic viscosity is linear in H from nu (H = 0) to ratio * nu (H = 1). Each class's
// rates come from the named model at that tau+, so TRT keeps its magic parameter Lambda (walls
// stay half-way whatever the local viscosity) and BGK relaxes both parts at 1/tau+. A byte per
// node (a table of 256 rates fits in L1) costs less bandwidth than a rate per node, and the
// quantisation (1/255 of the contrast) is far below the indicator's own smoothing error.
using ViscosityClass = std::uint8_t;
inline constexpr int kViscosityClasses = 256;

// The class nearest to the indicator H, which must lie in [0, 1].
ViscosityClass viscosity_class(double indicator);

// The rates of every class, kViscosityClasses entries; class 0 gets exactly
// relaxation_rates(model, parameters). Throws as relaxation_rates, and InputError naming
// `physics.cytoplasm_viscosity_ratio` unless 0 < ratio < infinity.
std::vector<RelaxationRates> viscosity_class_rates(std::string_view model,
                                                   const CollisionParameters& parameters,
                                                   double viscosity_ratio);

}  // namespace rbcsim::lattice
