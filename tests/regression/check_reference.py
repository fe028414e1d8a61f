#!/usr/bin/env python3
"""Reference-output regression of one case (doc/testing.md, "Reference-output regressions").

Runs wearlink as the case file says and compares selected figures of its output with the
stored reference values, each within its own tolerance.

  check_reference.py --wearlink build/wearlink --source-dir . --case tests/regression/four_bar.ref
                     --work-dir /tmp/four_bar [--bless | --spread N [--perturb "E | B | S"]]
                     [--set S/E=V ...]

  (default)   run, print the table (figure, reference, got, relative difference, tolerance,
              result) and exit 1 if any figure is outside its tolerance;
  --bless     run and write the figures' values into the case file (tolerances and their
              justifications kept): after an intended change of physics;
  --spread N  N equivalent runs (run k sets the case's `perturb` entry to base + k·step,
              k = 0 … N-1, 0 being the case itself) and per figure the mean, the standard
              deviation and how many of them the tolerance is: how a chaos-floor tolerance
              is measured; --perturb replaces the case's `perturb` line;
  --set       more overrides for this invocation only (e.g. to see that a change of physics
              fails the check); never in a registered test.

The work folder is removed and made again (the run's output goes to WORK/out, the FE table
cache to WORK/cache, so that every run computes its tables); nothing is written into the
source tree except the case file by --bless.

A case file (<case>.ref) holds lines
  command <wearlink command>                       run | life | contact | compare-contact | …
  scene   <path relative to the source folder>
  arg     <one more command-line argument>          (repeatable; @SOURCE_DIR@ is replaced)
  set     <Section/Entry=value>                     (repeatable: overrides that shorten the scene)
  perturb <Section/Entry> | <base value> | <step>   (the equivalent runs of --spread)
  figure  <locator> | <reference value> | <tolerance> | <justification>
and comments (#). A locator is [FILE:]PATH; FILE defaults to summary.json. In a .json file
PATH is a JSON pointer (/clearance_joints/A/impacts, /solvers/condensed/load_cases/3/…); in
a .csv file it is COLUMN=VALUE[,COLUMN=VALUE…]:COLUMN (the first row matching the selection,
the value of the last column). A tolerance is `rel X` (|got − ref| ≤ X |ref|), `abs X`
(|got − ref| ≤ X) or `exact` (the same text: strings, counts).
"""
import argparse
import csv
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import time


class CaseError(Exception):
    """A case file or a work folder that cannot be used."""


class Figure:
    def __init__(self, line, locator, reference, tolerance, why):
        self.line, self.locator, self.reference, self.tolerance, self.why = line, locator, reference, tolerance, why


def read_case(path, source_dir):
    case = {"command": "", "scene": "", "args": [], "sets": [], "perturb": "", "figures": []}
    with open(path, encoding="utf-8") as f:
        for raw in f:
            line = raw.rstrip("\n")
            stripped = line.strip()
            if not stripped or stripped.startswith("#"):
                continue
            key, _, rest = stripped.partition(" ")
            rest = rest.strip()
            if key in ("command", "scene", "perturb"):
                case[key] = rest
            elif key == "arg":
                case["args"].append(rest.replace("@SOURCE_DIR@", source_dir))
            elif key == "set":
                case["sets"].append(rest)
            elif key == "figure":
                parts = [p.strip() for p in rest.split("|")]
                if len(parts) != 4:
                    raise CaseError(f"{path}: 'figure LOCATOR | VALUE | TOLERANCE | JUSTIFICATION' expected, got '{line}'")
                locator, reference, tolerance, why = parts
                kind = tolerance.split()
                if not (tolerance == "exact" or (len(kind) == 2 and kind[0] in ("rel", "abs") and is_number(kind[1]))):
                    raise CaseError(f"{path}: tolerance 'rel X', 'abs X' or 'exact' expected, got '{tolerance}'")
                if not why:
                    raise CaseError(f"{path}: the figure {locator} has no justification of its tolerance")
                case["figures"].append(Figure(line, locator, reference, tolerance, why))
            else:
                raise CaseError(f"{path}: unknown keyword '{key}' (command, scene, arg, set, perturb, figure)")
    if not case["command"] or not case["scene"] or not case["figures"]:
        raise CaseError(f"{path}: needs a command, a scene and at least one figure")
    return case


def is_number(text):
    try:
        return math.isfinite(float(text))
    except ValueError:
        return False


