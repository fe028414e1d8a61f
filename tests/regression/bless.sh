#!/usr/bin/env bash
# Re-bless reference-output regressions after an intended change of physics: runs each
# case with the build's wearlink and writes its figures' values into tests/regression/
# <case>.ref (tolerances and justifications are kept). Review the change with git diff.
#   tests/regression/bless.sh BUILD_DIR            all cases
#   tests/regression/bless.sh BUILD_DIR CASE...    some (e.g. nine_bar_wear pin_bushing)
# The runs go to BUILD_DIR/tests/regression/bless/<case>.
set -euo pipefail
if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [CASE...]" >&2
  exit 2
fi
here="$(cd "$(dirname "$0")" && pwd)"
source_dir="$(cd "$here/../.." && pwd)"
build_dir="$(cd "$1" && pwd)"
shift
wearlink="$build_dir/wearlink"
if [ ! -x "$wearlink" ]; then
  echo "$wearlink is not an executable: build first (cmake --build $build_dir)" >&2
  exit 2
fi
if [ $# -eq 0 ]; then
  set -- $(cd "$here" && ls *.ref | sed 's/\.ref$//')
fi
for c in "$@"; do
  python3 "$here/check_reference.py" --wearlink "$wearlink" --source-dir "$source_dir" --case "$here/$c.ref" \
          --work-dir "$build_dir/tests/regression/bless/$c" --bless
done
echo "blessed: $*; review with: git -C $source_dir diff tests/regression"
