#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a result:
#   ./bootstrap.sh run    install what is missing, build (Release), run the default scene
#   ./bootstrap.sh test   install what is missing, build (Release), run the test suite
#   ./bootstrap.sh build  install and build only
# Extra arguments after `test` are passed to ctest (e.g. -L unit).
set -euo pipefail
cd "$(dirname "$0")"
mode="${1:-run}"
shift || true

packages="cmake make g++ libdeal.ii-dev libeigen3-dev libmetis-dev gmsh libgmsh-dev
          googletest libgtest-dev libsuitesparse-dev gnuplot-nox openmpi-bin python3-matplotlib
          nlohmann-json3-dev zlib1g-dev libfftw3-dev clang-format libopenblas0-pthread
          python3-dev pybind11-dev python3-numpy python3-pytest"
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "== installing Debian packages:$missing"
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends $missing
fi

jobs="$(nproc 2>/dev/null || echo 2)"
echo "== configuring and building (Release) in build/"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release ${WEARLINK_CMAKE_ARGS:-}
# A run needs only the program and the Python module; the tests are built by `test` (and `build`).
target=""
[ "$mode" = run ] && target="--target wearlink wearlink_python"
cmake --build build -j "$jobs" $target

# Open MPI refuses to run as root unless told that this is intended (CI runs as root).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

case "$mode" in
  run)
    echo "== running the default scene (params/nine_bar_clearance.prm) into output/nine_bar_clearance"
    ./build/wearlink run params/nine_bar_clearance.prm --output output/nine_bar_clearance --overwrite
    ;;
  test)
    echo "== running the test suite"
    cd build && ctest --output-on-failure -j "$jobs" "$@"
    ;;
  build) ;;
  *) echo "usage: $0 run|test|build" >&2; exit 2 ;;
esac
