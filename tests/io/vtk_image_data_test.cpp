// The .vti writer: the grid ParaView reconstructs (extent, origin, spacing) and point arrays in
// the lattice's x-fastest order.
#include "io/vtk_image_data.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <vector>

#include "support/vtk_base64.hpp"

namespace {

TEST(VtkImageData, WritesTheGridAndArraysInNodeOrder) {
  const rbcsim::io::ImageGrid grid{{3, 2, 2}, rbcsim::Vec3(-1.5, 0.0, 2.25), 0.5};
  ASSERT_EQ(grid.point_count(), 12u);
  std::vector<double> x_of_point;
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 3; ++i) x_of_point.push_back(-1.5 + 0.5 * i);
    }
  }
  const std::vector<std::uint8_t> mask = {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
  const std::vector<rbcsim::io::PointDataArray> arrays = {
      rbcsim::io::scalar_point_array("x_um", x_of_point),
      rbcsim::io::byte_point_array("solid_mask", mask)};
  std::ostringstream out;
  rbcsim::io::write_vtk_image_data(out, grid, arrays);
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\"", 0), 0u);
  EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(text.find("WholeExtent=\"0 2 0 1 0 1\" Origin=\"-1.5 0 2.25\" Spacing=\"0.5 0.5 0.5\""),
            std::string::npos);
  EXPECT_NE(text.find("<Piece Extent=\"0 2 0 1 0 1\">"), std::string::npos);
  const auto body_of = [&](const std::string& name) {
    const auto tag = text.find("Name=\"" + name + "\"");
    const auto begin = text.find('>', tag) + 1;
    return text.substr(begin, text.find("</DataArray>", begin) - begin);
  };
  EXPECT_EQ(rbcsim::testing::decode_vtk_binary<double>(body_of("x_um")), x_of_point);
  EXPECT_EQ(rbcsim::testing::decode_vtk_binary<std::uint8_t>(body_of("solid_mask")), mask);
  EXPECT_NE(text.find("</VTKFile>\n"), std::string::npos);
}

TEST(VtkImageData, RejectsEmptyAxesAndShortArrays) {
  std::ostringstream out;
  EXPECT_THROW(rbcsim::io::write_vtk_image_data(out, {{0, 2, 2}, rbcsim::Vec3::Zero(), 1.0}, {}),
               std::invalid_argument);
  const std::vector<double> short_values(3, 0.0);
  const std::vector<rbcsim::io::PointDataArray> arrays = {
      rbcsim::io::scalar_point_array("short", short_values)};
  EXPECT_THROW(
      rbcsim::io::write_vtk_image_data(out, {{2, 2, 1}, rbcsim::Vec3::Zero(), 1.0}, arrays),
      std::invalid_argument);
}

}  // namespace
