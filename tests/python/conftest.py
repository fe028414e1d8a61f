# SPDX-License-Identifier: LGPL-2.1-or-later
"""What the Python tests share: the project's folders, the program, a scratch folder.

CTest runs them (tests/python/CMakeLists.txt) with PYTHONPATH=build/python,
WEARLINK_BINARY=the program and WEARLINK_SOURCE=the project's root.
"""
import os
import subprocess

import pytest

SOURCE = os.environ.get("WEARLINK_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("WEARLINK_BINARY", os.path.join(SOURCE, "build", "wearlink"))


def scene_path(name):
    """A shipped scene, params/<name>."""
    return os.path.join(SOURCE, "params", name)


def set_args(sets):
    """A dict of entries as the program's --set arguments."""
    import wearlink
    return [a for k, v in sets.items() for a in ("--set", f"{k}={wearlink._format(v)}")]


def run_program(*args):
    """The program with `args`; its CompletedProcess (output captured)."""
    return subprocess.run([BINARY, *args], capture_output=True, text=True)


# A nine-bar wear run short enough for the default suite: 2 iterations of 1 cycle.
SHORT_WEAR = {"Wear/Number of iterations": 2, "Wear/Cycles per iteration": 1, "Wear/Response cycles": 1,
              "Output/Plots": False}


@pytest.fixture
def scratch(tmp_path):
    return tmp_path
