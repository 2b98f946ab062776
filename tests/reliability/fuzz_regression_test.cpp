// Inputs the fuzz targets (tests/fuzz) found to misbehave, kept as regression tests: each must now
// end in one InputError line. The CI's sanitizer build runs them with leak detection on.
#include <gtest/gtest.h>

#include <string>

#include "common/errors.hpp"
#include "mesh/import.hpp"
#include "support/scratch_directory.hpp"

namespace {

using rbcsim::testing::ScratchDirectory;

std::string import_problem(const std::string& file_name, const std::string& content) {
  const ScratchDirectory scratch;
  const auto file = scratch.write(file_name, content);
  try {
    rbcsim::mesh::import_mesh(file);
  } catch (const rbcsim::InputError& error) {
    return std::string(error.what()).substr(file.string().size() + 2);
  }
  return "accepted";
}

// fuzz_stl_reader, leak-af3af4ab: a keyword in another case. assimp's ASCII STL reader threw
// half-way through the facet and leaked the mesh it was building (LeakSanitizer, 2464 bytes).
TEST(FuzzRegression, AsciiStlKeywordInAnotherCase) {
  const std::string facet_start = " facet normal 0 0 0\n  outer loop\n";
  const std::string facet_end = "  endloop\n endfacet\n";
  const std::string text = "solid octahedron\n" + facet_start +
                           "   vertex 1 0 0\n   vertex 0 1 0\n   vertex 0 0 1\n" + facet_end +
                           facet_start + "   vertEx 0 1 0\n   vertex -1 0 0\n   vertex 0 0 1\n" +
                           facet_end + "endsolid octahedron\n";
  EXPECT_EQ(import_problem("leak.stl", text),
            "line 11: expected 'vertex', got 'vertEx' (ASCII STL)");
}

// fuzz_stl_reader, leak-3237a08a: a vertex's numbers split over two lines; assimp reads them line
// by line, threw, and leaked the same way.
TEST(FuzzRegression, AsciiStlVertexSplitOverTwoLines) {
  const std::string text =
      "solid split\n facet normal 0 0 0\n  outer loop\n   vertex 1 0\n 0\n   vertex 0 1 0\n"
      "   vertex 0 0 1\n  endloop\n endfacet\nendsolid split\n";
  EXPECT_EQ(import_problem("split.stl", text),
            "line 5: expected 3 numbers after 'vertex' on its line, got '0' (ASCII STL)");
}

}  // namespace
