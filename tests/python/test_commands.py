# SPDX-License-Identifier: LGPL-2.1-or-later
"""compare_contact and calibrate from Python: the program's tables, its checks of the options."""
import json
import os

import numpy as np
import pytest

import wearlink
from conftest import SOURCE, run_program, scene_path, set_args


def test_compare_contact_gives_the_programs_tables(scratch):
    result = wearlink.compare_contact(scene_path("nine_bar_clearance.prm"), effects=False)
    done = run_program("compare-contact", scene_path("nine_bar_clearance.prm"), "--no-effects", "--output",
                       str(scratch / "cli"))
    assert done.returncode == 0, done.stderr
    assert result.report and result.report in done.stdout
    for name in ("force_approach", "deviations", "pressure"):
        program = wearlink.Table.read(scratch / "cli" / f"{name}.csv")
        assert result.tables[name].columns == program.columns, name
        assert np.array_equal(result.tables[name].values, program.values, equal_nan=True), name
    with pytest.raises(wearlink.InputError, match="at most 1e4"):
        wearlink.compare_contact(scene_path("nine_bar_clearance.prm"), cycles=1e5, output=scratch / "bad")
    assert not os.path.exists(scratch / "bad"), "nothing written"


def test_calibrate_recovers_the_rigs_coefficient_with_an_interval(scratch):
    result = wearlink.calibrate(scene_path("nine_bar_experiment.prm"),
                                os.path.join(SOURCE, "params", "nine_bar_experiment_measurements.prm"), ensemble=1)
    k = result.summary["joints"]["A"]["pin_wear_coefficient"]
    assert k["ci95_low"] < k["value"] < k["ci95_high"] and k["prior"] == 1e-13
    assert "k = " in result.report
    assert result.summary["secant"]["converged"]
    with pytest.raises(wearlink.InputError, match="from 1 to 1000"):
        wearlink.calibrate(scene_path("nine_bar_experiment.prm"),
                           os.path.join(SOURCE, "params", "nine_bar_experiment_measurements.prm"), ensemble=0,
                           output=scratch / "bad")
    assert not os.path.exists(scratch / "bad"), "nothing written"


def test_contact_gives_the_programs_summary(scratch):
    sets = {"Loads/Load magnitudes": 1000, "FE model/Surface element size": 1e-4, "FE model/Solvers": "condensed",
            "Output/Write VTU": False}
    result = wearlink.contact(os.path.join(SOURCE, "params", "pin_bushing.prm"),
                              set=sets)
    args = ["contact", os.path.join(SOURCE, "params", "pin_bushing.prm"), "--output", str(scratch / "cli")]
    args += set_args(sets)
    done = run_program(*args)
    assert done.returncode == 0, done.stderr
    with open(scratch / "cli" / "summary.json") as f:
        cli = json.load(f)

    def mechanics(x):
        if isinstance(x, dict):
            # times (…_s) and the process-wide effect ledger measure the process, not the contact
            return {k: mechanics(v) for k, v in x.items() if not k.endswith("_s") and "ledger" not in k}
        if isinstance(x, list):
            return [mechanics(v) for v in x]
        return x

    assert mechanics(result.summary) == mechanics(cli)
    assert "pressure_0_condensed" in result.tables
    with pytest.raises(wearlink.InputError, match="mechanism scene"):
        wearlink.contact(scene_path("nine_bar_wear.prm"), output=scratch / "bad")
    assert not os.path.exists(scratch / "bad"), "nothing written"


def test_a_quick_accuracy_study_gives_the_programs_errors(scratch):
    result = wearlink.study("accuracy", scene_path("nine_bar_clearance.prm"), quick=True)
    done = run_program("study", "accuracy", scene_path("nine_bar_clearance.prm"), "--quick", "--quiet", "--output",
                       str(scratch / "cli"))
    assert done.returncode == 0, done.stderr
    assert result.report.startswith("Accuracy study of")
    program = wearlink.Table.read(scratch / "cli" / "accuracy.csv")
    mine = result.tables["accuracy"]
    assert mine.columns == program.columns and len(mine) == len(program) > 0
    # The errors are the mechanics' (the same to the bit); the times are the machine's.
    for column in ("worst_error", "floor_worst_mean", "A F_peak"):
        assert np.array_equal(mine[column], program[column], equal_nan=True), column
    with pytest.raises(wearlink.InputError, match="2 … 100 members"):
        wearlink.study("accuracy", scene_path("nine_bar_clearance.prm"), quick=True, ensemble=1,
                       output=scratch / "bad")
    assert not os.path.exists(scratch / "bad"), "nothing written"
