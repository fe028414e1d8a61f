#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""What a run costs from Python against the program: the same scene, the same outputs,
pair by pair in fresh processes (the order alternating between the pairs); prints each pair's
wall times, the medians and the ratio Python / program with its range (doc/performance.md,
"Python"). Not a pass/fail on the time: it fails only if a run fails.

    python_overhead.py --binary build/wearlink --python-path build/python --source . [--pairs 3]
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time


def timed(command, env):
    start = time.monotonic()
    subprocess.run(command, env=env, check=True, stdout=subprocess.DEVNULL)
    return time.monotonic() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", required=True)
    ap.add_argument("--python-path", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--scene", default="params/nine_bar_wear.prm")
    ap.add_argument("--pairs", type=int, default=3)
    opts = ap.parse_args()
    scene = os.path.join(opts.source, opts.scene)
    env = dict(os.environ, PYTHONPATH=os.path.abspath(opts.python_path))
    program, python = [], []
    with tempfile.TemporaryDirectory() as work:
        for k in range(opts.pairs):
            cli = [opts.binary, "run", scene, "--output", f"{work}/cli{k}", "--quiet"]
            code = f"import wearlink; wearlink.run({scene!r}, output={work + '/py' + str(k)!r})"
            py = [sys.executable, "-c", code]
            if k % 2 == 0:  # the order alternates, so that a drift of the machine cancels
                program.append(timed(cli, env))
                python.append(timed(py, env))
            else:
                python.append(timed(py, env))
                program.append(timed(cli, env))
            print(f"pair {k + 1}: program {program[-1]:.2f} s, Python {python[-1]:.2f} s, "
                  f"ratio {python[-1] / program[-1]:.4f}", flush=True)
    ratios = [p / c for p, c in zip(python, program)]
    print(f"{opts.scene}: program {statistics.median(program):.2f} s, Python {statistics.median(python):.2f} s "
          f"(medians of {opts.pairs} pairs); Python / program {statistics.median(ratios):.4f} "
          f"({min(ratios):.4f} … {max(ratios):.4f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
