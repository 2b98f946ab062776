#!/usr/bin/env bash
# The README's main command: set up (install missing packages, build), then run the main job on the
# embedded defaults — the paper in small — and leave its results in out/ (or the directory given as
# the first argument):
#   1. the three cell morphologies at the paper's resolution (STL, VTP, statistics) and the resolved
#      configuration;
#   2. calibrate: the patch tests' moduli beside the paper's (Table 2 parameters);
#   3. stretch: the quasi-static optical-tweezers curve of the discocyte against Mills et al. (2004),
#      with all six forces and without F_ad/F_tc (the paper's Fig. 8); then calibrate's stretch fit
#      (k_link fitted to Mills' curve, the contact patches held rigid as by glued beads: ~5 min)
#      and the curve with the fitted parameters;
#   4. shear: a short sweep (0, 1000, 2000 1/s) of each morphology with and without F_ad/F_tc, on
#      the coarse setting of docs/validation.md (642 vertices, dx 0.75 um, 10 strains: not steady);
#   5. capillary, 642-vertex cells with Table 2's moduli (k_link, k_area x2; docs/physics.md) on the
#      paper's dx 0.5 um: the discocyte through the validation tube (6.75 um throat, Re 0.0643)
#      with and without F_ad/F_tc (the paper's Fig. 13), and the three morphologies through the
#      three-morphology tube (6.8 um throat, Re 0.04);
#   6. report: out/report/report.html, summary.md, summary.json over every run above.
# How far each setting is from the paper's is in docs/validation.md ("The main job's settings").
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
output_dir="${1:-$repo_root/out}"

"$repo_root/scripts/setup.sh" "$repo_root/build"
rbcsim="$repo_root/build/cli/rbcsim"
mkdir -p "$output_dir"
threads="$(nproc)"
started_s=$SECONDS
# Each experiment's run directory is replaced, so a second main job does not mix old and new runs.
fresh_run() { rm -rf "${output_dir:?}/$1"; echo "$output_dir/$1"; }
stage() { echo "== $1 ($((SECONDS - started_s)) s)" >&2; }

stage "meshes and configuration"
"$rbcsim" config show > "$output_dir/config.json"
for morphology in discocyte stomatocyte-II echinocyte-III; do
  "$rbcsim" mesh generate --morphology "$morphology" -o "$output_dir/$morphology.stl" --json \
    > "$output_dir/$morphology.mesh.json"
  "$rbcsim" mesh import "$output_dir/$morphology.stl" -o "$output_dir/$morphology.vtp" >/dev/null
  echo "-- $morphology"
  "$rbcsim" mesh info "$output_dir/$morphology.stl"
done

stage "calibrate (hexagonal and two-triangle patch tests, Table 2)"
"$rbcsim" calibrate --output "$(fresh_run calibrate)"

stage "stretch (quasi-static, the 13 forces of Mills et al. 2004)"
"$rbcsim" stretch --output "$(fresh_run stretch-discocyte)"
"$rbcsim" stretch --set membrane.forces=link,bend,area,volume \
  --output "$(fresh_run stretch-discocyte-four-terms)"

stage "calibrate the stretch (k_link fitted to Mills et al. 2004, glued beads) and its curve"
"$rbcsim" calibrate --fits stretch --set stretch.contact.rigid=true \
  --output "$(fresh_run calibrate-stretch)"
"$rbcsim" stretch --config "$output_dir/calibrate-stretch/parameters.json" \
  --output "$(fresh_run stretch-discocyte-fitted)"

# Exit code 1 is a run that failed in its physics (a force law's limit, say): its result.json
# and the report say where; it is a finding of the main job, not a reason to stop it. Bad input
# (2), an interrupt (130) or anything else stops the job.
physics_may_fail() { "$@" || [[ $? -eq 1 ]]; }

stage "shear (three morphologies, 0/1000/2000 1/s, coarse setting)"
# 642-vertex cells with Table 2's moduli, as in the capillary below: each morphology's k_link and
# k_area scaled by the ratio of the paper's 2562-vertex cell's edge to theirs (x2; docs/physics.md).
table2_moduli=(--set membrane.network_calibrated_triangle_count=5120)
shear_setting=(--set mesh.subdivisions=3 --set lattice.spacing_um=0.75 "${table2_moduli[@]}"
               --rates 0,1000,2000 --max-strain 10 --threads "$threads")
for morphology in discocyte echinocyte-III stomatocyte-II; do
  physics_may_fail "$rbcsim" shear "${shear_setting[@]}" --morphology "$morphology" \
    --output "$(fresh_run "shear-$morphology")"
  physics_may_fail "$rbcsim" shear "${shear_setting[@]}" --morphology "$morphology" \
    --set membrane.forces=link,bend,area,volume --output "$(fresh_run "shear-$morphology-four-terms")"
done

stage "capillary (the validation tube: discocyte with and without F_ad/F_tc; three morphologies)"
# 642-vertex cells on the paper's dx = 0.5 um with Table 2's moduli: their edges are twice as long
# as the 2562-vertex cell's, and both the link and the local-area modulus go as k / L0 (the
# hexagonal patch test of `rbcsim calibrate`), so k_link and k_area are doubled (table2_moduli).
# Edges about one lattice spacing long are what lets the cell through: the 2562-vertex cell on this
# lattice (edges
# dx / 2) fails at the area limit before the throat (docs/validation.md, capillary). The vertex cap
# is 4 x 50 pN: a vertex here carries four paper vertices' share. The paper's validation tube (§3.3,
# Fig. 13: 31.2 um, 6.75 um throat, Re 0.0643) with the discocyte, with and without F_ad/F_tc; then
# the three morphologies through the three-morphology tube (§3.4: 42 um, 6.8 um throat, Re 0.04).
# One thread per run, the five runs side by side.
cell_setting=(--set mesh.subdivisions=3 "${table2_moduli[@]}"
              --set membrane.vertex_force_cap_pN=200 --set output.fluid_interval_s=0 --threads 1)
capillary_pids=()
run_capillary() {  # run name, then rbcsim capillary's options
  "$rbcsim" capillary "${cell_setting[@]}" "${@:2}" --output "$(fresh_run "$1")" \
    > "$output_dir/$1.txt" &
  capillary_pids+=($!)
}
run_capillary capillary-validation-discocyte
run_capillary capillary-validation-discocyte-four-terms --set membrane.forces=link,bend,area,volume
for morphology in discocyte echinocyte-III stomatocyte-II; do
  run_capillary "capillary-$morphology" --geometry paper-morphology --morphology "$morphology"
done
for pid in "${capillary_pids[@]}"; do physics_may_fail wait "$pid"; done
cat "$output_dir"/capillary-*.txt

stage "report"
"$rbcsim" report "$output_dir"/{calibrate,calibrate-stretch} \
  "$output_dir"/{stretch-discocyte,stretch-discocyte-four-terms,stretch-discocyte-fitted} \
  "$output_dir"/shear-{discocyte,echinocyte-III,stomatocyte-II}{,-four-terms} \
  "$output_dir"/capillary-validation-discocyte{,-four-terms} \
  "$output_dir"/capillary-{discocyte,echinocyte-III,stomatocyte-II} -o "$output_dir/report"
stage "main: results in $output_dir, report in $output_dir/report/report.html"
