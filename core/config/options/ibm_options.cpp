#include <string>
#include <vector>

#include "common/registry.hpp"
#include "config/options/option_areas.hpp"
#include "coupling/coupled_simulation.hpp"
#include "ibm/delta_kernels.hpp"
#include "ibm/point_advance.hpp"

namespace rbcsim::config {
namespace {

// The choices are the names of the IBM module's tables, the defaults the coupled loop's: one source
// of truth each.
const coupling::CouplingParameters kIbmDefaults{};

}  // namespace

void add_ibm_options(OptionTable& table) {
  table.add_choice("ibm.kernel", entry_names(ibm::delta_kernels()), kIbmDefaults.kernel,
                   "Immersed-boundary kernel: phi2 (trilinear, HemoCell's default), phi3, phi4 "
                   "(Peskin).");
  table.add_choice("ibm.point_advance", entry_names(ibm::point_advance_schemes()),
                   kIbmDefaults.point_advance,
                   "How vertices follow the interpolated velocity: euler (x += u dt, HemoCell's "
                   "scheme) or ab2 (second-order Adams-Bashforth).");
}

}  // namespace rbcsim::config
