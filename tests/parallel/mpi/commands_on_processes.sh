#!/bin/sh
# The experiment commands under mpiexec against one process: every file of the run directory is
# the same byte for byte, except the wall times (result.json, config.json's start time, a shear
# rate's point.json, the wall_time_s column of a CSV table); the result is printed once; each run
# exits 0. Snapshots in both formats: the capillary and the tube suspension write HDF5 + XDMF
# (output.format=hdf5, each process its part; the same bytes on 1 to 4 processes), which
# check_hdf5_output.py reads with h5py against the VTK of the same run; the sheared suspension
# writes VTK gathered onto rank 0. The physiological preset (membrane viscosity, a viscous
# cytoplasm) in a shear, a tube suspension and a stretch. A capillary checkpointed on 4 processes
# resumes on 2 and on 1 to the same files, with either preset. The capillary with curved walls
# (Bouzidi) on 2. The commands with no lattice to cut (the quasi-static stretch, calibrate) stop
# with exit 2, one line, before any output.
# Usage: commands_on_processes.sh MPIEXEC RBCSIM [FORMAT]
# FORMAT: hdf5 (default) or vtk, for a build without HDF5: the capillary and the tube suspension
# then write VTK too, and the HDF5 checks are left out.
set -u
mpiexec=$1
rbcsim=$2
format=${3:-hdf5}
check_hdf5="$(cd "$(dirname "$0")" && pwd)/check_hdf5_output.py"
# Debian's python3 with python3-h5py (scripts/test.sh installs it), ahead of any other on PATH.
python=python3
[ -x /usr/bin/python3 ] && python=/usr/bin/python3
failed=0
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

without_wall_time() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "wall_time_s") skip = i }
           { line = ""; for (i = 1; i <= NF; i++) if (i != skip) line = line $i ","; print line }' "$1"
}

# same_as_one NAME "PROCESS COUNTS" COMMAND...: the command on one process, then on each count.
same_as_one() {
  name=$1
  counts=$2
  shift 2
  "$rbcsim" "$@" --threads 1 --json --output "$name.1" >"$name.1.json" 2>"$name.1.err" ||
    { echo "$name on one process failed:"; cat "$name.1.err"; failed=1; return; }
  for processes in $counts; do
    out="$name.$processes"
    if ! "$mpiexec" -n "$processes" --oversubscribe "$rbcsim" "$@" --threads 1 --json \
        --output "$out" >"$out.json" 2>"$out.err"; then
      echo "$name on $processes processes failed:"; cat "$out.err"; failed=1; continue
    fi
    # Printed once, by rank 0: as many lines as one process prints.
    [ "$(wc -l <"$out.json")" -eq "$(wc -l <"$name.1.json")" ] ||
      { echo "$name on $processes processes: printed $(wc -l <"$out.json") lines"; failed=1; }
    files=$(cd "$name.1" && find . -type f ! -name result.json ! -name config.json ! -name point.json | sort)
    [ -n "$files" ] || { echo "$name: no files to compare"; failed=1; }
    for file in $files; do
      case $file in
        *.csv) [ "$(without_wall_time "$name.1/$file")" = "$(without_wall_time "$out/$file")" ] ;;
        *) cmp -s "$name.1/$file" "$out/$file" ;;
      esac || { echo "$name on $processes processes: $file differs from one process's"; failed=1; }
    done
  done
}

coarse_cell="--set mesh.subdivisions=3 --set mesh.method=parametric --set lattice.spacing_um=1"
# shellcheck disable=SC2086
same_as_one shear "2 3 4" shear $coarse_cell --set shear.max_reynolds_number=0.4 \
  --set shear.width_diameters=1.6 --set shear.gap_diameters=2 --max-strain 1 --rates 0,500 \
  --set lattice.block_planes=2
same_as_one stretch "2" stretch --set mesh.subdivisions=2 --set mesh.method=parametric \
  --set lattice.spacing_um=1 --set stretch.fluid.kinematic_viscosity_m2_per_s=3.7e-7 \
  --set stretch.fluid.steady_relative_rate_per_s=20 --mode fluid --forces 10 \
  --set lattice.block_planes=2
