#!/usr/bin/env bash
# The README's test command (and CI's, via .ci/run): set up, build with warnings as errors, run the
# whole test suite; then build the same tests with AddressSanitizer + UBSan and run them again.
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jobs="$(nproc)"

echo "== release build (warnings are errors) and tests" >&2
"$repo_root/scripts/setup.sh" "$repo_root/build" -DRBCSIM_WARNINGS_AS_ERRORS=ON
ctest --test-dir "$repo_root/build" --output-on-failure --parallel "$jobs" -LE validate

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests" >&2
# -O1 -g1: what the sanitizers recommend, and it halves the compile time of -O2 -g on 2 cores.
"$repo_root/scripts/setup.sh" "$repo_root/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DRBCSIM_WARNINGS_AS_ERRORS=ON -DRBCSIM_SANITIZE=ON
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$repo_root/build-sanitize" --output-on-failure --parallel "$jobs" -LE validate
