# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Ctrl-C during archgeo.solve: the solve stops after the current iteration
(the GIL is released while it runs, so other threads run meanwhile) and
KeyboardInterrupt is raised once it has returned, carrying the last valid
state as its `result`."""
import json
import os
import signal
import subprocess
import sys
import threading

import archgeo
from conftest import CONJUGATE, SOURCE

# A solve that does not end by itself for minutes: a tolerance no round
# reaches and many rounds of many iterations.
ENDLESS = {"tolerance__pq_normalized_max": 1e-15, "schedule__outer_iterations": 1000,
           "solver__max_num_iterations": 1000, "solver__function_tolerance": 0,
           "solver__gradient_tolerance": 0, "solver__parameter_tolerance": 0,
           "output__mesh": "", "output__report": "", "output__image": "",
           "solver__num_threads": 1}
SPEC = os.path.join(SOURCE, "examples", "planar_quads.yaml")


def test_sigint_from_another_thread_stops_the_solve():
    V, F = archgeo.read_mesh(CONJUGATE)
    started = threading.Event()
    lines = []

    def on_iteration(info):
        lines.append(info["line"])
        if info["kind"] == "iteration":
            started.set()

    def interrupt():  # runs while the solving thread holds no GIL
        started.wait()
        os.kill(os.getpid(), signal.SIGINT)

    thread = threading.Thread(target=interrupt)
    thread.start()
    try:
        archgeo.solve(SPEC, V, F, on_iteration=on_iteration, **ENDLESS)
        raise AssertionError("no KeyboardInterrupt")
    except KeyboardInterrupt as interrupted:
        result = interrupted.result
    thread.join()
    assert result.stopped and result.valid
    assert result.report["stop"].startswith("stopped by request")
    assert result.report["iterations"]["outer"] == 1
    assert result.report["iterations"]["inner"] < 1000
    # The state returned is measured by the report.
    assert result.face_values["pq_normalized"].max() == result.report["after"]["pq_normalized_max"]
    assert result.V.shape == V.shape


CHILD = r"""
import json, sys, time
import archgeo
V, F = archgeo.read_mesh(sys.argv[1])
keys = json.loads(sys.argv[3])
first = []
def on_iteration(info):
    if info["kind"] == "iteration" and not first:
        first.append(1)
        print("solving", flush=True)
try:
    archgeo.solve(sys.argv[2], V, F, on_iteration=on_iteration, **keys)
    print(json.dumps({"interrupted": False}))
except KeyboardInterrupt as e:
    r = e.result
    print(json.dumps({"interrupted": True, "caught": time.time(), "stopped": r.stopped,
                      "valid": r.valid, "stop": r.report["stop"],
                      "iterations": r.report["iterations"]}))
"""


def test_ctrl_c_in_a_python_process(tmp_path):
    """As a user's Ctrl-C: SIGINT from outside the process."""
    keys = dict(ENDLESS, output__report=str(tmp_path / "report.json"))
    child = subprocess.Popen([sys.executable, "-c", CHILD, CONJUGATE, SPEC, json.dumps(keys)],
                             stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "solving"
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=60)
    assert child.returncode == 0
    answer = json.loads(out)
    assert answer["interrupted"] and answer["stopped"] and answer["valid"]
    assert answer["stop"].startswith("stopped by request")
    assert answer["iterations"]["inner"] < 1000
    # An interrupted solve writes no output (as `archgeo solve` interrupted).
    assert not (tmp_path / "report.json").exists()
    assert os.listdir(tmp_path) == []
