# SPDX-License-Identifier: LGPL-2.1-or-later
"""A run from Python is the program's run: the same figures to the bit, arrays of the
documented shapes, names and units, progress told, the GIL released while it runs."""
import json
import os
import threading
import time

import numpy as np
import pytest

import wearlink
from conftest import SHORT_WEAR, run_program, scene_path, set_args

# Figures that measure the machine, not the mechanism: wall times and the phases' times.
MACHINE = {"wall_time_s", "wear_timing_s", "effect_ledger"}


def figures(summary):
    return {k: v for k, v in summary.items() if k not in MACHINE}


def program_run(scene, sets, out):
    args = ["run", scene, "--output", str(out), "--quiet"]
    args += set_args(sets)
    done = run_program(*args)
    assert done.returncode == 0, done.stderr
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def test_a_wear_run_gives_the_programs_figures(scratch):
    scene = wearlink.Scene(scene_path("nine_bar_wear.prm"), set=SHORT_WEAR)
    result = wearlink.run(scene, output=scratch / "python")
    cli = program_run(scene_path("nine_bar_wear.prm"), SHORT_WEAR, scratch / "cli")
    assert figures(result.summary) == figures(cli)
    # The wear history: one row per iteration, the same numbers as the program's file.
    history = result.wear_history
    assert len(history) == 2
    program = wearlink.Table.read(scratch / "cli" / "wear_history.csv")
    assert history.columns == program.columns
    assert np.array_equal(history.values, program.values)
    assert "B_max_depth_bushing_um" in history
    # The worn profiles: radii [m] at the angles of their samples, as bore_B.csv has them.
    for joint in ("A", "B"):
        p = result.profiles[joint]
        n = p["angle_rad"].shape[0]
        for surface in ("bore", "pin", "initial_bore", "initial_pin"):
            assert p[surface].shape == (n,) and p[surface].dtype == np.float64
        written = wearlink.Table.read(scratch / "cli" / f"bore_{joint}.csv")
        assert np.allclose(written["angle_rad"], p["angle_rad"], rtol=0, atol=1e-12)
        assert np.allclose(written["radius_m"], p["bore"], rtol=1e-12, atol=0)
        assert np.all(p["bore"] >= p["initial_bore"]) and np.all(p["pin"] <= p["initial_pin"])
        assert np.max(p["bore"] - p["initial_bore"]) > 0, "the bore wore"
    assert "summary.json" in result.files and "wear_history.csv" in result.files
    assert result.output_directory == str(scratch / "python")


def test_a_plain_run_hands_its_time_series(scratch):
    sets = {"Simulation/End time": 0.05, "Output/Plots": False}
    result = wearlink.run(wearlink.Scene(scene_path("nine_bar_clearance.prm"), set=sets))
    cli = program_run(scene_path("nine_bar_clearance.prm"), sets, scratch / "cli")
    assert figures(result.summary) == figures(cli)
    ts = result.time_series
    assert ts.columns[0] == "time_s"
    # Every column carries its unit as its last part (doc/running.md): m, s, rad, N, J, m_s2, ...
    units = {"m", "s", "s2", "rad", "N", "J", "W"}
    assert all(name.rsplit("_", 1)[-1] in units for name in ts.columns), ts.columns
    assert ts.values.shape == (len(ts), len(ts.columns))
    assert ts["time_s"][0] == pytest.approx(0.0) and ts["time_s"][-1] == pytest.approx(0.05)
    assert np.all(np.diff(ts["time_s"]) > 0)
    assert ts["time_s"].base is ts.values or ts["time_s"].base is ts.values.base, "a column is a view, not a copy"
    assert result.output_directory is None, "the temporary folder is gone"
    assert result.wear_history is None and result.profiles == {}


def test_progress_is_told_and_the_gil_is_free(scratch):
    told = []
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        wearlink.run(wearlink.Scene(scene_path("nine_bar_wear.prm"), set=SHORT_WEAR),
                     progress=lambda fraction, line: told.append((fraction, line)))
    finally:
        stop.set()
        counter.join()
    assert [f for f, _ in told] == [0.5, 1.0]
    assert told[0][1].startswith("wear iteration 1/2")
    # The counting thread ran all along: no gap of a second while the C++ ran.
    assert len(ticks) > 20 and max(np.diff(ticks)) < 1.0


def test_a_study_of_a_few_runs(scratch):
    depths = []
    for clearance in (2e-4, 5e-4):
        scene = wearlink.Scene(scene_path("nine_bar_wear.prm"), set=SHORT_WEAR)
        scene["Joint B/Clearance/Radial clearance"] = clearance
        assert float(scene["Joint B/Clearance/Radial clearance"]) == clearance
        result = wearlink.run(scene)
        depths.append(result.summary["clearance_joints"]["B"]["max_wear_depth_bushing_m"])
    assert all(d > 0 for d in depths) and depths[0] != depths[1]


def test_two_runs_in_threads_give_their_own_figures(scratch):
    # Each run has its own scene, mechanism and folder: run side by side, each gives what
    # it gives alone (the effect ledger, a process-wide count, is left out).
    scenes = [wearlink.Scene(scene_path("nine_bar_wear.prm"), set=SHORT_WEAR | {"Joint B/Clearance/Radial clearance": c})
              for c in (3e-4, 5e-4)]
    alone = [figures(wearlink.run(s).summary) for s in scenes]
    together = [None, None]

    def one(k):
        together[k] = figures(wearlink.run(scenes[k]).summary)

    threads = [threading.Thread(target=one, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert together == alone


def test_a_table_is_a_dataframe_where_pandas_is_installed():
    pandas = pytest.importorskip("pandas")
    table = wearlink.Table(["time_s", "x_m"], np.array([[0.0, 1.0], [0.5, 2.0]]))
    frame = table.to_pandas()
    assert isinstance(frame, pandas.DataFrame) and list(frame.columns) == ["time_s", "x_m"]
    assert frame["x_m"].tolist() == [1.0, 2.0]
