#!/usr/bin/env bash
# Makes the figures of the documentation again, from the shipped scenes, with the
# commands the pages document, and copies them into doc/figures/.
#
#   doc/figures/make_figures.sh             the quick figures (about 5 minutes on 2 cores)
#   doc/figures/make_figures.sh all         every figure (about an hour on 2 cores)
#   doc/figures/make_figures.sh NAME ...    the named figures (the names below)
#   doc/figures/make_figures.sh --list      the names, what each runs and how long
#
# Run it from anywhere after `./bootstrap.sh run` (it uses build/wearlink and, for the
# ensembles and studies, `mpirun -np 2`). The runs go into output/figures/ (each into a
# folder of its own, replaced if it exists); only the PNGs are copied into doc/figures/.
# The times are wall times on a 2-core machine with the second core free; the clearance
# dynamics are chaotic, so a figure made again differs in its details, not in what it
# shows. The FE table cache is a fresh folder in output/figures/, so the FE times are
# those of a first run.
set -euo pipefail
cd "$(dirname "$0")/../.."
wearlink=build/wearlink
out=output/figures
dest=doc/figures

# name | minutes | group | what it runs (the page that shows the figure)
figures="
getting_started          0.1  quick  params/getting_started.prm (doc/getting_started.md)
profile_B_bore           0.3  quick  params/nine_bar_wear.prm, 50,000 rev (README, doc/tutorials/profiles.md)
force_approach           1    quick  compare-contact params/nine_bar_wear.prm (README, doc/tutorials/fe_contact.md)
pressure_worn            1.5  quick  nine_bar_wear, then compare-contact --worn (doc/tutorials/fe_contact.md)
fe_depth_B               1    quick  params/nine_bar_wear_fe.prm (README, doc/tutorials/wear_prediction.md)
calibration              0.5  quick  calibrate the rig on 2 ranks (doc/tutorials/calibration.md)
calibrated_sensitivity   1    long   the calibrated rig, 16 members on 2 ranks (doc/tutorials/calibration.md)
life                     3    long   life of the nine-bar, 4 members on 2 ranks (README, doc/tutorials/life_and_ensembles.md)
life_uncertain_cdf       2.5  long   life with uncertain coefficients, 8 members on 2 ranks (doc/tutorials/calibration.md)
accuracy_default         3    long   study accuracy params/nine_bar_wear.prm on 2 ranks (doc/tutorials/accuracy_study.md)
convergence_hertz_strip  5    long   study convergence params/nine_bar_wear.prm on 2 ranks (doc/tutorials/profiles.md)
convergence_winkler      15   long   the same with winkler (doc/tutorials/profiles.md)
accuracy_fe              21   long   study accuracy of the FE scene's shortcuts (doc/tutorials/accuracy_study.md)
python_clearance_study   4.5  long   the Python study of doc/python.md: 4 clearances, a wear run and a life each
"

# A fresh folder for one command's output.
fresh() { rm -rf "$out/$1"; echo "$out/$1"; }
# Copy a run's PNG into doc/figures under the name the pages use.
keep() { cp "$1" "$dest/$2"; echo "make_figures.sh: wrote $dest/$2"; }

