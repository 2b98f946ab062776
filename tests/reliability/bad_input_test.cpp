// The bad-input matrix (docs/architecture.md) through the built binary: every defective mesh or
// config gives exit code 2, exactly one line on stderr that names the file and the problem, and
// leaves no output file or run directory behind. The bad files are generated here, small, from an
// octahedron.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"

namespace {

namespace fs = std::filesystem;
using rbcsim::testing::run_rbcsim;
using rbcsim::testing::ScratchDirectory;

using Point = std::array<float, 3>;
using Face = std::array<int, 3>;

struct Surface {
  std::vector<Point> points;
  std::vector<Face> faces;
};

// A closed, outward-oriented octahedron of radius 1.
Surface octahedron() {
  return {{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
          {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
}

// Two surfaces as one file (the second's indices shifted).
Surface together(const Surface& first, const Surface& second) {
  Surface both = first;
  const int base = static_cast<int>(first.points.size());
  both.points.insert(both.points.end(), second.points.begin(), second.points.end());
  for (const auto& f : second.faces) both.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  return both;
}

Surface shifted(Surface surface, float dx) {
  for (auto& p : surface.points) p[0] += dx;
  return surface;
}

std::string off_text(const Surface& surface) {
  std::string text = "OFF\n" + std::to_string(surface.points.size()) + " " +
                     std::to_string(surface.faces.size()) + " 0\n";
  for (const auto& p : surface.points) {
    text += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  }
  for (const auto& f : surface.faces) {
    text += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) +
            "\n";
  }
  return text;
}

template <typename T>
void append_bytes(std::string& bytes, const T& value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

// 80-byte header, triangle count, then per triangle a normal, three corners and 2 spare bytes.
std::string binary_stl(const Surface& surface, std::uint32_t declared_count) {
  std::string bytes(80, ' ');
  append_bytes(bytes, declared_count);
  for (const auto& f : surface.faces) {
    const Point normal{0, 0, 0};
    append_bytes(bytes, normal);
    for (int k = 0; k < 3; ++k) append_bytes(bytes, surface.points[static_cast<std::size_t>(f[k])]);
    append_bytes(bytes, std::uint16_t{0});
  }
  return bytes;
}

std::string binary_stl(const Surface& surface) {
  return binary_stl(surface, static_cast<std::uint32_t>(surface.faces.size()));
}

class BadInput : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& bytes) const {
    const auto file = scratch_.path() / name;
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
  }

  // Every way a mesh reaches the program: import (with an output file), info, and a stretch run
  // whose config names it. Each must refuse it with one line naming it and `problem`.
  void expect_mesh_refused(const fs::path& file, const std::string& problem) const {
    const auto quoted = "'" + file.string() + "'";
    const auto output = scratch_.path() / "out.stl";
    expect_refused("mesh import " + quoted + " -o '" + output.string() + "'", file, problem);
    EXPECT_FALSE(fs::exists(output));
    expect_refused("mesh info " + quoted, file, problem);
    const auto config = write("mesh_file.json", R"({"mesh": {"file": ")" + file.string() + "\"}}");
    expect_stretch_refused(config, file, problem);
  }

  void expect_config_refused(const fs::path& config, const std::string& problem) const {
    expect_refused("config show --config '" + config.string() + "'", config, problem);
    expect_stretch_refused(config, config, problem);
  }

  void expect_stretch_refused(const fs::path& config, const fs::path& named,
                              const std::string& problem) const {
    const auto run_dir = scratch_.path() / "run";
    expect_refused(
        "stretch --set mesh.subdivisions=1 --set mesh.method=parametric --forces 0 --config '" +
            config.string() + "' --output '" + run_dir.string() + "'",
        named, problem);
    EXPECT_FALSE(fs::exists(run_dir));
  }

  // An experiment command refused before it makes its run directory.
  void expect_run_refused(const std::string& arguments, const std::string& named,
                          const std::string& problem) const {
    const auto run_dir = scratch_.path() / "run";
    expect_refused(arguments + " --quiet --threads 1 --output '" + run_dir.string() + "'", named,
                   problem);
    EXPECT_FALSE(fs::exists(run_dir));
  }

  void expect_refused(const std::string& arguments, const fs::path& named,
                      const std::string& problem) const {
    const auto result = run_rbcsim(arguments, scratch_.path());
    EXPECT_EQ(result.exit_code, 2) << arguments << "\n" << result.err;
    EXPECT_EQ(result.out, "") << arguments;
    ASSERT_FALSE(result.err.empty()) << arguments;
    EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "not one line: " << result.err;
    EXPECT_EQ(result.err.rfind("rbcsim: error: ", 0), 0u) << result.err;
    EXPECT_NE(result.err.find(named.string()), std::string::npos)
        << "does not name " << named << ": " << result.err;
    EXPECT_NE(result.err.find(problem), std::string::npos)
        << "expected '" << problem << "' in: " << result.err;
  }

  ScratchDirectory scratch_;
};

TEST_F(BadInput, ValidOctahedronIsAccepted) {  // the base every defect below is made from
  const auto stl = write("good.stl", binary_stl(octahedron()));
  const auto result = run_rbcsim("mesh info '" + stl.string() + "'", scratch_.path());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  const auto off = write("good.off", off_text(octahedron()));
  EXPECT_EQ(run_rbcsim("mesh info '" + off.string() + "'", scratch_.path()).exit_code, 0);
}

TEST_F(BadInput, TruncatedBinaryStl) {
  auto bytes = binary_stl(octahedron());
  bytes.resize(bytes.size() - 20);
  expect_mesh_refused(write("truncated.stl", bytes), "truncated");
}

TEST_F(BadInput, BinaryStlWhoseHeaderCountDisagreesWithItsSize) {
  expect_mesh_refused(write("count.stl", binary_stl(octahedron(), 100)),
                      "header declares 100 triangles");
}

TEST_F(BadInput, AsciiStlWithASyntaxError) {
  const std::string text =
      "solid broken\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
      "   vertex 0 1 0\n  endloop\n endfacet\n facet normal 0 0 1\n  outer lop\n"
      "   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1\n  endloop\n endfacet\nendsolid broken\n";
  expect_mesh_refused(write("syntax.stl", text), "line 10: expected 'loop', got 'lop' (ASCII STL)");
}

TEST_F(BadInput, NanCoordinate) {
  auto surface = octahedron();
  surface.points[2][1] = std::numeric_limits<float>::quiet_NaN();
  expect_mesh_refused(write("nan.stl", binary_stl(surface)), "NaN or infinite coordinate");
}

TEST_F(BadInput, InfiniteCoordinate) {
  auto surface = octahedron();
  surface.points[4][2] = std::numeric_limits<float>::infinity();
  expect_mesh_refused(write("inf.stl", binary_stl(surface)), "NaN or infinite coordinate");
}

TEST_F(BadInput, ZeroAreaTriangle) {
  auto surface = octahedron();
  surface.points.push_back({0, 0, 0});  // on the segment between vertices 0 and 1
  surface.faces.push_back({0, 6, 1});
  expect_mesh_refused(write("flat.off", off_text(surface)), "degenerate (zero-area) triangle");
}

TEST_F(BadInput, DuplicateTriangle) {
  auto surface = octahedron();
  surface.faces.push_back(surface.faces[3]);
  expect_mesh_refused(write("twice.off", off_text(surface)), "duplicate triangle");
}

TEST_F(BadInput, OpenSurface) {
  auto surface = octahedron();
  surface.faces.pop_back();
  expect_mesh_refused(write("open.stl", binary_stl(surface)), "open surface");
}

TEST_F(BadInput, NonManifoldEdge) {
  // Two tetrahedra sharing the edge 0-1: four triangles meet there, no edge is open.
  const Surface bowtie{
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}, {0, 0, -1}},
      {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 4, 1}, {0, 1, 5}, {1, 4, 5}, {0, 5, 4}}};
  expect_mesh_refused(write("bowtie.off", off_text(bowtie)), "not a 2-manifold");
}

