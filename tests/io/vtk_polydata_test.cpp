// The .vtp writer: structure ParaView expects, values written back exactly enough, and refusal
// of arrays that do not match the points.
#include "io/vtk_polydata.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <vector>

namespace {

using rbcsim::Vec3;
using Triangle = std::array<std::int32_t, 3>;

// The whitespace-separated numbers between the opening tag that contains `marker` and the next
// closing tag.
std::vector<double> numbers_after(const std::string& text, const std::string& marker) {
  const auto tag = text.find(marker);
  EXPECT_NE(tag, std::string::npos) << marker;
  const auto begin = text.find('>', tag) + 1;
  const auto end = text.find("</DataArray>", begin);
  std::istringstream in(text.substr(begin, end - begin));
  std::vector<double> values;
  for (double value; in >> value;) values.push_back(value);
  return values;
}

TEST(VtkPolyData, WritesPointsTrianglesAndNamedArrays) {
  const std::vector<Vec3> points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1.25)};
  const std::vector<Triangle> triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const std::vector<double> pressure = {1.5, -2.0, 3.0e-7, 4.0};
  const std::vector<Vec3> force = {Vec3(1, 2, 3), Vec3(4, 5, 6), Vec3(7, 8, 9), Vec3(-1, 0, 0.5)};
  const std::vector<rbcsim::io::PointDataArray> arrays = {
      rbcsim::io::scalar_point_array("pressure", pressure),
      rbcsim::io::vector_point_array("force_link_pN", force)};
  std::ostringstream out;
  rbcsim::io::write_vtk_polydata(out, points, triangles, arrays);
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\"", 0), 0u);
  EXPECT_NE(text.find("NumberOfPoints=\"4\""), std::string::npos);
  EXPECT_NE(text.find("NumberOfPolys=\"4\""), std::string::npos);
  EXPECT_EQ(numbers_after(text, "Name=\"pressure\""), pressure);
  EXPECT_EQ(numbers_after(text, "Name=\"force_link_pN\" NumberOfComponents=\"3\""),
            (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, -1, 0, 0.5}));
  EXPECT_EQ(numbers_after(text, "Name=\"Points\""),
            (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1.25}));
  EXPECT_EQ(numbers_after(text, "Name=\"connectivity\""),
            (std::vector<double>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  EXPECT_EQ(numbers_after(text, "Name=\"offsets\""), (std::vector<double>{3, 6, 9, 12}));
  EXPECT_NE(text.find("</VTKFile>\n"), std::string::npos);
}

TEST(VtkPolyData, RejectsArraysOfTheWrongLengthAndBadTriangles) {
  const std::vector<Vec3> points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const std::vector<Triangle> triangle = {{0, 1, 2}};
  const std::vector<double> too_short = {1.0, 2.0};
  std::ostringstream out;
  const std::vector<rbcsim::io::PointDataArray> bad = {
      rbcsim::io::scalar_point_array("short", too_short)};
  EXPECT_THROW(rbcsim::io::write_vtk_polydata(out, points, triangle, bad), std::invalid_argument);
  const std::vector<Triangle> dangling = {{0, 1, 3}};
  EXPECT_THROW(rbcsim::io::write_vtk_polydata(out, points, dangling, {}), std::invalid_argument);
}

}  // namespace
