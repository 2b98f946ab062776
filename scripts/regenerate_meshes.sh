#!/usr/bin/env bash
# Regenerates the shipped cell meshes in meshes/ (binary STL, icosphere levels 3 and 4) and
# meshes/manifest.json (each mesh's `rbcsim mesh generate --json` report) with a built rbcsim.
# Run it after changing a generator, then commit meshes/; tests/mesh/shipped_meshes_test.cpp
# fails until the shipped files match the generators again.
# Usage: scripts/regenerate_meshes.sh [path/to/rbcsim]     (default: build/cli/rbcsim)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
binary="$(realpath "${1:-$root/build/cli/rbcsim}")"
cd "$root/meshes"
entries=()
for shape in discocyte stomatocyte-II echinocyte-III; do
  for level in 3 4; do
    entries+=("$("$binary" mesh generate --shape "$shape" --subdivisions "$level" \
      -o "${shape}_n${level}.stl" --json)")
  done
done
joined="$(IFS=,; printf '%s' "${entries[*]}")"
printf '{"generator": "rbcsim mesh generate (scripts/regenerate_meshes.sh)",\n"meshes": [%s]}\n' \
  "$joined" >manifest.json.tmp
mv manifest.json.tmp manifest.json
echo "regenerated ${#entries[@]} meshes in $root/meshes"