TEST_F(BadInput, TwoSeparateBodies) {
  expect_mesh_refused(
      write("two.stl", binary_stl(together(octahedron(), shifted(octahedron(), 5)))),
      "2 separate connected surfaces");
}

TEST_F(BadInput, EmptyFile) { expect_mesh_refused(write("empty.stl", ""), "empty file"); }

TEST_F(BadInput, MeshOrConfigPathThatIsNotAFile) {
  const auto directory = scratch_.path() / "cell.stl";
  fs::create_directory(directory);
  expect_mesh_refused(directory, "is a directory");
  // A device exists but is no file: /dev/null must not read as an empty mesh or config.
  expect_refused("mesh info /dev/null", "/dev/null", "is not a regular file");
  expect_refused("config show --config /dev/null", "/dev/null", "is not a regular file");
}

TEST_F(BadInput, FileThatIsNotAMesh) {
  expect_mesh_refused(write("notes.stl", "These are my notes, not a mesh.\n"), "binary STL");
  std::string noise(1000, '\0');
  for (std::size_t i = 0; i < noise.size(); ++i) noise[i] = static_cast<char>((i * 7919) % 251);
  expect_mesh_refused(write("noise.ply", noise), "not a readable mesh");
}

TEST_F(BadInput, MeshTooLargeForMemoryIsRefusedBeforeReading) {
  // A sparse file whose size agrees with its header's billion triangles: reading it would need
  // hundreds of GB. It must be refused from the header alone, without touching the rest.
  const auto file = scratch_.path() / "huge.stl";
  constexpr std::uint32_t kTriangles = 1'000'000'000;
  write("huge.stl", binary_stl({}, kTriangles));
  fs::resize_file(file, 84 + 50ULL * kTriangles);
  expect_mesh_refused(file, "available memory");
}

