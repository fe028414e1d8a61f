#!/usr/bin/env bash
# Instructions per accepted step and per right-hand-side evaluation of the clearance
# dynamics, counted by callgrind inside Simulation::run only (the program's start-up —
# relocating the deal.II libraries alone is ~1e9 instructions — is not counted). Counts
# are repeatable to a fraction of a percent whatever else the machine runs, unlike wall
# time. Two crank cycles (1 s of motion) of params/nine_bar_clearance.prm with each
# embedded pair and with dopri5-stiff (the scene's method). Asserts nothing; prints the figures.
#   usage: instructions_per_step.sh WEARLINK SOURCE_DIR WORK_DIR
set -euo pipefail
wearlink="$1"; source="$2"; work="$3"
if ! command -v valgrind >/dev/null; then
  echo "valgrind is not installed: nothing measured"; exit 0
fi
mkdir -p "$work"
printf '%-12s %10s %10s %10s %16s %16s\n' method steps rejected rhs_evals instr/step instr/rhs
for method in dopri5 dopri5-stiff dop853; do
  out="$work/$method"
  valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.$method" \
    --toggle-collect='wearlink::mbs::Simulation::run*' \
    "$wearlink" run "$source/params/nine_bar_clearance.prm" --output "$out" --overwrite --quiet \
    --set "Simulation/End time=1" --set "Output/Time series=false" --set "Integrator/Method=$method" >/dev/null 2>&1
  ir=$(callgrind_annotate "$work/callgrind.$method" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
  /usr/bin/python3 -c "
import json
s = json.load(open('$out/summary.json'))
ir = float('$ir')
print('%-12s %10d %10d %10d %16.0f %16.0f' % ('$method', s['steps'], s['rejected_steps'], s['rhs_evaluations'],
      ir / s['steps'], ir / s['rhs_evaluations']))"
done
