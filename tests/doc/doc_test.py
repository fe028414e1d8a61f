#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The documentation's commands, run: every shell and Python block of README.md and doc/**/*.md.

A fenced block tagged ```sh, ```bash or ```shell is run by bash; a block tagged ```python
by python3 with the module of the build under test on its path (--python-path) and
matplotlib drawing into files (MPLBACKEND=Agg); a block tagged anything else (```text for
a synopsis with placeholders or a printed table, ```prm for a scene, ```pycon for a
Python session to read) is not. A fence without a tag is an error, so that no block
escapes the choice.

Before a block's fence, HTML comments (invisible on the rendered page, visible in the
source and in this test's report) may shorten it:

  <!-- doc-test: --set "Wear/Number of iterations=1" -->
      appends these arguments to every `build/wearlink` command of the block (after
      the command's own arguments, before a pipe, `&&`, `;` or a comment);
  <!-- doc-test: sub "--ensemble 64" "--ensemble 2" -->
      replaces every occurrence of the first text in the block by the second (the first
      must occur);
  <!-- doc-test: skip: REASON -->
      does not run the block, and says why in the report.
A Python block takes `sub` and `skip:` (there is no build/wearlink command to append to).

doc/parameters.md is not a page of this test: it is generated (GENERATED below) and
has a test of its own. Lines that call ./bootstrap.sh are not run (CI runs `./bootstrap.sh test`, which
installs and builds; here the program is built already). A run block may not hold a
synopsis: `[--option ...]`, `...` or one of the placeholder words (SCENE.prm, DIR, ...)
is an error that asks for a ```text fence.

Each Markdown file runs in a fresh working directory WORK/<file>/ that holds copies of
the source's params/ and meshes/ and build/wearlink, a link to the program under test
(and build/python, a link to the module's folder, with --python-path),
so the commands run as written from the project's root and nothing is written into the
source tree. The blocks of one file run in order in that directory (a block may use
the output of an earlier block of the same file), with
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 (Open MPI refuses root
otherwise), WEARLINK_CACHE_DIR=WORK/cache and TMPDIR=WORK/tmp. A block fails when it exits non-zero or
runs longer than --timeout seconds; the file stops at its first failing block.

Usage (as CTest runs it, tests/doc/CMakeLists.txt):
  doc_test.py --binary build/wearlink --source . --work build/tests/doc/work doc/getting_started.md
  doc_test.py --binary ... --source . --work ... --list      every block and what would run
Exit status: 0 every block ran, 1 a block failed or a file breaks the rules above.
"""

import argparse
import os
import re
import shlex
import shutil
import subprocess
import sys
import time
from pathlib import Path

SHELL_TAGS = {"sh", "bash", "shell"}
PYTHON_TAGS = {"python"}
RUN_TAGS = SHELL_TAGS | PYTHON_TAGS
# Pages written by a program, not by hand: their own test keeps them current.
GENERATED = {"doc/parameters.md": "written by tests/support/parameter_reference.cmake from "
                                  "`wearlink --print-parameters`; the test doc.parameter_reference checks it"}
PLACEHOLDERS = {
    "SCENE", "SCENE.prm", "DIR", "RUN_DIR", "OUT_DIR", "MEASURED.csv", "MEAS.prm", "CASE", "CASE.prm",
    "SERIES.csv", "NAME", "BEFORE_DIR", "AFTER_DIR", "FROM:TO:COUNT", "COMMAND", "STUDY.prm", "FILE",
}
FENCE = re.compile(r"^(\s*)(`{3,}|~{3,})\s*([^\s`]*)\s*$")
DIRECTIVE = re.compile(r"^\s*<!--\s*doc-test:\s*(.*?)\s*-->\s*$")


class Block:
    def __init__(self, path, line, tag, text, directives):
        self.path, self.line, self.tag, self.text, self.directives = path, line, tag, text, directives

    @property
    def where(self):
        return f"{self.path}:{self.line}"


def read_blocks(path, display):
    """The fenced blocks of a Markdown file, with the doc-test comments right before each."""
    lines = path.read_text(encoding="utf-8").split("\n")
    blocks, errors = [], []
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, fence, tag = m.group(1), m.group(2), m.group(3).lower()
        start = i
        directives = []
        j = i - 1
        while j >= 0 and DIRECTIVE.match(lines[j]):
            directives.insert(0, DIRECTIVE.match(lines[j]).group(1))
            j -= 1
        body = []
        i += 1
        while i < len(lines):
            c = FENCE.match(lines[i])
            if c and c.group(2)[0] == fence[0] and len(c.group(2)) >= len(fence) and not c.group(3):
                break
            body.append(lines[i][len(indent):] if lines[i].startswith(indent) else lines[i].lstrip())
            i += 1
        if i == len(lines):
            errors.append(f"{display}:{start + 1}: a fence that is never closed")
            break
        if not tag:
            errors.append(f"{display}:{start + 1}: a fence without a tag: ```sh (run by the doc-test) "
                          "or ```text (not run)")
        blocks.append(Block(display, start + 1, tag, "\n".join(body), directives))
        i += 1
    return blocks, errors


def split_outside_quotes(line):
    """Positions in a shell line where a command segment ends: |, &&, ||, ; and a comment."""
    ends, quote, k = [], None, 0
    while k < len(line):
        ch = line[k]
        if quote:
            if ch == "\\" and quote == '"':
                k += 2
                continue
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "\\":
            k += 2
            continue
        elif ch == "#" and (k == 0 or line[k - 1] in " \t"):
            ends.append(k)
            return ends, True
        elif ch in "|;&":
            ends.append(k)
            k += 2 if line[k:k + 2] in ("||", "&&") else 1
            continue
        k += 1
    return ends, False


def command_part(line):
    """The line without its trailing shell comment."""
    ends, comment = split_outside_quotes(line)
    return line[:ends[-1]] if comment else line


def append_to_wearlink(line, args):
    """@p line with @p args after every `build/wearlink` command segment in it."""
    ends, comment = split_outside_quotes(line)
    bounds = ends + ([] if comment else [len(line)])
    out, start, changed = "", 0, False
    for end in bounds:
        segment = line[start:end]
        if re.search(r"(^|[\s/])build/wearlink(\s|$)", segment):
            stripped = segment.rstrip()
            segment = stripped + " " + args + segment[len(stripped):]
            changed = True
        out += segment
        start = end
    return out + line[start:], changed


def logical_lines(text):
    """Shell lines with backslash continuations joined."""
    out, current = [], ""
    for raw in text.split("\n"):
        if raw.rstrip().endswith("\\") and not raw.lstrip().startswith("#"):
            current += raw.rstrip()[:-1] + " "
        else:
            out.append(current + raw)
            current = ""
    if current:
        out.append(current)
    return out


def prepare(block):
    """(script, notes, errors) of a run block: bootstrap lines dropped, directives applied."""
    notes, errors, args, subs = [], [], [], []
    for d in block.directives:
        if d.startswith("skip:"):
            return None, [f"skipped: {d[5:].strip()}"], []
        if d.startswith("sub "):
            parts = shlex.split(d[4:])
            if len(parts) != 2:
                errors.append(f"{block.where}: `sub` takes two quoted texts: {d}")
            else:
                subs.append(parts)
        elif d.startswith("-"):
            args.append(d)
        else:
            errors.append(f"{block.where}: unknown doc-test directive '{d}' (--ARGS, sub \"A\" \"B\", skip: REASON)")
    text = block.text
    if block.tag in PYTHON_TAGS and args:
        errors.append(f"{block.where}: doc-test arguments before a ```python block (use sub \"A\" \"B\")")
    for old, new in subs:
        if old not in text:
            errors.append(f"{block.where}: doc-test sub: '{old}' is not in the block")
        text = text.replace(old, new)
        notes.append(f"sub '{old}' -> '{new}'")
    if block.tag in PYTHON_TAGS:
        return text + "\n", notes, errors
    lines, dropped = [], 0
    for line in logical_lines(text):
        code = command_part(line).strip()
        if re.match(r"^(\./)?bootstrap\.sh\b", code):
            dropped += 1
            continue
        for word in re.findall(r"[^\s\"'=]+", code):
            if word in PLACEHOLDERS or word.strip(",") in ("...", "…") or word.startswith("[--"):
                errors.append(f"{block.where}: a synopsis in a run block ('{word}' in `{code}`): "
                              "fence it as ```text, or write a command that runs")
                break
        lines.append(line)
    if dropped:
        notes.append(f"{dropped} ./bootstrap.sh line(s) not run (CI runs them)")
    if not any(command_part(line).strip() for line in lines):
        return None, notes + ["nothing left to run"], errors
    if args:
        joined = " ".join(args)
        hit = False
        for n, line in enumerate(lines):
            lines[n], changed = append_to_wearlink(line, joined)
            hit = hit or changed
        if not hit:
            errors.append(f"{block.where}: doc-test arguments but no build/wearlink command in the block")
        notes.append(f"appended to build/wearlink: {joined}")
    return "\n".join(lines) + "\n", notes, errors


def fresh_workdir(work, display, source, binary, python_path=None):
    name = re.sub(r"[^A-Za-z0-9_.-]", "_", display)
    d = work / name
    if d.exists():
        shutil.rmtree(d)
    (d / "build").mkdir(parents=True)
    os.symlink(binary, d / "build" / "wearlink")
    if python_path:
        os.symlink(python_path, d / "build" / "python")
    for sub in ("params", "meshes"):
        shutil.copytree(source / sub, d / sub, symlinks=True)
    return d


def run_file(md, display, opts):
    blocks, errors = read_blocks(md, display)
    plans = []
    for b in blocks:
        if b.tag not in RUN_TAGS:
            if b.directives:
                errors.append(f"{b.where}: a doc-test comment before a ```{b.tag} block, which is not run")
            continue
        script, notes, errs = prepare(b)
        errors += errs
        plans.append((b, script, notes))
    n_text = sum(1 for b in blocks if b.tag not in RUN_TAGS)
    if errors:
        for e in errors:
            print(f"doc-test: ERROR {e}")
        return False, {}
    if opts.list:
        for b, script, notes in plans:
            print(f"--- {b.where} ({'; '.join(notes) if notes else 'as written'})")
            print(script if script else "(not run)")
        return True, {}
    wd = fresh_workdir(opts.work, display, opts.source, opts.binary, opts.python_path)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               WEARLINK_CACHE_DIR=str(opts.work / "cache"), TMPDIR=str(opts.work / "tmp"), LC_ALL="C.UTF-8")
    # `python3` in a shell block is the interpreter running this test (the build's).
    env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + env.get("PATH", "")
    if opts.python_path:
        env["PYTHONPATH"] = str(opts.python_path) + os.pathsep + env.get("PYTHONPATH", "")
    env["MPLBACKEND"] = "Agg"
    (opts.work / "tmp").mkdir(exist_ok=True)
    stats = {"run": 0, "override": 0, "skip": 0, "bootstrap": 0, "text": n_text, "seconds": 0.0}
    t_file = time.monotonic()
    for b, script, notes in plans:
        tag = f"{b.where}"
        if script is None:
            key = "skip" if any(n.startswith("skipped") for n in notes) else "bootstrap"
            stats[key] += 1
            print(f"doc-test: {tag}: not run ({'; '.join(notes)})")
            continue
        stats["run"] += 1
        if any(n.startswith(("appended", "sub")) for n in notes):
            stats["override"] += 1
        t0 = time.monotonic()
        try:
            command = [sys.executable, "-c", script] if b.tag in PYTHON_TAGS else \
                ["bash", "-c", "set -eo pipefail\n" + script]
            p = subprocess.run(command, cwd=wd, env=env,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=opts.timeout)
            rc, out = p.returncode, p.stdout.decode("utf-8", "replace")
        except subprocess.TimeoutExpired as e:
            rc, out = "timeout", (e.stdout or b"").decode("utf-8", "replace")
        dt = time.monotonic() - t0
        extra = f" [{'; '.join(notes)}]" if notes else ""
        if rc != 0:
            print(f"doc-test: FAILED {tag} (exit status {rc} after {dt:.1f} s){extra}")
            print("---- the block as run (in " + str(wd) + "):")
            print(script.rstrip())
            print("---- its output (last 40 lines):")
            print("\n".join(out.rstrip().split("\n")[-40:]))
            stats["seconds"] = time.monotonic() - t_file
            return False, stats
        print(f"doc-test: ok {tag} ({dt:.1f} s){extra}")
    stats["seconds"] = time.monotonic() - t_file
    return True, stats


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", required=True, type=Path, help="the wearlink program under test")
    ap.add_argument("--source", required=True, type=Path, help="the project's source directory")
    ap.add_argument("--work", required=True, type=Path, help="a scratch directory (in the build tree)")
    ap.add_argument("--python-path", type=Path, help="the folder holding the Python module under test")
    ap.add_argument("--timeout", type=float, default=120, help="seconds per block (default 120)")
    ap.add_argument("--list", action="store_true", help="print what would run, run nothing")
    ap.add_argument("files", nargs="*", help="Markdown files (default: README.md and doc/**/*.md)")
    opts = ap.parse_args()
    opts.source = opts.source.resolve()
    opts.binary = opts.binary.resolve()
    opts.work = opts.work.resolve()
    if opts.python_path:
        opts.python_path = opts.python_path.resolve()
    if not opts.list and not os.access(opts.binary, os.X_OK):
        print(f"doc-test: ERROR the program {opts.binary} is not an executable file")
        return 1
    opts.work.mkdir(parents=True, exist_ok=True)
    files = opts.files or ["README.md"] + sorted(
        f for f in (str(p.relative_to(opts.source)) for p in (opts.source / "doc").rglob("*.md"))
        if f not in GENERATED)
    ok, total = True, {"run": 0, "override": 0, "skip": 0, "bootstrap": 0, "text": 0, "seconds": 0.0}
    for f in files:
        md = Path(f) if Path(f).is_absolute() else opts.source / f
        display = str(md.relative_to(opts.source)) if opts.source in md.resolve().parents else md.name
        good, stats = run_file(md, display, opts)
        ok = ok and good
        for k, v in stats.items():
            total[k] += v
        if stats and not opts.list:
            print(f"doc-test: {display}: {stats['run']} blocks run ({stats['override']} shortened by a doc-test "
                  f"comment), {stats['skip']} skipped, {stats['bootstrap']} ./bootstrap.sh only, "
                  f"{stats['text']} not shell (text, prm, ...); {stats['seconds']:.1f} s")
    if len(files) > 1 and not opts.list:
        print(f"doc-test: all {len(files)} files: {total['run']} blocks run ({total['override']} shortened), "
              f"{total['skip']} skipped, {total['bootstrap']} ./bootstrap.sh only, {total['text']} not shell; "
              f"{total['seconds']:.1f} s")
    print("doc-test: " + ("passed" if ok else "FAILED"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