TEST_F(BadInput, MeshAboveTheConfiguredTriangleLimit) {
  const auto file = write("cap.stl", binary_stl(octahedron()));
  const auto config =
      write("cap.json", R"({"mesh": {"file": ")" + file.string() + R"(", "max_triangles": 4}})");
  expect_stretch_refused(config, file, "more than the limit of 4 (mesh.max_triangles)");
}

TEST_F(BadInput, InsideOutMeshIsRepairedWithANotice) {
  auto surface = octahedron();
  for (auto& f : surface.faces) std::swap(f[1], f[2]);
  const auto file = write("inside_out.stl", binary_stl(surface));
  const auto output = scratch_.path() / "out.stl";
  const auto result = run_rbcsim("mesh import '" + file.string() + "' -o '" + output.string() + "'",
                                 scratch_.path());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "rbcsim: notice: " + file.string() +
                            ": the surface was inside out (normals pointing inwards); flipped all "
                            "8 triangles\n");
  EXPECT_TRUE(fs::exists(output));
}

TEST_F(BadInput, JsonSyntaxErrorGivesLineAndColumn) {
  expect_config_refused(write("syntax.json", "{\n  \"lattice\": {\"spacing_um\": 0.5,,}\n}\n"),
                        "line 2, column");
}

TEST_F(BadInput, UnknownKeySuggestsTheKnownOne) {
  expect_config_refused(write("typo.json", R"({"lattice": {"spacing_uM": 0.5}})"),
                        "unknown key; did you mean `lattice.spacing_um`?");
}

TEST_F(BadInput, WrongType) {
  expect_config_refused(write("type.json", R"({"lattice": {"spacing_um": "half"}})"),
                        "lattice.spacing_um: expected number");
}

