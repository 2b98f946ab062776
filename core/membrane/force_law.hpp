// The force law every membrane term shares (paper Eq. 5):
//   F = -(k kBT / length) * slope(d),   slope(d) = d (1 + 1/(tau^2 - d^2))
// and, for the volume (Eq. 9, no linear term), slope(d) = d / (tau^2 - d^2).
// energy(d) is the integral of slope from 0, so a term whose energy is K * energy(d) has
// dE/dd = K * slope(d) and energy(0) = 0:
//   energy(d) = d^2/2 - (1/2) ln(1 - d^2/tau^2)   [= d^2/2 - (1/2) ln(tau^2 - d^2) + const]
//   volume:     -(1/2) ln(1 - d^2/tau^2)
// Both are singular at |d| = tau; the terms check within_limit first and never clamp.
#pragma once

#include <cmath>

namespace rbcsim::membrane {

class ForceLaw {
 public:
  static ForceLaw with_linear_term(double tau) { return ForceLaw(tau, 1.0); }
  static ForceLaw divergent_only(double tau) { return ForceLaw(tau, 0.0); }

  double tau() const { return tau_; }
  bool within_limit(double d) const { return std::abs(d) < tau_; }
  double slope(double d) const { return linear_weight_ * d + d / (tau_ * tau_ - d * d); }
  double energy(double d) const {
    const double ratio = d / tau_;
    return 0.5 * linear_weight_ * d * d - 0.5 * std::log1p(-ratio * ratio);
  }

 private:
  ForceLaw(double tau, double linear_weight) : tau_(tau), linear_weight_(linear_weight) {}
  double tau_;
  double linear_weight_;
};

}  // namespace rbcsim::membrane
