// Mesh import: every format we promise, welding, the inside-out repair, the options, and one
// clear "FILE: problem" line for each defect, from small hand-written files.
#include "mesh/import.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <sstream>

#include "common/errors.hpp"
#include "mesh/geometry.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/inspection.hpp"
#include "mesh/stl_writer.hpp"
#include "mesh/topology.hpp"
#include "mesh_test_support.hpp"

namespace {

using rbcsim::Vec3;
using namespace rbcsim::mesh;
using rbcsim::mesh::testing::octahedron;
using rbcsim::mesh::testing::TemporaryDirectory;

// An ASCII STL of the given triangles (corners written out per facet, as STL does).
std::string ascii_stl(const TriangleMesh& mesh) {
  std::ostringstream out;
  out.precision(17);
  out << "solid test\n";
  for (const auto& t : mesh.triangles) {
    out << " facet normal 0 0 0\n  outer loop\n";
    for (auto v : t) {
      const auto& p = mesh.positions_um[v];
      out << "   vertex " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    }
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid test\n";
  return out.str();
}

std::string off_file(const TriangleMesh& mesh) {
  std::ostringstream out;
  out.precision(17);
  out << "OFF\n" << mesh.vertex_count() << ' ' << mesh.triangle_count() << " 0\n";
  for (const auto& p : mesh.positions_um) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return out.str();
}

std::string obj_file(const TriangleMesh& mesh) {
  std::ostringstream out;
  out.precision(17);
  for (const auto& p : mesh.positions_um)
    out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& t : mesh.triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  return out.str();
}

std::string ply_file(const TriangleMesh& mesh) {
  std::ostringstream out;
  out.precision(17);
  out << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertex_count()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
      << mesh.triangle_count() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : mesh.positions_um) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return out.str();
}

// Torus of revolution (radii 2 and 0.7) as a quad grid split into triangles: genus 1.
TriangleMesh torus() {
  TriangleMesh mesh;
  constexpr int kAround = 12, kTube = 8;
  for (int i = 0; i < kAround; ++i) {
    for (int j = 0; j < kTube; ++j) {
      const double phi = 2.0 * std::numbers::pi * i / kAround;
      const double theta = 2.0 * std::numbers::pi * j / kTube;
      const double r = 2.0 + 0.7 * std::cos(theta);
      mesh.positions_um.emplace_back(r * std::cos(phi), r * std::sin(phi), 0.7 * std::sin(theta));
    }
  }
  auto index = [](int i, int j) { return ((i + kAround) % kAround) * kTube + (j + kTube) % kTube; };
  for (int i = 0; i < kAround; ++i) {
    for (int j = 0; j < kTube; ++j) {
      mesh.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      mesh.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return mesh;
}

// Expects import to fail with one line naming the file and containing `phrase`.
void expect_defect(const std::filesystem::path& file, const std::string& phrase) {
  SCOPED_TRACE(file.filename().string() + " -> " + phrase);
  try {
    import_mesh(file);
    ADD_FAILURE() << "imported without error";
  } catch (const rbcsim::InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(phrase), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(Import, EveryFormatGivesTheWeldedOctahedron) {
  const TemporaryDirectory dir;
  const auto reference = octahedron();
  std::ostringstream binary;
  write_stl_binary(binary, reference);
  for (const auto& file :
       {dir.write("a.stl", ascii_stl(reference)), dir.write("b.stl", binary.str()),
        dir.write("c.obj", obj_file(reference)), dir.write("d.ply", ply_file(reference)),
        dir.write("e.off", off_file(reference))}) {
    SCOPED_TRACE(file.filename().string());
    const auto imported = import_mesh(file);
    EXPECT_TRUE(imported.notices.empty());
    EXPECT_EQ(imported.mesh.vertex_count(), 6u);
    EXPECT_EQ(imported.mesh.triangle_count(), 8u);
    EXPECT_NEAR(enclosed_volume_um3(imported.mesh), 4.0 / 3.0, 1e-6);
    EXPECT_NO_THROW(MeshTopology::build(imported.mesh));
  }
}

TEST(Import, BinaryStlRoundTripKeepsTrianglesInOrderToFloatPrecision) {
  const TemporaryDirectory dir;
  const auto sphere = unit_icosphere(3);
  write_stl_binary(dir.path() / "sphere.stl", sphere);
  const auto imported = import_mesh(dir.path() / "sphere.stl").mesh;
  ASSERT_EQ(imported.triangle_count(), sphere.triangle_count());
  EXPECT_EQ(imported.vertex_count(), sphere.vertex_count());
  for (std::size_t t = 0; t < sphere.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_LT((imported.positions_um[imported.triangles[t][k]] -
                 sphere.positions_um[sphere.triangles[t][k]])
                    .norm(),
                1e-7);  // float32 rounding of coordinates of order 1
    }
  }
}

TEST(Import, WeldsCornersThatDifferByRoundOff) {
  const TemporaryDirectory dir;
  auto mesh = octahedron();
  // Unshare the corners, then disturb one copy by 1e-9 um (far below 1e-5 of the mean edge).
  TriangleMesh soup;
  for (const auto& t : mesh.triangles) {
    Triangle corners;
    for (int k = 0; k < 3; ++k) {
      corners[k] = static_cast<std::int32_t>(soup.positions_um.size());
      soup.positions_um.push_back(mesh.positions_um[t[k]]);
    }
    soup.triangles.push_back(corners);
  }
  soup.positions_um[0].x() += 1e-9;
  const auto imported = import_mesh(dir.write("soup.off", off_file(soup)));
  EXPECT_EQ(imported.mesh.vertex_count(), 6u);
  EXPECT_EQ(inspect_mesh(imported.mesh).genus, 0);
}

TEST(Import, InsideOutMeshIsFlippedWithANotice) {
  const TemporaryDirectory dir;
  auto inverted = octahedron();
  for (auto& t : inverted.triangles) std::swap(t[1], t[2]);
  const auto file = dir.write("inverted.stl", ascii_stl(inverted));
  const auto imported = import_mesh(file);
  ASSERT_EQ(imported.notices.size(), 1u);
  EXPECT_NE(imported.notices[0].find("inside out"), std::string::npos);
  EXPECT_NE(imported.notices[0].find(file.string()), std::string::npos);
  EXPECT_NEAR(enclosed_volume_um3(imported.mesh), 4.0 / 3.0, 1e-6);
}

TEST(Import, EachDefectGetsItsOwnClearLine) {
  const TemporaryDirectory dir;
  expect_defect(dir.path() / "missing.stl", "no such file");
  expect_defect(dir.write("empty.stl", ""), "empty file");
  expect_defect(dir.write("garbage.stl", std::string(300, '\x07')), "");
  expect_defect(dir.write("text.obj", "this is not a mesh\n"), "");
  expect_defect(dir.write("points.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"),
                "not a readable mesh");
  expect_defect(dir.write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n"),
                "no triangles");

  auto with_nan = octahedron();
  with_nan.positions_um[4].z() = std::numeric_limits<double>::quiet_NaN();
  std::ostringstream binary_nan;
  write_stl_binary(binary_nan, with_nan);
  expect_defect(dir.write("nan.stl", binary_nan.str()), "NaN or infinite");

  auto degenerate = octahedron();
  degenerate.positions_um.push_back(Vec3(0.5, 0.5, 0.0));  // midpoint of edge (0, 2)
  degenerate.triangles[0] = {0, 6, 4};
  degenerate.triangles.push_back({6, 2, 4});
  degenerate.triangles.push_back({0, 2, 6});  // zero area, and closes the split edge
  expect_defect(dir.write("degenerate.off", off_file(degenerate)), "degenerate (zero-area)");

  auto duplicate = octahedron();
  duplicate.triangles.push_back(duplicate.triangles[3]);
  expect_defect(dir.write("duplicate.off", off_file(duplicate)), "duplicate triangle");

  auto open = octahedron();
  open.triangles.pop_back();
  expect_defect(dir.write("open.stl", ascii_stl(open)), "open surface: 3 boundary edge");

  // A closed tetrahedron sharing the octahedron's edge (0, 2): four triangles on that edge.
  auto fin = octahedron();
  fin.positions_um.push_back(Vec3(2, 2, 2));
  fin.positions_um.push_back(Vec3(2, 2, -2));
  for (Triangle t : {Triangle{0, 6, 2}, Triangle{0, 2, 7}, Triangle{0, 7, 6}, Triangle{2, 6, 7}}) {
    fin.triangles.push_back(t);
  }
  expect_defect(dir.write("fin.off", off_file(fin)), "shared by more than two triangles");

  auto two = octahedron();
  for (int v = 0; v < 6; ++v)
    two.positions_um.push_back(octahedron().positions_um[v] + Vec3(5, 0, 0));
  for (auto t : octahedron().triangles) two.triangles.push_back({t[0] + 6, t[1] + 6, t[2] + 6});
  expect_defect(dir.write("two.obj", obj_file(two)), "2 separate connected surfaces");

  auto misoriented = octahedron();
  std::swap(misoriented.triangles[0][1], misoriented.triangles[0][2]);
  expect_defect(dir.write("misoriented.ply", ply_file(misoriented)),
                "inconsistent triangle orientation");

  expect_defect(dir.write("torus.off", off_file(torus())), "genus 1");
}

ImportOptions options(std::optional<double> area, std::optional<double> volume, bool center,
                      bool align) {
  ImportOptions result;
  result.target_area_um2 = area;
  result.target_volume_um3 = volume;
  result.center = center;
  result.align = align;
  return result;
}

TEST(Import, OptionsScaleCentreAndAlign) {
  const TemporaryDirectory dir;
  // An ellipsoid with semi-axes 1 (x), 3 (y), 2 (z), shifted: aligning puts 3 on x, 1 on z.
  auto ellipsoid = unit_icosphere(3);
  for (auto& p : ellipsoid.positions_um) p = Vec3(p.x(), 3.0 * p.y(), 2.0 * p.z()) + Vec3(4, -1, 2);
  const auto file = dir.write("ellipsoid.off", off_file(ellipsoid));

  const auto scaled = import_mesh(file, options(50.0, {}, false, false)).mesh;
  EXPECT_NEAR(surface_area_um2(scaled), 50.0, 1e-9);
  const auto by_volume = import_mesh(file, options({}, 10.0, false, false)).mesh;
  EXPECT_NEAR(enclosed_volume_um3(by_volume), 10.0, 1e-9);

  const auto aligned = import_mesh(file, options({}, {}, true, true)).mesh;
  const auto report = inspect_mesh(aligned);
  const Vec3 box = report.bounding_box_max_um - report.bounding_box_min_um;
  EXPECT_NEAR(box.x(), 6.0, 0.05);  // vertices of the inscribed mesh reach the extreme points
  EXPECT_NEAR(box.y(), 4.0, 0.05);  // to within the chord error of level 3
  EXPECT_NEAR(box.z(), 2.0, 0.05);
  EXPECT_GT(enclosed_volume_um3(aligned), 0.0);  // a rotation, not a reflection
  Vec3 centroid = Vec3::Zero();
  // The solid's centroid at the origin: for a symmetric solid the vertex mean too, up to the
  // float32 rounding assimp stores coordinates with (~1e-7 of 5 um).
  for (const auto& p : aligned.positions_um) centroid += p;
  EXPECT_LT((centroid / static_cast<double>(aligned.vertex_count())).norm(), 1e-6);

  EXPECT_THROW(import_mesh(file, options(1.0, 1.0, false, false)), rbcsim::InputError);
  EXPECT_THROW(import_mesh(file, options(-1.0, {}, false, false)), rbcsim::InputError);
}

}  // namespace