# Warm-started forces: every process relaxes its own copy of the cell to the same equilibrium.
same_as_one stretch_warm_start "2" stretch --set mesh.subdivisions=2 --set mesh.method=parametric \
  --set lattice.spacing_um=1 --set stretch.fluid.kinematic_viscosity_m2_per_s=3.7e-7 \
  --set stretch.fluid.steady_relative_rate_per_s=20 --mode fluid --forces 10 \
  --set stretch.fluid.warm_start=true --set lattice.block_planes=2
# The capillary's cell of tests/cli_capillary (162 vertices, stiffened), inlet, outlet and walls.
capillary="capillary --set mesh.subdivisions=2 --set mesh.method=parametric
  --set lattice.spacing_um=1 --set membrane.k_link_kBT=112 --set membrane.k_area_kBT=80
  --set membrane.k_bend_kBT=800 --set membrane.k_volume_kBT=320
  --set membrane.k_area_difference_kBT=4800 --set membrane.k_total_curvature_kBT=1600
  --set membrane.vertex_force_cap_pN=2000 --set capillary.throat_diameter_um=9
  --set capillary.inlet_velocity_m_per_s=0.014 --set capillary.pass_margin_um=2
  --set output.membrane_interval_s=2e-4 --set output.fluid_interval_s=1e-3
  --set lattice.block_planes=2 --set output.format=$format"
# shellcheck disable=SC2086
same_as_one capillary "2 3 4" $capillary
# Curved walls (Bouzidi's interpolated links, which read the node behind, on another process's
# plane at a slab's edge).
# shellcheck disable=SC2086
same_as_one capillary_bouzidi "2" $capillary --set lattice.wall_rule=bouzidi
if [ "$format" = hdf5 ]; then
  # shellcheck disable=SC2086
  "$rbcsim" $capillary --set output.format=vtk --threads 1 --output capillary.vtk >/dev/null 2>&1
  "$python" "$check_hdf5" capillary.2 capillary.vtk || failed=1
fi
# Checkpoints across process counts: the capillary written on 4 processes every 43 steps (the
# last at step 301 of about 330, odd: the AA kernel's swapped layout), resumed on 2 and on 1; both
# rewrite the straight run's time series and snapshots byte for byte. 330 steps leave the cell
# upstream of the narrow section: a "failed" run, exit 1, each time. Both presets: the
# physiological one's friction warm start and viscosity classes must come back from the
# checkpoint on any process count.
# output.format=auto: HDF5 on 4 processes, and a resume on one goes on in HDF5 (the series it
# finds), not in one process's VTK.
# resumes_alike NAME ARGUMENTS...
resumes_alike() {
  name=$1
  shift
  # shellcheck disable=SC2068
  "$mpiexec" -n 4 --oversubscribe "$rbcsim" $@ --checkpoint-every 43 --output "$name.written" \
    >/dev/null 2>"$name.written.err"
  code=$?
  if [ $code -ne 1 ] || [ ! -f "$name.written/checkpoint.bin" ]; then
    echo "$name with checkpoints on 4 processes: exit $code"; cat "$name.written.err"; failed=1
    return
  fi
  for processes in 2 1; do
    resumed="$name.resumed$processes"
    cp -r "$name.written" "$resumed"
    rm "$resumed/result.json" "$resumed/capillary_timeseries.csv"
    launcher=""
    [ "$processes" -gt 1 ] && launcher="$mpiexec -n $processes --oversubscribe"
    # shellcheck disable=SC2068,SC2086
    $launcher "$rbcsim" $@ --resume "$resumed" >/dev/null 2>resumed.err
    code=$?
    [ $code -eq 1 ] || { echo "$name resumed on $processes: exit $code"; cat resumed.err; failed=1; }
    # auto wrote HDF5 on 4 processes when built with it, VTK otherwise.
    series="cells.xdmf fluid.xdmf $(cd "$name.written" && find h5 -type f 2>/dev/null)"
    [ -f "$name.written/cells.xdmf" ] ||
      series="cell0.pvd fluid.pvd $(cd "$name.written" && find vtk -type f)"
    for file in capillary_timeseries.csv $series; do
      cmp -s "$name.written/$file" "$resumed/$file" ||
        { echo "$name written on 4, resumed on $processes: $file differs"; failed=1; }
    done
  done
}
checkpointed="$capillary --set output.format=auto --set capillary.max_time_s=5e-5 --threads 1"
# shellcheck disable=SC2086
resumes_alike checkpointed $checkpointed
# shellcheck disable=SC2086
resumes_alike physiological_checkpointed $checkpointed --preset physiological

