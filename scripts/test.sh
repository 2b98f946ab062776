#!/usr/bin/env bash
# The README's test command (and CI's, via .ci/run): set up, build with warnings as errors, run the
# whole test suite; then build the same tests with AddressSanitizer + UBSan and run them again.
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jobs="$(nproc)"
# clang with its sanitizer and libFuzzer runtimes and its OpenMP runtime, for the sanitizer and
# fuzz stages; python3-h5py, which reads the HDF5 snapshots back (tests/parallel/mpi).
export RBCSIM_EXTRA_PACKAGES="clang-14 libclang-rt-14-dev libomp-14-dev python3-h5py"

# Each stage's start with the seconds since this script's (CI's budget is 25 minutes).
stage() { echo "== $1 (at ${SECONDS} s)" >&2; }

stage "release build (warnings are errors)"
"$repo_root/scripts/setup.sh" "$repo_root/build" -DRBCSIM_WARNINGS_AS_ERRORS=ON
stage "release tests"
ctest --test-dir "$repo_root/build" --output-on-failure --parallel "$jobs" -LE validate

stage "AddressSanitizer + UndefinedBehaviorSanitizer build (clang)"
# -O1 -g1: what the sanitizers recommend, and it halves the compile time of -O2 -g on 2 cores.
# clang rather than GCC: it builds this in two thirds of GCC's time, and with the release build
# above every file compiles warning-free under both compilers (clang found two tests that passed
# only under GCC: one relied on its order of evaluating a call's arguments, one on its reading of
# a one-element braced list as a json array).
# RBCSIM_FUZZ: the two fuzz targets of the last stage are built here too, the parsers' sources
# alone instrumented for coverage (a build of their own cost two minutes of CI).
"$repo_root/scripts/setup.sh" "$repo_root/build-sanitize" -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DRBCSIM_WARNINGS_AS_ERRORS=ON -DRBCSIM_SANITIZE=ON -DRBCSIM_FUZZ=ON
# Long physics runs are left to the Release stage: under the sanitizers they repeat the code of
# shorter tests thousands of times at 5-26x the Release cost (a third of the stage's CPU time in
# December 2026), and the shorter tests run that code under ASan+UBSan too:
#   the implicit membrane friction (ShearRotation.CentralMembraneViscosity...): ImplicitMembrane-
#     Friction.* and the viscous checkpoint resume;
#   the cytoplasm classes (CytoplasmRelaxation.*): CytoplasmIndicator.* and the contrast resume;
#   the shape minimiser (EnergyShape.TheDiscocyteIsEvansAndFungs..., EnergyShape.SeededTrials...,
#     CliMesh.InfoOfAGeneratedMesh..., CliMesh.GenerateWritesStl...): EnergyShape.Minimisation-
#     HoldsAreaAndVolumeAndConverges, EnergyShape.AMinimisationOutOfIterations... and
#     CliMesh.GenerateTellsOfUnresolvedSpiculesOnStderr;
#   a suspension's coupled run (CliSuspension.CellsOvertakingEachOther...): CliSuspension.Writes-
#     TheRunDirectoryOfAMixedSuspension and the CellContact.* runs;
#   the packing giving up (SuspensionPacking.RefusesATargetItCannotReach): SuspensionPacking.Packs-
#     MixedCellsClearOfEachOtherAndTheWall;
#   the capillary's time-scale compression and single precision (CapillaryCase.CompressedRun...,
#     CapillaryCase.SinglePrecisionPopulations...): CliCapillary.* and SinglePrecision.*;
#   the quasi-static and fluid stretch curves (StretchCase.LowResolutionCurve,
#     FluidStretch.SteadyShapeIsTheEquilibrium...): CliStretch.*, StretchFit.* and
#     FluidStretch.AForceNotSteadyInTimeIsReported;
#   the icosphere STL round trip (ShippedShapes.TheIcosphereStlReaderRoundTrips...): the STL
#     reader's fuzzing below and Import.*;
#   the level-4 parametric echinocyte, 13x slower under the sanitizers (ShapeAnalysis.CountsThe-
#     DrawnEchinocytes..., CellFromConfig.EchinocyteSpiculeCount..., CellShapes.Unresolved-
#     Spicules...): Echinocyte.Level4ResolvesEverySpicule... for the generator, CliMesh.Generate-
#     TellsOfUnresolvedSpiculesOnStderr for the spicule count, the cup's measure and the notice,
#     CellFromConfig.AGeneratedShapeTheMeshDoesNotResolve... for the notice of a run;
#   the coupled contact of two capsules (CellContact.MoreCellsThanThreads...,
#     CellContact.PushedCellsStopAtTheRange...): CellContact.OneAndTwoThreadsGiveTheSameRun and
#     CellContact.SurfaceLawInTheCoupledStep, the same pushed pair;
#   the finite-difference check of the shape energies' gradients (SurfaceEnergies.EveryGradient-
#     Matches...): the other SurfaceEnergies.* and EnergyShape.MinimisationHolds..., which runs
#     the gradients;
#   the membrane kernels' equivalence at level 3 (AllShapes/KernelEquivalence.*/*3_*): the same
#     kernels at levels 2 and 4;
#   the two-layer TRT channel (TwoLayerChannel.Trt...): TwoLayerChannel.BgkPoiseuille... and
#     ViscosityClasses.*; the sheared capsule's rotation (ShearRotation.StiffSpherical...):
#     ShearRun.*; FIRE on Euler's buckling (RelaxationMethods.FireFindsEulers...):
#     RelaxationMethods.FireConvergesThroughTheTotalCurvatureKinks; the stretch fit's recovery
#     (StretchFit.RecoversTheLinkStiffness...): CliCalibrate.StretchFitWritesParameters..., the
#     same fit through the command; the sheared stresslet with membrane viscosity
#     (ShearedSuspension.StressletCountsTheMembraneViscositysFriction):
#     ShearedSuspension.StressletOfOneCellEqualsTheWallStress, the same run without it;
#   the experiment commands under mpiexec against one process (CliMpi.CommandsWriteTheSameFiles-
#     AsOneProcess, 196 s here, a seventh of CI): DistributedFluidMpi.* on 4 processes (the
#     coupled step with 20 cells, its checkpoints and HDF5 snapshots) and the binary under mpiexec
#     in CliMpi.BenchRanksOnTwoProcesses and CliMpi.ACommandNotYetDistributedStopsWithExit2;
#   the same on 1, 2 and 3 processes (DistributedFluidMpi.SameStateAndCheckpointsOn1Processes,
#     ...On2Processes and ...On3Processes, 18, 26 and 32 s): the same exchange code on 4 processes,
#     whose checkpoints are resumed on 2 (the tests' "resume on half"); the bench starting mpiexec
#     itself (CliMpi.BenchPaperCasesOnTwoProcesses, 40 s on both cores): BenchPaperCases.* and the
#     bench under mpiexec above;
#   the physiological shear on both fluid kernels (CliShear.ThePhysiologicalMembraneRunsWhichever-
#     Kernel..., 121 s, a sixth of the stage): the coupled friction in Checkpoint.ResumedRunWith-
#     MembraneViscosity... and ImplicitMembraneFriction.*, the reference kernel in the lattice tests;
#   the membrane terms' properties on the level-4 meshes (AllTerms/*/...4_*, 128 s): the same
#     terms, shapes and properties on the level-3 meshes (the finite-difference gradient checks
#     alone 73 s at level 4);
#   the paper's throat with a stiffer local-area term (CapillaryCase.AStifferLocalArea..., 12 s):
#     CapillaryCase.CellIsCarriedThroughTheThroat..., the same case with the paper's terms;
#   the continuation along Delta a0 (EnergyShape.TheContinuationPathWalksDeltaA0ToTheShapes, 28 s):
#     the path's stages in EnergyShape.TheContinuationPathIsTheStiffPathWhenThereIsNothingToWalk,
#     the minimiser each stage runs in EnergyShape.MinimisationHoldsAreaAndVolumeAndConverges;
#   the resume of a sheared suspension's sweep (CliShear.ResumeOfASuspensionSweep..., 22 s): the
#     sweep's resume in ShearResume.* and a suspension's checkpoints in CliSuspension.Resume-
#     RewritesTheStraightRunsResults; the sheared suspension in CliShear.ASuspensionBetweenWalls...
stage "sanitizer tests"
sanitizer_skip='^(ShearRotation\.CentralMembraneViscosity|EnergyShape\.(TheDiscocyteIsEvansAndFungs|SeededTrials)|CytoplasmRelaxation\.|CliSuspension\.CellsOvertaking|SuspensionPacking\.RefusesATarget|CapillaryCase\.(CompressedRun|SinglePrecision)|StretchCase\.LowResolutionCurve|FluidStretch\.SteadyShape|CliMesh\.(InfoOfAGeneratedMesh|GenerateWritesStl)|ShippedShapes\.TheIcosphereStlReaderRoundTrips|ShapeAnalysis\.CountsTheDrawnEchinocytes|CellFromConfig\.EchinocyteSpiculeCount|CellShapes\.UnresolvedSpicules|CellContact\.(MoreCellsThanThreads|PushedCellsStop)|SurfaceEnergies\.EveryGradient|AllShapes/KernelEquivalence\.EveryTermSubsetAgreesWithTheReference/[A-Za-z_]+3_|TwoLayerChannel\.Trt|ShearRotation\.StiffSpherical|RelaxationMethods\.FireFindsEulers|StretchFit\.RecoversTheLinkStiffness|ShearedSuspension\.StressletCounts|CliMpi\.(CommandsWriteTheSameFiles|BenchPaperCasesOnTwoProcesses)|DistributedFluidMpi\.SameStateAndCheckpointsOn(1|2|3)Processes|AllTerms/[A-Za-z]+\.[A-Za-z]+/[A-Za-z_]+4_|CapillaryCase\.AStifferLocalArea|CliShear\.ThePhysiologicalMembraneRuns|EnergyShape\.TheContinuationPathWalks|CliShear\.ResumeOfASuspensionSweep)'
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$repo_root/build-sanitize" --output-on-failure --parallel "$jobs" -LE validate \
  -E "$sanitizer_skip"

