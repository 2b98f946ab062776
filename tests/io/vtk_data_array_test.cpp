// The shared <DataArray> writer: both encodings give back the values exactly enough, the base64
// form carries VTK's byte-count header, and every padding case of base64 decodes.
#include "io/vtk_data_array.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <sstream>
#include <vector>

#include "support/vtk_base64.hpp"

namespace {

using rbcsim::io::DataArray;
using rbcsim::io::VtkEncoding;

// The text between the opening <DataArray ...> tag and its closing tag.
std::string array_body(const std::string& text) {
  const auto begin = text.find('>') + 1;
  return text.substr(begin, text.find("</DataArray>") - begin);
}

std::string written(const DataArray& array, VtkEncoding encoding) {
  std::ostringstream out;
  rbcsim::io::write_data_array(out, array, encoding, "  ");
  return out.str();
}

TEST(VtkDataArray, Base64RoundTripsDoublesExactlyWithTheByteCountHeader) {
  const std::vector<double> values = {1.0 / 3.0, -2.5e-300, 6.02214076e23, 0.0, -0.0};
  const auto text = written(rbcsim::io::scalar_point_array("v", values), VtkEncoding::base64);
  EXPECT_NE(text.find("type=\"Float64\" Name=\"v\" format=\"binary\""), std::string::npos);
  EXPECT_EQ(rbcsim::testing::decode_vtk_binary<double>(array_body(text)), values);
}

TEST(VtkDataArray, Base64PadsEveryRemainderOfThree) {
  // Header (8 bytes) + n bytes: 8 + n = 0, 1, 2 (mod 3) for n = 1, 2, 3.
  for (const std::vector<std::uint8_t>& values :
       {std::vector<std::uint8_t>{7}, std::vector<std::uint8_t>{7, 255},
        std::vector<std::uint8_t>{7, 255, 0}}) {
    const auto body =
        array_body(written(rbcsim::io::byte_point_array("mask", values), VtkEncoding::base64));
    EXPECT_EQ(rbcsim::testing::decode_vtk_binary<std::uint8_t>(body), values);
    // Four characters per group of three bytes, the last group padded with '='.
    std::string encoded;
    for (const char c : body) {
      if (!std::isspace(static_cast<unsigned char>(c))) encoded.push_back(c);
    }
    EXPECT_EQ(encoded.size() % 4, 0u);
    EXPECT_EQ(encoded.size(), 4 * ((8 + values.size() + 2) / 3));
  }
}

TEST(VtkDataArray, AsciiWritesOneTupleALineAndBytesAsNumbers) {
  const std::vector<rbcsim::Vec3> vectors = {rbcsim::Vec3(1, 2, 3), rbcsim::Vec3(-4, 0.5, 6)};
  const auto text =
      written(rbcsim::io::vector_point_array("force_pN", vectors), VtkEncoding::ascii);
  EXPECT_NE(text.find("Name=\"force_pN\" NumberOfComponents=\"3\" format=\"ascii\""),
            std::string::npos);
  EXPECT_NE(text.find("1 2 3\n"), std::string::npos);
  EXPECT_NE(text.find("-4 0.5 6\n"), std::string::npos);
  const std::vector<std::uint8_t> mask = {0, 1, 2};
  const auto mask_text = written(rbcsim::io::byte_point_array("m", mask), VtkEncoding::ascii);
  EXPECT_NE(mask_text.find("type=\"UInt8\""), std::string::npos);
  std::istringstream numbers(array_body(mask_text));
  std::vector<int> read;
  for (int value; numbers >> value;) read.push_back(value);
  EXPECT_EQ(read, (std::vector<int>{0, 1, 2}));
}

TEST(VtkDataArray, ChecksNamesComponentsAndLengths) {
  const std::vector<double> three = {1, 2, 3};
  const std::vector<DataArray> good = {rbcsim::io::scalar_point_array("ok", three)};
  EXPECT_NO_THROW(rbcsim::io::check_point_arrays(3, good));
  EXPECT_THROW(rbcsim::io::check_point_arrays(2, good), std::invalid_argument);
  const std::vector<DataArray> markup = {rbcsim::io::scalar_point_array("a<b", three)};
  EXPECT_THROW(rbcsim::io::check_point_arrays(3, markup), std::invalid_argument);
  const std::vector<DataArray> two_components = {{"pairs", 2, std::span<const double>(three)}};
  EXPECT_THROW(rbcsim::io::check_point_arrays(3, two_components), std::invalid_argument);
}

}  // namespace
