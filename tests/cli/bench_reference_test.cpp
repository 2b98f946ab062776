// The reference `rbcsim bench` divides by: the shipped one carries only what was measured side by
// side (HemoCell's one-core coupled step, 5.2 ms on the project machine), and a user's file is
// read strictly, each problem named by its key.
#include <gtest/gtest.h>

#include <string>

#include "bench_reference.hpp"
#include "common/errors.hpp"

namespace {

using rbcsim::cli::load_bench_reference;
using rbcsim::cli::parse_bench_reference;

std::string refusal(const std::string& text) {
  try {
    parse_bench_reference(text, "mine.json");
  } catch (const rbcsim::InputError& error) {
    return error.what();
  }
  return "accepted";
}

TEST(BenchReference, TheShippedOneHasOnlyTheSideBySideFigure) {
  const auto reference = load_bench_reference(std::nullopt);
  EXPECT_EQ(reference.label, "HemoCell d916987 + Palabos 2.3.0");
  EXPECT_NE(reference.machine.find("EPYC"), std::string::npos);
  ASSERT_TRUE(reference.coupled_ms(1));
  EXPECT_DOUBLE_EQ(*reference.coupled_ms(1), 5.2);  // the fastest of 5.2-6.5 ms (issue record)
  EXPECT_FALSE(reference.coupled_ms(2));
  EXPECT_FALSE(reference.fluid_mlups(1));
}

TEST(BenchReference, AUsersFileGivesFiguresPerThreadCount) {
  const auto reference = parse_bench_reference(
      R"({"label": "mine", "machine": "laptop", "coupled_ms_per_step_642_vertices": {"1": 4.0,
          "4": 1.5}, "fluid_mlups_40x40x20": {"2": 30}})",
      "mine.json");
  EXPECT_EQ(reference.provenance, "");
  EXPECT_DOUBLE_EQ(*reference.coupled_ms(4), 1.5);
  EXPECT_DOUBLE_EQ(*reference.fluid_mlups(2), 30.0);
  EXPECT_FALSE(reference.fluid_mlups(1));
}

TEST(BenchReference, ProblemsAreNamedByFileAndKey) {
  EXPECT_EQ(refusal(R"({"machine": "m"})"), "mine.json: label: missing");
  EXPECT_EQ(refusal(R"({"label": "x", "machine": "m", "speed": 1})"),
            "mine.json: speed: unknown key (label, machine, provenance, "
            "coupled_ms_per_step_642_vertices, fluid_mlups_40x40x20)");
  EXPECT_EQ(refusal(R"({"label": "x", "machine": "m", "fluid_mlups_40x40x20": {"0": 3}})"),
            "mine.json: fluid_mlups_40x40x20.0: a thread count must be a whole number >= 1");
  EXPECT_EQ(refusal(R"({"label": "x", "machine": "m",
                        "coupled_ms_per_step_642_vertices": {"1": -2}})"),
            "mine.json: coupled_ms_per_step_642_vertices.1: expected a positive number");
  EXPECT_EQ(refusal("[1]"), "mine.json: expected a JSON object");
}

}  // namespace