stage "fuzzing the STL reader and the config parser (libFuzzer + ASan + UBSan, bounded)"
# The fuzz targets come from the sanitizer build. A crash fails this script and leaves the input
# in build-sanitize/fuzz/ (it then becomes a regression test in tests/reliability).
fuzz_seconds="${RBCSIM_FUZZ_SECONDS:-30}"
fuzz_dir="$repo_root/build-sanitize/fuzz"
mkdir -p "$fuzz_dir"
stl_corpus="$(mktemp -d)"
config_corpus="$(mktemp -d)"
trap 'rm -rf "$stl_corpus" "$config_corpus"' EXIT
"$repo_root/build/cli/rbcsim" mesh generate --subdivisions 1 -o "$stl_corpus/icosphere.stl" >/dev/null
# Prints the fuzzer's last lines (runs, coverage); all of its output if it found something.
run_fuzzer() {
  local log="$fuzz_dir/$1.log"
  if "$repo_root/build-sanitize/tests/fuzz/$1" -max_total_time="$fuzz_seconds" -rss_limit_mb=4096 \
    -artifact_prefix="$fuzz_dir/" "${@:2}" >"$log" 2>&1; then
    tail -n 2 "$log"
  else
    cat "$log"
    return 1
  fi
}
# The two fuzzers side by side: each is one process on one core.
run_fuzzer fuzz_stl_reader -max_len=8192 "$stl_corpus" "$repo_root/tests/fuzz/seeds/stl" &
stl_fuzzer=$!
config_status=0
run_fuzzer fuzz_config_parser "$config_corpus" "$repo_root/share/config" || config_status=$?
stl_status=0
wait "$stl_fuzzer" || stl_status=$?
stage "done"
((stl_status == 0 && config_status == 0))
