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
  table.add_boolean("ibm.hold_volume", kIbmDefaults.hold_volume,
                    "Move each cell's vertices less the multiple of its volume gradient that "
                    "would change its enclosed volume (the membrane lets no water through; the "
                    "interpolated velocity leaks): on in the physiological preset, off in the "
                    "paper's (HemoCell has no such step).");
  table.add_boolean("ibm.sub_spacing_drag", kIbmDefaults.sub_spacing_drag,
                    "Also move each vertex with the fluid's Stokes drag on the part of its force "
                    "its edge neighbours do not share (wavenumber pi / edge length; normal motion "
                    "at half the rate), which the lattice cannot carry: holds membrane modes "
                    "finer than a spacing; with ibm.hold_volume. "
                    "On in the physiological preset, off in the paper's (HemoCell has no such "
                    "step).");
  // H has slope <= 1/eps (eps >= 1 dx): 0.05 dx keeps the classes within 0.05 of the membrane's H.
  table
      .add_number("ibm.cytoplasm_update_dx", "dx", kIbmDefaults.cytoplasm_update_lu,
                  "With physics.cytoplasm_viscosity_ratio != 1: recompute where the cytoplasm is "
                  "once a vertex has moved this far since the last time; 0: every step.")
      .at_least(0.0)
      .at_most(0.5);
}

}  // namespace rbcsim::config