def run_case(opts, case, directory, name, extra_sets, quiet=False):
    """Runs the case into DIRECTORY/out; raises CaseError with the log's tail on failure."""
    cmd = [opts.wearlink] + case["command"].split() + [os.path.join(opts.source_dir, case["scene"])]
    cmd += case["args"] + ["--output", os.path.join(directory, "out")]
    for s in case["sets"] + opts.set + extra_sets:
        cmd += ["--set", s]
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    env = dict(os.environ, WEARLINK_CACHE_DIR=os.path.join(directory, "cache"))
    if not quiet:
        print(f"{name}: " + " ".join(f'"{c}"' if " " in c else c for c in cmd))
    start = time.monotonic()
    result = subprocess.run(cmd, cwd=directory, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(directory, "wearlink.log"), "w", encoding="utf-8") as log:
        log.write(result.stdout)
    if result.returncode != 0:
        raise CaseError(f"{name}: wearlink exited with {result.returncode} (log: {directory}/wearlink.log):\n"
                        + result.stdout[-4000:])
    print(f"{name}: {' '.join(extra_sets)} ran in {time.monotonic() - start:.0f} s (log: {directory}/wearlink.log)")


def as_text(value):
    """A JSON or CSV value as the case file writes it (None: missing or not a plain value)."""
    if value is None or isinstance(value, (dict, list)):
        return None
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def read_figure(directory, locator):
    file, path = "summary.json", locator
    head, sep, tail = locator.partition(":")
    if sep and (head.endswith(".json") or head.endswith(".csv")):
        file, path = head, tail
    full = os.path.join(directory, "out", file)
    if not os.path.exists(full):
        return None
    if file.endswith(".json"):
        if not path.startswith("/"):
            raise CaseError(f"a JSON figure is [FILE.json:]/member/member/…, got '{locator}'")
        with open(full, encoding="utf-8") as f:
            node = json.load(f)
        for member in path[1:].split("/"):
            if isinstance(node, list) and member.isdigit() and int(member) < len(node):
                node = node[int(member)]
            elif isinstance(node, dict) and member in node:
                node = node[member]
            else:
                return None
        return as_text(node)
    selection, sep, column = path.rpartition(":")
    if not sep:
        raise CaseError(f"a CSV figure is FILE.csv:COLUMN=VALUE[,…]:COLUMN, got '{locator}'")
    conditions = [c.split("=", 1) for c in selection.split(",")]
    with open(full, newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            if all(row.get(k) == v for k, v in conditions):
                return row.get(column)
    return None


def compare(figure, got):
    """(result, relative difference as text)."""
    if figure.tolerance == "exact":
        return ("OK" if got == figure.reference else "FAIL"), "-"
    if not (is_number(got) and is_number(figure.reference)):
        return "FAIL (not a number)", "-"
    ref, value = float(figure.reference), float(got)
    kind, bound = figure.tolerance.split()
    difference = abs(value - ref)
    relative = f"{difference / abs(ref):.2g}" if ref != 0 else "-"
    allowed = float(bound) * abs(ref) if kind == "rel" else float(bound)
    return ("OK" if difference <= allowed else "FAIL"), relative


def check(opts, case, name):
    run_case(opts, case, opts.work_dir, name, [])
    rows, failed = [], []
    for f in case["figures"]:
        got = read_figure(opts.work_dir, f.locator)
        result, relative = ("FAIL (missing)", "-") if got is None else compare(f, got)
        rows.append((f.locator, f.reference, got or "(missing)", relative, f.tolerance, result))
        if result != "OK":
            failed.append(f)
    header = ("figure", "reference", "got", "rel. diff", "tolerance", "result")
    widths = [max(len(r[i]) for r in rows + [header]) for i in range(6)]
    print()
    for r in [header] + rows:
        print("  ".join(r[i].ljust(widths[i]) for i in range(6)).rstrip())
    if failed:
        print(f"\nWhy each tolerance ({opts.case}):")
        for f in failed:
            print(f"  {f.locator}: {f.why}")
        print(f"\n{name}: {len(failed)} of {len(rows)} figures outside their tolerance. If the change is intended "
              f"(a change of physics), write the new reference values with\n"
              f"  tests/regression/bless.sh BUILD_DIR {name}\nsee doc/testing.md.")
        return 1
    print(f"{name}: all {len(rows)} figures within their tolerances")
    return 0


def bless(opts, case, name):
    run_case(opts, case, opts.work_dir, name, [])
    new = []
    for f in case["figures"]:
        got = read_figure(opts.work_dir, f.locator)
        if got is None:
            raise CaseError(f"{name}: the figure {f.locator} is not in the output: fix the case file")
        # A value equal to the stored one keeps its text (another printing of the same double).
        same = is_number(got) and is_number(f.reference) and float(got) == float(f.reference)
        new.append(f.reference if same else got)
    width = max(len(v) for v in new)
    with open(opts.case, encoding="utf-8") as fh:
        content = fh.read()
    changed = 0
    for f, value in zip(case["figures"], new):
        parts = f.line.split("|")
        parts[1] = f" {value.ljust(width)} "
        content = content.replace(f.line, "|".join(parts), 1)
        if value != f.reference:
            print(f"  {f.locator}: {f.reference} -> {value}")
            changed += 1
    with open(opts.case, "w", encoding="utf-8") as fh:
        fh.write(content)
    print(f"{name}: blessed {opts.case} ({changed} of {len(new)} reference values changed)")
    return 0


def spread(opts, case, name):
    perturb = opts.perturb or case["perturb"]
    parts = [p.strip() for p in perturb.split("|")]
    if len(parts) != 3:
        raise CaseError(f"{opts.case}: 'perturb ENTRY | BASE | STEP' expected (a case line or --perturb)")
    entry, base, step = parts[0], float(parts[1]), float(parts[2])
    values = {f.locator: [] for f in case["figures"]}
    for k in range(opts.spread):
        directory = os.path.join(opts.work_dir, f"spread_{k}")
        run_case(opts, case, directory, name, [f"{entry}={base + k * step!r}"], quiet=True)
        for f in case["figures"]:
            got = read_figure(directory, f.locator)
            if got is None:
                raise CaseError(f"{name}: the figure {f.locator} is not in the output of run {k}")
            values[f.locator].append(got)
    print(f"\n{name}: {opts.spread} equivalent runs ('{entry}' = {base!r} + k × {step!r}, k = 0 … {opts.spread - 1})")
    print("figure | reference | mean | std | std/|mean| | largest |x-ref|/|ref| | tolerance | tolerance/std")
    for f in case["figures"]:
        v = values[f.locator]
        if f.tolerance == "exact":
            distinct = sorted(set(v))
            print(f"{f.locator} | {f.reference} | {len(distinct)} distinct value(s): {', '.join(distinct)} | | | | exact |")
            continue
        x = [float(a) for a in v]
        ref = float(f.reference)
        mean, sd = statistics.fmean(x), statistics.stdev(x) if len(x) > 1 else 0.0
        largest = max(abs(a - ref) for a in x)
        kind, bound = f.tolerance.split()
        allowed = float(bound) * abs(ref) if kind == "rel" else float(bound)
        print(f"{f.locator} | {f.reference} | {mean:.10g} | {sd:.2g} | "
              f"{(sd / abs(mean)) if mean else float('nan'):.2g} | {(largest / abs(ref)) if ref else float('nan'):.2g} | "
              f"{f.tolerance} | {(allowed / sd) if sd else float('inf'):.2g}")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--wearlink", required=True)
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--case", required=True)
    parser.add_argument("--work-dir", required=True)
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--bless", action="store_true")
    mode.add_argument("--spread", type=int, default=0)
    parser.add_argument("--perturb", default="")
    parser.add_argument("--set", action="append", default=[])
    opts = parser.parse_args()
    opts.wearlink = os.path.abspath(opts.wearlink)
    opts.case = os.path.abspath(opts.case)
    opts.source_dir = os.path.abspath(opts.source_dir)
    opts.work_dir = os.path.abspath(opts.work_dir)
    name = os.path.splitext(os.path.basename(opts.case))[0]
    try:
        if not os.access(opts.wearlink, os.X_OK):
            raise CaseError(f"--wearlink {opts.wearlink} is not an executable: build it first")
        # The work folder is removed before each run: refuse the source tree, a folder
        # above it, and a non-empty folder that is not an earlier work folder of this script.
        earlier = os.path.exists(os.path.join(opts.work_dir, "wearlink.log")) or \
            os.path.exists(os.path.join(opts.work_dir, "spread_0"))
        if (opts.source_dir + "/").startswith(opts.work_dir + "/") or \
                (os.path.isdir(opts.work_dir) and os.listdir(opts.work_dir) and not earlier):
            raise CaseError(f"--work-dir {opts.work_dir} would be removed: give an empty or new folder (the build tree's)")
        case = read_case(opts.case, opts.source_dir)
        if opts.bless:
            return bless(opts, case, name)
        if opts.spread:
            return spread(opts, case, name)
        return check(opts, case, name)
    except CaseError as e:
        print(e, file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
