#include "io/xdmf_series.hpp"

#include <ostream>
#include <stdexcept>
#include <string_view>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/atomic_file.hpp"
#include "io/text_file.hpp"
#include "io/xml_attribute.hpp"

namespace rbcsim::io {
namespace {

void require_plain(const std::string& text, const char* what) {
  if (text.empty() || text.find_first_of("<>&\"':") != std::string::npos) {
    throw std::invalid_argument(std::string("XDMF ") + what + " '" + text +
                                "' must be non-empty plain text (no XML markup, no colon)");
  }
}

// NumberType and Precision of a DataItem.
std::string number_type(XdmfNumber number) {
  switch (number) {
    case XdmfNumber::float64:
      return "NumberType=\"Float\" Precision=\"8\"";
    case XdmfNumber::int32:
      return "NumberType=\"Int\" Precision=\"4\"";
    case XdmfNumber::uint8:
      return "NumberType=\"UChar\" Precision=\"1\"";
  }
  return {};
}

// A DataItem reading dataset `dataset` of `file`.
void write_hdf_item(std::ostream& out, const std::string& dimensions, XdmfNumber number,
                    const std::string& file, const std::string& dataset, const char* indent) {
  out << indent << "<DataItem Dimensions=\"" << dimensions << "\" " << number_type(number)
      << " Format=\"HDF\">" << file << ":/" << dataset << "</DataItem>\n";
}

// Topology and geometry of one grid; returns the dimensions of a per-point scalar.
std::string write_geometry(std::ostream& out, const XdmfImage& image, const std::string& /*file*/) {
  // XDMF lists the slowest axis first: z, y, x.
  const std::string dimensions = std::to_string(image.nodes[2]) + " " +
                                 std::to_string(image.nodes[1]) + " " +
                                 std::to_string(image.nodes[0]);
  out << "        <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << dimensions << "\"/>\n"
      << "        <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
      << "          <DataItem Name=\"Origin\" Dimensions=\"3\" NumberType=\"Float\" "
         "Precision=\"8\" Format=\"XML\">"
      << format_number(image.origin[2]) << " " << format_number(image.origin[1]) << " "
      << format_number(image.origin[0]) << "</DataItem>\n"
      << "          <DataItem Name=\"Spacing\" Dimensions=\"3\" NumberType=\"Float\" "
         "Precision=\"8\" Format=\"XML\">"
      << format_number(image.spacing) << " " << format_number(image.spacing) << " "
      << format_number(image.spacing) << "</DataItem>\n"
      << "        </Geometry>\n";
  return dimensions;
}

std::string write_geometry(std::ostream& out, const XdmfTriangles& surface,
                           const std::string& file) {
  out << "        <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << surface.triangles
      << "\">\n";
  write_hdf_item(out, std::to_string(surface.triangles) + " 3", XdmfNumber::int32, file,
                 surface.triangles_dataset, "          ");
  out << "        </Topology>\n        <Geometry GeometryType=\"XYZ\">\n";
  write_hdf_item(out, std::to_string(surface.points) + " 3", XdmfNumber::float64, file,
                 surface.points_dataset, "          ");
  out << "        </Geometry>\n";
  return std::to_string(surface.points);
}

void write_grid(std::ostream& out, const XdmfLayout& layout, std::span<const XdmfArray> arrays,
                const XdmfEntry& entry) {
  out << "      <Grid Name=\"" << entry.file << "\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << format_number(entry.time) << "\"/>\n";
  const std::string dimensions = std::visit(
      [&](const auto& geometry) { return write_geometry(out, geometry, entry.file); }, layout);
  for (const auto& array : arrays) {
    const bool vector = array.components == 3;
    out << "        <Attribute Name=\"" << array.name << "\" AttributeType=\""
        << (vector ? "Vector" : "Scalar") << "\" Center=\"Node\">\n";
    write_hdf_item(out, dimensions + (vector ? " 3" : ""), array.number, entry.file, array.name,
                   "          ");
    out << "        </Attribute>\n";
  }
  out << "      </Grid>\n";
}

}  // namespace

void write_xdmf_series(const std::filesystem::path& path, const XdmfLayout& layout,
                       std::span<const XdmfArray> arrays, std::span<const XdmfEntry> entries) {
  for (const auto& array : arrays) {
    require_plain(array.name, "array name");
    if (array.components != 1 && array.components != 3) {
      throw std::invalid_argument("XDMF array " + array.name + ": 1 or 3 components");
    }
  }
  if (const auto* surface = std::get_if<XdmfTriangles>(&layout)) {
    require_plain(surface->points_dataset, "points dataset");
    require_plain(surface->triangles_dataset, "triangles dataset");
  }
  for (const auto& entry : entries) require_plain(entry.file, "file");
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<Xdmf Version=\"3.0\">\n"
           "  <Domain>\n"
           "    <Grid Name=\"series\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& entry : entries) write_grid(out, layout, arrays, entry);
    out << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  });
}

std::vector<XdmfEntry> read_xdmf_series(const std::filesystem::path& path) {
  const std::string text = read_text_file(path);
  if (text.find("<Xdmf ") == std::string::npos || text.find("</Xdmf>") == std::string::npos) {
    throw InputError(path.string(), "not a complete XDMF series (.xdmf)");
  }
  std::vector<XdmfEntry> entries;
  for (auto begin = text.find("<Grid Name="); begin != std::string::npos;
       begin = text.find("<Grid Name=", begin + 1)) {
    const auto end = text.find('>', begin);
    if (end == std::string::npos) throw InputError(path.string(), "an unterminated Grid");
    const std::string_view element(text.data() + begin, end - begin);
    if (element.find("GridType=\"Uniform\"") == std::string_view::npos) continue;
    const auto time = text.find("<Time ", end);
    const auto time_end = time == std::string::npos ? time : text.find("/>", time);
    if (time_end == std::string::npos) throw InputError(path.string(), "a Grid without a Time");
    entries.push_back(
        {xml_number_attribute(std::string_view(text.data() + time, time_end - time), "Value", path),
         xml_attribute(element, "Name", path)});
  }
  return entries;
}

}  // namespace rbcsim::io
