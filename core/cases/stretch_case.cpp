#include "cases/stretch_case.hpp"

#include <array>
#include <utility>

#include "cases/fluid_stretch.hpp"
#include "cases/quasi_static_stretch.hpp"
#include "cases/stretch_geometry.hpp"
#include "common/registry.hpp"

namespace rbcsim::cases {
namespace {

struct StretchMode {
  std::string_view name;
  StretchRun (*run)(const membrane::MembraneModel&, const StretchCell&, const StretchSettings&,
                    const StretchObserver&);
};

constexpr std::array<StretchMode, 2> kStretchModes{{
    {"quasi-static", run_quasi_static_stretch},
    {"fluid", run_fluid_stretch},
}};

}  // namespace

StretchCell prepare_stretch_cell(mesh::TriangleMesh mesh, const ContactSettings& contact) {
  auto framed = in_stretch_frame(std::move(mesh));
  auto patches = select_contact_patches(framed.positions_um, contact);
  return {std::move(framed), std::move(patches)};
}

std::vector<std::string> stretch_mode_names() { return entry_names(kStretchModes); }

StretchRun run_stretch(const membrane::MembraneModel& model, const StretchCell& cell,
                       const StretchSettings& settings, const StretchObserver& observer) {
  const auto& mode = find_entry(kStretchModes, settings.mode, "stretch.mode");
  return mode.run(model, cell, settings, observer);
}

}  // namespace rbcsim::cases
