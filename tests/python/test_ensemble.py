# SPDX-License-Identifier: LGPL-2.1-or-later
"""Ensembles from Python: the program's ensemble to the bit, in-process and over two MPI
ranks alike; bad requests refused before anything runs."""
import json
import os
import shutil
import subprocess
import sys
import textwrap

import pytest

import wearlink
from conftest import SHORT_WEAR, run_program, scene_path, set_args

# What measures the machine or names the folder, not the members' mechanics.
MACHINE = ("wall_time_s", "wear_timing_s", "effect_ledger", "elapsed")
PLACE = {"directory", "output_directory", "rank", "ranks", "mpi_ranks"}  # where the members ran


def mechanics(x):
    """The summary without the figures of the machine (at any depth)."""
    if isinstance(x, dict):
        return {k: mechanics(v) for k, v in x.items() if k not in PLACE and not any(m in k for m in MACHINE)}
    if isinstance(x, list):
        return [mechanics(v) for v in x]
    return x


def test_an_ensemble_is_the_programs_on_any_rank_count(scratch):
    scene = wearlink.Scene(scene_path("nine_bar_wear.prm"), set=SHORT_WEAR)
    serial = wearlink.run(scene, output=scratch / "serial", ensemble=2, seed=7)
    assert serial.members is not None and len(serial.members) == 2
    assert os.path.isdir(scratch / "serial" / "member_1") or os.path.isdir(scratch / "serial" / "member_01")
    args = ["run", scene_path("nine_bar_wear.prm"), "--ensemble", "2", "--seed", "7", "--output",
            str(scratch / "cli"), "--quiet"]
    args += set_args(SHORT_WEAR)
    done = run_program(*args)
    assert done.returncode == 0, done.stderr
    with open(scratch / "cli" / "summary.json") as f:
        cli = json.load(f)
    assert mechanics(serial.summary) == mechanics(cli)

    mpirun = shutil.which("mpirun") or shutil.which("mpiexec")
    if mpirun is None:
        pytest.skip("no mpirun: the two-rank half needs openmpi-bin")
    code = textwrap.dedent(f"""
        import json, wearlink
        scene = wearlink.Scene({scene_path("nine_bar_wear.prm")!r}, set={SHORT_WEAR!r})
        r = wearlink.run(scene, output={str(scratch / "mpi")!r}, ensemble=2, seed=7)
        rank = wearlink._wearlink.mpi_ranks()[0]
        with open({str(scratch)!r} + f"/rank{{rank}}.json", "w") as f:
            json.dump(r.summary, f)
    """)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    done = subprocess.run([mpirun, "-np", "2", "--oversubscribe", sys.executable, "-c", code], env=env,
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    for rank in (0, 1):
        with open(scratch / f"rank{rank}.json") as f:
            assert mechanics(json.load(f)) == mechanics(serial.summary), f"rank {rank}"


def test_a_bad_ensemble_request_is_refused_before_anything_runs(scratch):
    scene = wearlink.Scene(scene_path("nine_bar_wear.prm"), set=SHORT_WEAR)
    with pytest.raises(wearlink.InputError, match="from 2 to 1000"):
        wearlink.run(scene, output=scratch / "one", ensemble=1)
    with pytest.raises(wearlink.InputError, match="belong to an ensemble"):
        wearlink.run(scene, output=scratch / "seed", seed=3)
    with pytest.raises(wearlink.InputError, match="at most 1e-3 rad"):
        wearlink.run(scene, output=scratch / "big", ensemble=2, perturbation=0.1)
    assert not any(os.path.exists(scratch / d) for d in ("one", "seed", "big")), "nothing written"
