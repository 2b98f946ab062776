// `rbcsim mesh ...` end to end: the built binary (RBCSIM_BINARY) run in a shell, its exit code,
// stdout and stderr, and the files it writes (or, on bad input, does not write).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct CommandResult {
  int exit_code;
  std::string out;
  std::string err;
};

class CliMesh : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device entropy;
    dir_ = fs::temp_directory_path() / ("rbcsim_cli_mesh_" + std::to_string(entropy()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CommandResult run(const std::string& arguments) const {
    const auto out = dir_ / "stdout.txt";
    const auto err = dir_ / "stderr.txt";
    const std::string command = "cd '" + dir_.string() + "' && '" RBCSIM_BINARY "' " + arguments +
                                " >'" + out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
  }
  static std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  fs::path dir_;
};

TEST_F(CliMesh, GenerateWritesStlAndReportsJson) {
  const auto result = run("mesh generate --shape discocyte --subdivisions 2 -o cell.stl --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["shape"], "discocyte");
  EXPECT_EQ(json["report"]["counts"]["vertices"], 162);
  EXPECT_EQ(json["report"]["topology"]["genus"], 0);
  // 80-byte header, count, 50 bytes per triangle.
  EXPECT_EQ(fs::file_size(dir_ / "cell.stl"), 84u + 50u * 320u);
}

// A shape the level does not resolve (mesh::resolution_notice) is still written, with a notice
// on stderr that leaves stdout's JSON clean; a resolved one prints nothing there.
TEST_F(CliMesh, GenerateTellsOfUnresolvedSpiculesOnStderr) {
  const auto coarse =
      run("mesh generate --method parametric --shape echinocyte-III --subdivisions 2 --json");
  ASSERT_EQ(coarse.exit_code, 0) << coarse.err;
  EXPECT_EQ(nlohmann::json::parse(coarse.out)["report"]["counts"]["vertices"], 162);
  EXPECT_EQ(coarse.err.rfind("rbcsim: notice: echinocyte-III at mesh.subdivisions = 2 has a ", 0),
            0u)
      << coarse.err;
  const auto smooth =
      run("mesh generate --method parametric --shape discocyte --subdivisions 2 --json");
  ASSERT_EQ(smooth.exit_code, 0) << smooth.err;
  EXPECT_EQ(smooth.err, "");
}

TEST_F(CliMesh, InfoOfAGeneratedMeshPrintsATable) {
  ASSERT_EQ(run("mesh generate --shape stomatocyte-II --subdivisions 2 -o cup.vtp").exit_code, 0);
  ASSERT_EQ(run("mesh generate --shape stomatocyte-II --subdivisions 2 -o cup.stl").exit_code, 0);
  EXPECT_TRUE(fs::exists(dir_ / "cup.vtp"));
  const auto result = run("mesh info cup.stl");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("genus                           0"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("area [um^2]"), std::string::npos);
}

TEST_F(CliMesh, ImportRepairsAnInsideOutMeshAndRescales) {
  std::ofstream(dir_ / "flipped.off") << "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                                         "3 0 4 2\n3 2 4 1\n3 1 4 3\n3 3 4 0\n"
                                         "3 2 5 0\n3 1 5 2\n3 3 5 1\n3 0 5 3\n";
  const auto result =
      run("mesh import flipped.off -o clean.stl --scale-to-volume 10 --center --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("rbcsim: notice: flipped.off: the surface was inside out"),
            std::string::npos)
      << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_NEAR(json["report"]["size"]["volume_um3"].get<double>(), 10.0, 1e-9);
  EXPECT_TRUE(fs::exists(dir_ / "clean.stl"));
}

TEST_F(CliMesh, BadInputExitsTwoWithOneLineAndNoOutputFile) {
  // Two triangles sharing one edge: the other four edges are boundary edges.
  std::ofstream(dir_ / "open.off") << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n";
  const auto result = run("mesh import open.off -o out.stl");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err,
            "rbcsim: error: open.off: open surface: 4 boundary edge(s) with a single "
            "triangle (holes)\n");
  EXPECT_FALSE(fs::exists(dir_ / "out.stl"));

  const auto unknown = run("mesh generate --shape spherocyte -o x.stl");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.err.rfind("rbcsim: error: --shape: \"spherocyte\" is not a shape", 0), 0u)
      << unknown.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.stl"));

  const auto format = run("mesh generate --subdivisions 1 -o cell.obj");
  EXPECT_EQ(format.exit_code, 2);
  EXPECT_NE(format.err.find("cell.obj: unknown output format"), std::string::npos);

  EXPECT_EQ(run("mesh info missing.stl").exit_code, 2);
}

}  // namespace
