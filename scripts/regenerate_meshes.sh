#!/usr/bin/env bash
# Regenerates the shipped cell meshes in meshes/ (binary STL, icosphere levels 3 and 4) and
# meshes/manifest.json (each mesh's `rbcsim mesh generate --json` report, with the settings it was
# minimised with) with a built rbcsim: the three morphologies of the paper, minimised from
# membrane mechanics (mesh.method energy, the defaults). The binary embeds what it finds here and
# takes a shipped mesh instead of minimising again when a run's settings are the same; the
# validate target regenerates them and compares (tests/shapes/shipped_shapes_test.cpp).
# Run it after changing the energy model, a default or the minimiser, then commit meshes/ (and
# rebuild, so the binary embeds the new files). Takes about 10 minutes on 2 cores.
# Usage: scripts/regenerate_meshes.sh [path/to/rbcsim]     (default: build/cli/rbcsim)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
binary="$(realpath "${1:-$root/build/cli/rbcsim}")"
cd "$root/meshes"
jobs=()
for shape in discocyte stomatocyte-II echinocyte-III; do
  for level in 3 4; do
    # --fresh: minimise even where a mesh of these settings is already embedded.
    OMP_NUM_THREADS=1 "$binary" mesh generate --method energy --fresh --quiet --shape "$shape" \
      --subdivisions "$level" -o "${shape}_n${level}.stl" --json >"${shape}_n${level}.json.tmp" &
    jobs+=($!)
    if (( ${#jobs[@]} >= $(nproc) )); then wait "${jobs[0]}"; jobs=("${jobs[@]:1}"); fi
  done
done
for job in "${jobs[@]}"; do wait "$job"; done
entries=()
for shape in discocyte stomatocyte-II echinocyte-III; do
  for level in 3 4; do
    entries+=("$(cat "${shape}_n${level}.json.tmp")")
    rm "${shape}_n${level}.json.tmp"
  done
done
joined="$(IFS=,; printf '%s' "${entries[*]}")"
printf '{"generator": "rbcsim mesh generate --method energy (scripts/regenerate_meshes.sh)",\n"meshes": [%s]}\n' \
  "$joined" >manifest.json.tmp
mv manifest.json.tmp manifest.json
echo "regenerated ${#entries[@]} meshes in $root/meshes"
