// The measurement `rbcsim bench` compares itself with: another code's figures on the same cases,
// with where and how they were measured. The shipped one is share/reference/hemocell_bench.json
// (HemoCell side by side on the project machine); `--reference FILE` gives one of the user's own.
// A ratio is printed only where the reference has a figure for that case and thread count, and
// always beside the reference's machine, so that no constant measured elsewhere passes for a
// comparison on this machine.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace rbcsim::cli {

struct BenchReference {
  std::string label;       // the code and version, e.g. "HemoCell d916987 + Palabos 2.3.0"
  std::string machine;     // where it was measured
  std::string provenance;  // how (optional)
  // Figures per thread count, for the bench's own cases: ms per coupled step with the 642-vertex
  // cell on the 40x40x20 lattice, and fluid-only MLUPS on 40x40x20.
  std::map<int, double> coupled_ms_per_step_642_vertices;
  std::map<int, double> fluid_mlups_40x40x20;

  std::optional<double> coupled_ms(int threads) const;
  std::optional<double> fluid_mlups(int threads) const;
};

// Reads a reference from JSON text: keys label, machine (strings, required), provenance (string),
// coupled_ms_per_step_642_vertices and fluid_mlups_40x40x20 (objects from a thread count, "1",
// "2", ..., to a positive number). Anything else, or a wrong type, throws InputError(source,
// "key: problem").
BenchReference parse_bench_reference(std::string_view text, std::string_view source);

// The shipped reference (share/reference/hemocell_bench.json, embedded), or the file's.
BenchReference load_bench_reference(const std::optional<std::filesystem::path>& file);

}  // namespace rbcsim::cli