TEST_F(BadInput, RelaxationTimeAtTheStabilityLimit) {
  expect_config_refused(write("tau.json", R"({"lattice": {"relaxation_time": 0.5}})"),
                        "lattice.relaxation_time");
}

TEST_F(BadInput, OutOfRangeValue) {
  expect_config_refused(write("range.json", R"({"mesh": {"subdivisions": -3}})"),
                        "mesh.subdivisions");
}

// A command's own option stands for a config key (--geometry for capillary.geometry); a bad value
// is diagnosed under the option the user typed, not as a --set the user never wrote.
TEST_F(BadInput, ACommandOptionsBadValueIsNamedAsThatOption) {
  const struct {
    std::string arguments;
    std::string option;
    std::string problem;
  } cases[] = {
      {"capillary --geometry foo", "--geometry: capillary.geometry",
       "\"foo\" is not one of paper-validation, paper-morphology"},
      {"stretch --mode slow", "--mode: stretch.mode", "\"slow\" is not one of"},
      {"stretch --contact-diameter-um -1", "--contact-diameter-um: stretch.contact.diameter_um",
       "must be > 0"},
      {"shear --boundary box", "--boundary: shear.boundary", "\"box\" is not one of"},
      {"shear --max-strain -3", "--max-strain: shear.max_strain", "must be > 0"},
      {"calibrate --fits stretch,bend2", "--fits: calibrate.fits", "\"bend2\" is not one of"},
      {"calibrate --target-poisson-ratio 3", "--target-poisson-ratio: calibrate.target",
       "must be < 1"},
  };
  for (const auto& bad : cases) {
    expect_run_refused(bad.arguments, bad.option, bad.problem);
    EXPECT_EQ(run_rbcsim(bad.arguments, scratch_.path()).err.find("--set"), std::string::npos)
        << bad.arguments;
  }
}

// "Cell larger than the domain": the cell plus the IBM kernel's reach (phi2: 1 lattice spacing,
// phi4: 2) on each side must fit the periodic box or the lumen. The 7.82 um discocyte.
TEST_F(BadInput, ShearBoxTooSmallForTheCellAndTheKernel) {
  // dx = 4 um: a 4-node (16 um) box along x holds 7.82 + 2 x 2 x 4 um with phi4 only.
  expect_run_refused(
      "shear --rates 500 --set mesh.subdivisions=2 --set mesh.method=parametric --set "
      "lattice.spacing_um=4 "
      "--set ibm.kernel=phi4",
      "shear box",
      "the cell does not fit the domain along x: 7.82 um of cell plus 16 um of "
      "clearance (2 lattice spacings per side) exceed the domain's 16 um");
  // phi2, dx = 0.5 um: 1.05 diameters (17 nodes, 8.5 um) are less than 7.82 + 2 x 0.5 um.
  expect_run_refused(
      "shear --rates 500 --set mesh.subdivisions=2 --set mesh.method=parametric --set "
      "shear.width_diameters=1.05",
      "shear box", "does not fit the domain along x");
}

TEST_F(BadInput, FluidStretchBoxTooSmallForTheCellAndTheKernel) {
  // dx = 2 um, margin 0.5 um: 5 nodes (10 um) across y, less than 7.82 + 2 x 2 um (phi2).
  expect_run_refused(
      "stretch --mode fluid --forces 0 --set mesh.subdivisions=1 --set mesh.method=parametric "
      "--set lattice.spacing_um=2 "
      "--set stretch.fluid.box_margin_um=0.5",
      "stretch.fluid.box_margin_um", "the cell does not fit the domain along y");
}

TEST_F(BadInput, CapillaryLumenTooNarrowForTheCell) {  // the capillary's own check, before settling
  expect_run_refused(
      "capillary --set mesh.subdivisions=2 --set mesh.method=parametric --set lattice.spacing_um=1 "
      "--set mesh.discocyte.radius_um=8",
      "capillary.release_gap_um", "the released cell does not fit in the lumen");
}

}  // namespace
