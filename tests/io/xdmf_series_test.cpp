// The XDMF time series over HDF5 snapshots: well-formed XML in the layout ParaView's XDMF reader
// takes (a temporal collection; z y x order for images), names that would break it refused, and
// the entries read back for a resumed run.
#include "io/xdmf_series.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "common/errors.hpp"
#include "support/files.hpp"
#include "support/scratch_directory.hpp"
#include "support/xml_document.hpp"

namespace rbcsim::io::xdmf_test {
namespace {

const std::vector<XdmfArray> kFluidArrays = {{"velocity_m_per_s", 3, XdmfNumber::float64},
                                             {"solid_mask", 1, XdmfNumber::uint8}};

TEST(XdmfSeries, AnImageSeriesListsEachSnapshotWithItsTimeAndDatasets) {
  const testing::ScratchDirectory scratch;
  const XdmfImage image{{4, 5, 6}, {-1.0, 0.5, 2.0}, 0.25};
  const std::vector<XdmfEntry> entries = {{0.0, "h5/fluid_000000000.h5"},
                                          {2.5e-4, "h5/fluid_000000100.h5"}};
  write_xdmf_series(scratch.path() / "fluid.xdmf", image, kFluidArrays, entries);
  const auto document = testing::parse_xml(testing::read_text(scratch.path() / "fluid.xdmf"));
  ASSERT_EQ(document.error, "");
  const auto collections = document.find("Grid");
  ASSERT_EQ(collections.size(), 3u);  // the temporal collection and its two grids
  EXPECT_EQ(document.elements[collections[0]].attribute("CollectionType"), "Temporal");
  const auto times = document.find("Time");
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(document.elements[times[1]].attribute("Value"), "0.00025");
  const auto topologies = document.find("Topology");
  // XDMF lists the slowest axis first: nz ny nx, and the origin as z y x.
  EXPECT_EQ(document.elements[topologies[0]].attribute("Dimensions"), "6 5 4");
  bool origin_found = false;
  bool velocity_found = false;
  for (const auto i : document.find("DataItem")) {
    const auto& item = document.elements[i];
    if (item.attribute("Name") == "Origin") origin_found = item.text == "2 0.5 -1";
    if (item.text == "h5/fluid_000000100.h5:/velocity_m_per_s") {
      velocity_found = item.attribute("Dimensions") == "6 5 4 3" &&
                       item.attribute("NumberType") == "Float" &&
                       item.attribute("Precision") == "8" && item.attribute("Format") == "HDF";
    }
  }
  EXPECT_TRUE(origin_found);
  EXPECT_TRUE(velocity_found);
}

TEST(XdmfSeries, ASurfaceSeriesNamesItsTrianglesAndPoints) {
  const testing::ScratchDirectory scratch;
  const XdmfTriangles surface{162, 320, "points_um", "triangles"};
  const std::vector<XdmfArray> arrays = {{"cell_id", 1, XdmfNumber::int32}};
  const std::vector<XdmfEntry> entries = {{1e-5, "h5/cells_000000004.h5"}};
  write_xdmf_series(scratch.path() / "cells.xdmf", surface, arrays, entries);
  const auto document = testing::parse_xml(testing::read_text(scratch.path() / "cells.xdmf"));
  ASSERT_EQ(document.error, "");
  const auto topology = document.find("Topology");
  ASSERT_EQ(topology.size(), 1u);
  EXPECT_EQ(document.elements[topology[0]].attribute("TopologyType"), "Triangle");
  EXPECT_EQ(document.elements[topology[0]].attribute("NumberOfElements"), "320");
  std::vector<std::string> items;
  for (const auto i : document.find("DataItem")) {
    items.push_back(document.elements[i].attribute("Dimensions") + " " +
                    document.elements[i].attribute("NumberType") + " " + document.elements[i].text);
  }
  EXPECT_EQ(items, (std::vector<std::string>{"320 3 Int h5/cells_000000004.h5:/triangles",
                                             "162 3 Float h5/cells_000000004.h5:/points_um",
                                             "162 Int h5/cells_000000004.h5:/cell_id"}));
}

TEST(XdmfSeries, RefusesNamesThatWouldBreakTheXmlOrTheDatasetPath) {
  const testing::ScratchDirectory scratch;
  const XdmfImage image{{2, 2, 2}, {0.0, 0.0, 0.0}, 1.0};
  const auto path = scratch.path() / "x.xdmf";
  for (const std::string bad : {"", "a<b", "a:b", "a\"b"}) {
    const std::vector<XdmfEntry> entries = {{0.0, bad}};
    EXPECT_THROW(write_xdmf_series(path, image, kFluidArrays, entries), std::invalid_argument)
        << bad;
    const std::vector<XdmfArray> arrays = {{bad, 1, XdmfNumber::float64}};
    const std::vector<XdmfEntry> good = {{0.0, "h5/a.h5"}};
    EXPECT_THROW(write_xdmf_series(path, image, arrays, good), std::invalid_argument) << bad;
  }
  const std::vector<XdmfArray> two_components = {{"a", 2, XdmfNumber::float64}};
  EXPECT_THROW(write_xdmf_series(path, image, two_components, {}), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(XdmfSeries, ReadsBackEveryEntryItWrote) {
  const testing::ScratchDirectory scratch;
  const std::vector<XdmfEntry> entries = {
      {0.0, "h5/fluid_000000000.h5"}, {1.1e-06, "h5/fluid_000000013.h5"}, {0.1 + 0.2, "b.h5"}};
  const XdmfTriangles surface{3, 1, "points_um", "triangles"};
  write_xdmf_series(scratch.path() / "cells.xdmf", surface, kFluidArrays, entries);
  const auto read = read_xdmf_series(scratch.path() / "cells.xdmf");
  ASSERT_EQ(read.size(), entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    EXPECT_EQ(read[i].time, entries[i].time) << i;
    EXPECT_EQ(read[i].file, entries[i].file) << i;
  }
}

TEST(XdmfSeries, ReadingSomethingElseNamesTheFile) {
  const testing::ScratchDirectory scratch;
  const auto path = scratch.path() / "not.xdmf";
  testing::write_file(path, "<VTKFile/>\n");
  try {
    read_xdmf_series(path);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("not.xdmf"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace rbcsim::io::xdmf_test
