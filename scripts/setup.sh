#!/usr/bin/env bash
# Installs what rbcsim needs to build on Debian, if missing, and builds it.
#   scripts/setup.sh [BUILD_DIR] [extra cmake arguments...]
# RBCSIM_EXTRA_PACKAGES (space-separated) adds Debian packages a caller needs beyond the build's,
# e.g. scripts/test.sh's clang for the fuzz targets.
# Idempotent: installed packages are not touched, an existing build directory is reused.
# As root it runs apt-get itself; otherwise it prints the exact command to run and exits 2.
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${1:-$repo_root/build}"
shift || true

# libexpat1-dev: the report and coupling tests read their HTML and VTK output back with a strict
# XML parser.
# ninja-build: a new build directory is generated for Ninja, which compiles a target's sources
# while the libraries it links are still being built (make waits for them: on 2 cores one core
# idled through the chain of libraries and the rbcsim binary).
# openmpi-bin libopenmpi-dev: runs across processes (mpirun; RBCSIM_MPI below).
# libhdf5-openmpi-dev: parallel HDF5 snapshots with XDMF indexes (RBCSIM_HDF5 below).
required_packages=(cmake ninja-build g++ libcli11-dev libeigen3-dev nlohmann-json3-dev
                   libassimp-dev libgtest-dev libexpat1-dev openmpi-bin libopenmpi-dev
                   libhdf5-openmpi-dev)
read -r -a extra_packages <<<"${RBCSIM_EXTRA_PACKAGES:-}"
required_packages+=("${extra_packages[@]}")

missing_packages=()
for package in "${required_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing_packages+=("$package")
done

if ((${#missing_packages[@]})); then
  install_command="apt-get update && apt-get install -y --no-install-recommends ${missing_packages[*]}"
  if [[ $(id -u) -eq 0 ]]; then
    echo "setup: installing ${missing_packages[*]}" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing_packages[@]}" >/dev/null
  else
    echo "setup: missing packages; run as root:  $install_command" >&2
    exit 2
  fi
fi

# An existing build directory keeps the generator it was made with.
generator=()
[[ -f "$build_dir/CMakeCache.txt" ]] || generator=(-G Ninja)
cmake -S "$repo_root" -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DRBCSIM_MPI=ON -DRBCSIM_HDF5=ON "$@" >/dev/null
cmake --build "$build_dir" --parallel "$(nproc)"
