#!/usr/bin/env python3
# Usage: python3 tests/benchmarks/build/build_time.py WORK_DIR [NAME="-DOPTION=VALUE ..."]...
#
# Wall-clock time of a clean build in each of the given configurations, one after the
# other in the same run, so that the ratios compare builds on the same machine under the
# same load: first the `wearlink` target alone (what `./bootstrap.sh run` builds), then
# everything else (what `./bootstrap.sh test` adds). Each configuration is configured
# afresh in WORK_DIR/NAME (Release, the Makefile generator that bootstrap.sh uses) and
# built with as many jobs as the machine has cores. Without configurations it compares
# the build options' defaults with all three remedies switched off:
#   before  -DWEARLINK_UNITY=OFF -DWEARLINK_DEBUG_INFO=ON -DWEARLINK_PCH=OFF
#   default (no options)
# Prints one row per configuration and each one's ratio to the first.
import os, shutil, subprocess, sys, time

source = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
if len(sys.argv) < 2:
    sys.exit('usage: build_time.py WORK_DIR [NAME="-DOPTION=VALUE ..."]...')
work = os.path.abspath(sys.argv[1])
os.makedirs(work, exist_ok=True)
configs = [a.split("=", 1) for a in sys.argv[2:]] or [
    ["before", "-DWEARLINK_UNITY=OFF -DWEARLINK_DEBUG_INFO=ON -DWEARLINK_PCH=OFF"],
    ["default", ""],
]
jobs = str(os.cpu_count() or 2)


def timed(cmd, cwd):
    start = time.monotonic()
    subprocess.run(cmd, cwd=cwd, check=True, stdout=subprocess.DEVNULL)
    return time.monotonic() - start


rows = []
for name, options in configs:
    build = os.path.join(work, name)
    shutil.rmtree(build, ignore_errors=True)
    configure = timed(["cmake", "-S", source, "-B", build, "-DCMAKE_BUILD_TYPE=Release"] + options.split(), work)
    program = timed(["cmake", "--build", build, "-j", jobs, "--target", "wearlink"], work)
    rest = timed(["cmake", "--build", build, "-j", jobs], work)
    rows.append((name, options, configure, program, program + rest))
    print(f"{name}: configure {configure:.0f} s, wearlink {program:.0f} s, everything {program + rest:.0f} s", flush=True)

print(f"\n{'configuration':14s} {'wearlink [s]':>13s} {'ratio':>6s} {'everything [s]':>15s} {'ratio':>6s}  options")
for name, options, _, program, everything in rows:
    print(f"{name:14s} {program:13.0f} {program / rows[0][3]:6.2f} {everything:15.0f} {everything / rows[0][4]:6.2f}  {options}")