make_getting_started() {
  local d; d=$(fresh getting_started)
  "$wearlink" run params/getting_started.prm --output "$d"
  keep "$d/orbit_B.png" getting_started_orbit_B.png
  keep "$d/contact_forces.png" getting_started_contact_forces.png
  keep "$d/accelerations.png" getting_started_accelerations.png
}
nine_bar_wear_run() {
  [ -f "$out/nine_bar_wear/summary.json" ] && return 0
  local d; d=$(fresh nine_bar_wear)
  "$wearlink" run params/nine_bar_wear.prm --output "$d"
}
make_profile_B_bore() {
  rm -rf "$out/nine_bar_wear"
  nine_bar_wear_run
  keep "$out/nine_bar_wear/profile_B_bore.png" nine_bar_wear_profile_B_bore.png
}
make_force_approach() {
  local d; d=$(fresh contact)
  "$wearlink" compare-contact params/nine_bar_wear.prm --output "$d"
  keep "$d/force_approach.png" compare_contact_force_approach_nine_bar_wear.png
}
make_pressure_worn() {
  nine_bar_wear_run
  local d; d=$(fresh contact_wear)
  "$wearlink" compare-contact params/nine_bar_wear.prm --worn "$out/nine_bar_wear" --output "$d"
  keep "$d/pressure.png" compare_contact_pressure_nine_bar_wear.png
}
make_fe_depth_B() {
  local d; d=$(fresh nine_bar_wear_fe)
  "$wearlink" run params/nine_bar_wear_fe.prm --output "$d"
  keep "$d/wear_depth_B.png" nine_bar_wear_fe_depth_B.png
}
make_calibration() {
  local d; d=$(fresh calibration)
  mpirun -np 2 "$wearlink" calibrate params/nine_bar_experiment.prm \
      --measurements params/nine_bar_experiment_measurements.prm --ensemble 4 --output "$d"
  keep "$d/calibration.png" experiment_calibration.png
}
make_calibrated_sensitivity() {
  local d; d=$(fresh experiment_calibrated)
  mpirun -np 2 "$wearlink" run params/nine_bar_experiment_calibrated.prm --ensemble 16 --output "$d"
  keep "$d/sensitivity.png" experiment_calibrated_sensitivity.png
}
make_life() {
  local d; d=$(fresh nine_bar_life_ensemble)
  mpirun -np 2 "$wearlink" life params/nine_bar_life.prm --ensemble 4 --output "$d"
  keep "$d/life.png" nine_bar_life.png
}
make_life_uncertain_cdf() {
  local d; d=$(fresh nine_bar_life_uncertain)
  mpirun -np 2 "$wearlink" life params/nine_bar_life.prm --ensemble 8 --output "$d" \
      --set "Uncertainty/Inputs=Joint A/Clearance/archard/Bushing wear coefficient: lognormal(4.6e-14, 0.3); Joint B/Clearance/archard/Bushing wear coefficient: lognormal(4.6e-14, 0.3)"
  keep "$d/life_cdf.png" nine_bar_life_uncertain_cdf.png
}
make_accuracy_default() {
  local d; d=$(fresh nine_bar_wear_accuracy)
  mpirun -np 2 "$wearlink" study accuracy params/nine_bar_wear.prm --output "$d"
  keep "$d/accuracy_pareto.png" accuracy_nine_bar_wear_default.png
}
make_convergence_hertz_strip() {
  local d; d=$(fresh convergence_hertz_strip)
  mpirun -np 2 "$wearlink" study convergence params/nine_bar_wear.prm --output "$d"
  keep "$d/convergence_B_bushing.png" convergence_hertz_strip_B_bushing.png
}
make_convergence_winkler() {
  local d; d=$(fresh convergence_winkler)
  mpirun -np 2 "$wearlink" study convergence params/nine_bar_wear.prm --output "$d" \
      --set "Joint A/Clearance/Pressure model=winkler" --set "Joint B/Clearance/Pressure model=winkler"
  keep "$d/convergence_A_bushing.png" convergence_winkler_A_bushing.png
}
make_accuracy_fe() {
  local d; d=$(fresh fe_shortcuts)
  cat > "$out/fe_shortcuts.prm" <<'END'
subsection Accuracy study
  set Knobs = load-sampling, remesh-depth, fe-law-table, baumgarte
end
END
  "$wearlink" study accuracy params/nine_bar_wear_fe.prm --study "$out/fe_shortcuts.prm" --output "$d" \
      --set "Wear/Number of iterations=5" --set "Wear/Cycles per iteration=2" --set "Wear/Extrapolation factor=5000"
  keep "$d/accuracy_pareto.png" accuracy_nine_bar_wear_fe.png
}

make_python_clearance_study() {
  local d; d=$(fresh python_clearance_study)
  ln -s "$PWD/params" "$d/params"
  ln -s "$PWD/meshes" "$d/meshes"
  # The page's own block, as the doc-test runs it (shortened there, whole here).
  awk '/^```python$/ {inside = 1; next} inside && /^```$/ {exit} inside' doc/python.md > "$d/study.py"
  (cd "$d" && PYTHONPATH="$OLDPWD/build/python" MPLBACKEND=Agg /usr/bin/python3 study.py)
  keep "$d/clearance_study.png" python_clearance_study.png
}

names_of() { echo "$figures" | awk -v g="$1" 'NF && (g == "all" || $3 == g) {print $1}'; }

case "${1:-quick}" in
  --list) echo "$figures" | awk 'NF {printf "%-24s %5s min  %-5s  ", $1, $2, $3; for (i = 4; i <= NF; i++) printf "%s ", $i; print ""}'; exit 0 ;;
  quick|long|all) selected=$(names_of "${1:-quick}") ;;
  *) selected="$*" ;;
esac
for name in $selected; do
  echo "$figures" | awk -v n="$name" 'NF && $1 == n {found = 1} END {exit !found}' ||
    { echo "make_figures.sh: no figure '$name' (see --list)" >&2; exit 2; }
done
[ -x "$wearlink" ] || { echo "make_figures.sh: $wearlink is missing; run ./bootstrap.sh run first" >&2; exit 2; }
mkdir -p "$out"
export WEARLINK_CACHE_DIR="$PWD/$out/cache"
# Open MPI refuses to run as root unless told that this is intended.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for name in $selected; do
  echo "== make_figures.sh: $name"
  start=$SECONDS
  "make_$name"
  echo "== make_figures.sh: $name took $((SECONDS - start)) s"
done
