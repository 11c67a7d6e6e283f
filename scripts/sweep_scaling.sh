#!/usr/bin/env bash
# Sweep scaling (docs/performance.md "Sweeps"): cases per second of one sweep on 1 and
# 2 threads and on 1 and 2 MPI ranks, and the sweep's own overhead per case.
#   scripts/sweep_scaling.sh [CAMOPT_BINARY] [WORK_DIR]
# Work sweep: 40 cycloid_ltca cases (logarithmic crowning coefficient × torque, 16 crank angles,
# 24×24 grid). Overhead sweep: 2000 cases of a three-element transmission_rigidity chain, whose
# own computation is a few microseconds, so that its time per case is the cost of the sweep
# (building the case's JSON, the registry's parse and checks, the kind's result files in memory,
# the result.json parse, the checkpoint line) plus that small computation.
# Each configuration runs once: wall clock of the whole command (mpirun's start-up included) and
# CPU time (user + system of every thread and rank): on a machine shared with other work the wall
# clock shows the share of the cores we got, the CPU time what the sweep cost.
set -euo pipefail
bin=$(realpath "${1:-build/camopt}")
work=$(realpath -m "${2:-$(mktemp -d)}")
src=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work"
cat > "$work/work.json" <<JSON
{ "sweep": "scaling", "base": "$src/studies/examples/cycloid_ltca_nnm_lcm.json",
  "set": { "/analysis": { "crank_angles_per_mesh_period": 16, "grid": [24, 24] }, "/geometry_files": false },
  "vary": [ { "path": "/crowning/coefficient_mm", "range": [0.001, 0.02], "count": 8 },
            { "path": "/load/torque_Nm", "range": [100, 600], "count": 5 } ],
  "outputs": ["/max_contact_stress_MPa"] }
JSON
cat > "$work/overhead.json" <<JSON
{ "sweep": "overhead", "base": "$src/studies/examples/rigidity_stepped_shaft.json",
  "vary": [ { "path": "/chain/0/length_mm", "range": [20, 60], "count": 2000 } ],
  "outputs": ["/rigidity_Nm_per_rad"] }
JSON
mpirun=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpirun+=(--allow-run-as-root)
run() {  # label cases command...
  local label=$1 n=$2; shift 2
  rm -rf "$work/out"
  /usr/bin/time -f "%e %U %S" -o "$work/time.txt" "$@" > /dev/null
  # wall and CPU (user + system, every thread and rank) seconds
  awk -v l="$label" -v n="$n" '{ printf "%-24s %5d cases %7.2f s wall %8.2f cases/s %8.3f ms/case wall %8.3f ms/case CPU\n", l, n, $1, n / $1, 1000 * $1 / n, 1000 * ($2 + $3) / n }' "$work/time.txt"
}
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores"
run "work, 1 thread"           40 "$bin" sweep "$work/work.json" --quiet --jobs 1 --out "$work/out"
run "work, 2 threads"          40 "$bin" sweep "$work/work.json" --quiet --jobs 2 --out "$work/out"
run "work, mpirun -n 1"        40 "${mpirun[@]}" -n 1 "$bin" sweep "$work/work.json" --quiet --jobs 1 --out "$work/out"
run "work, mpirun -n 2"        40 "${mpirun[@]}" -n 2 "$bin" sweep "$work/work.json" --quiet --jobs 1 --out "$work/out"
run "overhead, 1 thread"     2000 "$bin" sweep "$work/overhead.json" --quiet --jobs 1 --out "$work/out"
run "overhead, 2 threads"    2000 "$bin" sweep "$work/overhead.json" --quiet --jobs 2 --out "$work/out"
run "overhead, mpirun -n 2"  2000 "${mpirun[@]}" -n 2 "$bin" sweep "$work/overhead.json" --quiet --jobs 1 --out "$work/out"
