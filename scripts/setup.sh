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
required_packages=(cmake make g++ libcli11-dev libeigen3-dev nlohmann-json3-dev libassimp-dev
                   libgtest-dev libexpat1-dev)
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

cmake -S "$repo_root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build_dir" --parallel "$(nproc)"
