#include "shapes/named_cells.hpp"

#include <algorithm>

#include "shapes/sequence.hpp"
#include "shapes/shipped_shapes.hpp"

namespace rbcsim::shapes {
namespace {

std::vector<std::string> sequence_names() { return shape_sequence().names(); }

std::vector<std::string> parametric_names() {
  std::vector<std::string> names;
  for (const auto& entry : mesh::cell_shapes()) names.emplace_back(entry.name);
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string result;
  for (const auto& name : names) result += (result.empty() ? "" : ", ") + name;
  return result;
}

std::string level_text(std::string_view shape, int subdivisions) {
  return "built-in " + std::string(shape) + " level " + std::to_string(subdivisions);
}

}  // namespace

const Registry<ShapeMethod>& shape_methods() {
  static const Registry<ShapeMethod> methods(
      "shape method",
      {{"energy",
        "the minimum of bending, area-difference and skeleton energy at the shape's relaxed area "
        "difference (Lim, Wortis & Mukhopadhyay 2002)",
        sequence_names},
       {"parametric", "drawn shapes: Evans-Fung, a bent thick shell, a sphere with spicules",
        parametric_names}});
  return methods;
}

NamedCell make_named_cell(std::string_view shape, std::string_view shape_key,
                          const NamedCellSettings& settings, const EnergyShapeProgress& progress) {
  const auto& method = shape_methods().find(settings.method, "mesh.method");
  const auto names = method.shape_names();
  if (std::find(names.begin(), names.end(), shape) == names.end()) {
    throw InputError(std::string(shape_key), in_quotes(shape) + " is not a shape mesh.method " +
                                                 in_quotes(method.name) + " makes (" +
                                                 joined(names) + ")");
  }
  NamedCell cell;
  if (method.name == "parametric") {
    cell.mesh = mesh::generate_cell(shape, settings.subdivisions, settings.parametric);
    cell.source = level_text(shape, settings.subdivisions);
    return cell;
  }
  if (settings.use_shipped) {
    if (auto shipped =
            find_shipped_shape("energy", shape, settings.subdivisions, to_json(settings.energy))) {
      cell.mesh = std::move(shipped->mesh);
      cell.shipped_entry = std::move(shipped->entry);
      cell.source = level_text(shape, settings.subdivisions);
      return cell;
    }
  }
  cell.minimised = minimise_shape(settings.subdivisions, settings.energy, progress);
  cell.mesh = cell.minimised->mesh;
  cell.source = level_text(shape, settings.subdivisions);
  return cell;
}

}  // namespace rbcsim::shapes
