#!/usr/bin/env bash
# The README's main command: set up (install missing packages, build), then run the main job on the
# embedded defaults and leave its results in out/ (or the directory given as the first argument).
# Today the main job builds and inspects the three cell morphologies at the paper's resolution,
# prints the resolved configuration, and stretches the discocyte as the paper's Fig. 8 does (with
# and without the area-difference and total-curvature terms), then reports on both stretch runs;
# the other experiments (shear, capillary) join it as they land.
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
output_dir="${1:-$repo_root/out}"

"$repo_root/scripts/setup.sh" "$repo_root/build"
rbcsim="$repo_root/build/cli/rbcsim"
mkdir -p "$output_dir"

"$rbcsim" config show > "$output_dir/config.json"
for morphology in discocyte stomatocyte-II echinocyte-III; do
  "$rbcsim" mesh generate --morphology "$morphology" -o "$output_dir/$morphology.stl" --json \
    > "$output_dir/$morphology.mesh.json"
  "$rbcsim" mesh import "$output_dir/$morphology.stl" -o "$output_dir/$morphology.vtp" >/dev/null
  echo "== $morphology"
  "$rbcsim" mesh info "$output_dir/$morphology.stl"
done
echo "== stretch (quasi-static, the 13 forces of Mills et al. 2004)"
"$rbcsim" stretch --output "$output_dir/stretch-discocyte"
"$rbcsim" stretch --set membrane.forces=link,bend,area,volume \
  --output "$output_dir/stretch-discocyte-four-terms"
"$rbcsim" report "$output_dir/stretch-discocyte" "$output_dir/stretch-discocyte-four-terms" \
  -o "$output_dir/report"
echo "main: results in $output_dir" >&2