suspension="--set mesh.subdivisions=2 --set mesh.method=parametric --set lattice.spacing_um=1
  --set suspension.contact_range_um=1.75 --set lattice.block_planes=2"
# shellcheck disable=SC2086
same_as_one sheared_suspension "2" shear $suspension --hematocrit 0.1 --rates 200 \
  --set suspension.strain=1 --set output.format=vtk
tube="capillary --geometry tube --diameter-um 10 --length-um 12 $suspension
  --set suspension.duration_s=2e-4 --set suspension.sample_interval_s=2e-5
  --set output.membrane_interval_s=1e-4 --set output.fluid_interval_s=1e-4 --hematocrit 0.2
  --mix discocyte=0.5,stomatocyte-II=0.5"
# shellcheck disable=SC2086
same_as_one tube_suspension "2" $tube --set output.format=$format
if [ "$format" = hdf5 ]; then
  # shellcheck disable=SC2086
  "$rbcsim" $tube --set output.format=vtk --threads 1 --output tube_suspension.vtk >/dev/null 2>&1
  "$python" "$check_hdf5" tube_suspension.2 tube_suspension.vtk || failed=1
fi

# The physiological preset: membrane viscosity (each cell's implicit friction step over fluid nodes
# on several processes) and a viscous cytoplasm (per-node viscosity classes): one cell sheared, a
# two-cell suspension in the tube (its cells packed at 0.99 of their size and grown in the flow:
# ten reference stages and a dilation every step; on dx 1 um a larger growth pushes a cell packed
# 0.5 um from the staircase wall into it), one cell stretched.
# shellcheck disable=SC2086
same_as_one physiological_shear "2" shear $coarse_cell --set shear.max_reynolds_number=0.4 \
  --set shear.width_diameters=1.6 --set shear.gap_diameters=2 --max-strain 1 --rates 500 \
  --set lattice.block_planes=2 --preset physiological
# shellcheck disable=SC2086
same_as_one physiological_tube "2" $tube --set output.format=vtk --preset physiological \
  --set suspension.packing_scale=0.99 --set suspension.growth_time_s=1e-4
# shellcheck disable=SC2086
same_as_one physiological_stretch "2" stretch --set mesh.subdivisions=2 --set mesh.method=parametric \
  --set lattice.spacing_um=1 --set stretch.fluid.kinematic_viscosity_m2_per_s=3.7e-7 \
  --set stretch.fluid.steady_relative_rate_per_s=20 --mode fluid --forces 10 \
  --set lattice.block_planes=2 --preset physiological

# What has no lattice to cut: exit 2, one line naming the setting, no run directory.
refused() {
  "$mpiexec" -n 2 --oversubscribe "$rbcsim" "$@" --output refused >/dev/null 2>refused.err
  code=$?
  lines=$(grep -c "rbcsim: error: " refused.err)
  if [ $code -ne 2 ] || [ "$lines" -ne 1 ] || [ -e refused ]; then
    echo "$* on 2 processes: exit $code, $lines error line(s), run directory left: $(ls refused 2>&1)"
    cat refused.err; failed=1
  fi
  rm -rf refused
}
refused stretch --set mesh.subdivisions=2 --mode quasi-static
refused calibrate

[ $failed -eq 0 ] && echo "shear, stretch --mode fluid, capillary (also with curved walls) and" \
  "both suspensions (also with the physiological preset): the same files as one process, HDF5" \
  "snapshots as VTK's; the commands without a lattice refused"
exit $failed
