# SPDX-License-Identifier: LGPL-2.1-or-later
"""Every kind of failure reaches Python as its own exception, with the program's message;
bad input leaves the scene as it was; an interrupted or failed run leaves no half-written
outputs."""
import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

import wearlink
from conftest import SHORT_WEAR, SOURCE, scene_path


def test_bad_input_is_a_value_error_naming_file_and_entry():
    scene = wearlink.Scene(scene_path("nine_bar_wear.prm"))
    with pytest.raises(wearlink.InputError) as caught:
        scene["Joint B/Clearance/Radial clearance"] = -1
    assert isinstance(caught.value, ValueError)
    assert caught.value.entry == "Joint B/Clearance/Radial clearance"
    assert "0...0.5" in str(caught.value), "the allowed range"
    assert scene.overrides == [], "a refused entry is not kept"
    with pytest.raises(wearlink.InputError) as caught:
        scene["Joint B/Clearance/No such entry"]
    assert caught.value.file == scene_path("nine_bar_wear.prm")
    with pytest.raises(wearlink.InputError) as caught:
        wearlink.Scene(scene_path("no_such_scene.prm"))
    assert "no_such_scene.prm" in str(caught.value)


def test_a_scene_from_text_reads_its_includes_from_its_folder():
    text = "include nine_bar_wear.prm\nset Title = from text\n"
    scene = wearlink.Scene.from_string(text, base=os.path.join(SOURCE, "params"))
    assert scene.title == "from text"
    assert scene.wearing_joints == ["A", "B"]
    with pytest.raises(wearlink.InputError) as caught:
        wearlink.Scene.from_string("set Title = x\nset Nonsense = 1\n")
    assert caught.value.line == 2, str(caught.value)


def test_a_numerical_failure_is_its_own_exception(scratch):
    # A step budget far below what the nine-bar needs (doc/running.md, the step budget).
    # A smallest step far above what the impacts need: the step size control fails.
    scene = wearlink.Scene(scene_path("nine_bar_clearance.prm"),
                           set={"Integrator/Method": "dopri5", "Integrator/Minimum step": 5e-4,
                                "Output/Plots": False})
    with pytest.raises(wearlink.NumericalError) as caught:
        wearlink.run(scene, output=scratch / "out")
    assert isinstance(caught.value, RuntimeError)
    assert "step size fell" in str(caught.value)
    assert no_partials(scratch / "out")


def no_partials(folder):
    """No temporary file of an unfinished output in `folder` (which may be gone: an empty
    folder a run created is removed)."""
    return not os.path.exists(folder) or not [f for f in os.listdir(folder) if "partial" in f]


def run_child(code, **kwargs):
    """`code` in a child Python with the module on its path."""
    return subprocess.Popen([sys.executable, "-c", textwrap.dedent(code)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, **kwargs)


def test_an_output_that_cannot_be_written_is_an_environment_fault(scratch):
    # The file-size limit makes every write beyond 4 kB fail (EFBIG), as a full disk would.
    child = run_child(f"""
        import resource, wearlink
        resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))
        try:
            wearlink.run(wearlink.Scene({scene_path("nine_bar_wear.prm")!r}, set={SHORT_WEAR!r}),
                         output={str(scratch / "out")!r})
        except wearlink.EnvironmentFault as e:
            print("EnvironmentFault", isinstance(e, OSError))
    """)
    out, err = child.communicate(timeout=300)
    assert child.returncode == 0, err
    assert out.strip() == "EnvironmentFault True", out + err
    assert no_partials(scratch / "out")


def test_ctrl_c_stops_a_run_cleanly(scratch):
    child = run_child(f"""
        import sys, wearlink
        def told(fraction, line):
            print("started", flush=True)
        try:
            wearlink.run(wearlink.Scene({scene_path("nine_bar_wear.prm")!r}),
                         output={str(scratch / "out")!r}, progress=told)
        except wearlink.Interrupted as e:
            print("Interrupted", isinstance(e, KeyboardInterrupt), flush=True)
    """)
    assert child.stdout.readline().strip() == "started"  # the first iteration is done
    time.sleep(0.5)
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=120)
    assert child.returncode == 0, err
    assert out.strip().split("\n")[-1] == "Interrupted True", out + err
    assert no_partials(scratch / "out")
    assert not os.path.exists(scratch / "out" / "summary.json"), "an interrupted run writes no summary"
