# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Issue 46's Python acceptance against an installed archgeo (run by
tools/python_acceptance.sh after `pip install --no-build-isolation .` into a
fresh virtual environment, from a folder outside the repository):
planar_panels.py reads the shared Conjugate mesh, solves planar quads with a
progress callback, checks the per-face flatness against the report's δ_PQ,n
max and writes panels.csv; and SIGINT ends it within 1 s.

Environment: ARCHGEO_SOURCE_DIR (the clone installed from),
ARCHGEO_CONJUGATE (the shared mesh)."""
import os
import shutil
import signal
import subprocess
import sys
import time

import numpy as np

SCRIPT = os.path.join(os.environ["ARCHGEO_SOURCE_DIR"], "python", "acceptance", "planar_panels.py")
CONJUGATE = os.environ["ARCHGEO_CONJUGATE"]


def test_the_package_is_the_installed_one():
    import archgeo
    assert not archgeo.__file__.startswith(os.environ["ARCHGEO_SOURCE_DIR"])
    assert "site-packages" in archgeo.__file__


def script_outside(tmp_path):
    """The script copied to a folder outside the repository."""
    return shutil.copy(SCRIPT, tmp_path / "planar_panels.py")


def test_planar_panels_script(tmp_path):
    run = subprocess.run([sys.executable, script_outside(tmp_path), CONJUGATE], cwd=tmp_path,
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert sum(" iter " in line for line in run.stdout.splitlines()) > 1  # the callback
    table = np.loadtxt(tmp_path / "panels.csv", delimiter=",", skiprows=1)
    assert table.shape == (1633, 7)
    assert table[:, 5].max() <= 1e-3  # planar_quads' default tolerance
    assert np.array_equal(table[:, 0], np.arange(1633))


def test_sigint_ends_the_script_within_a_second(tmp_path):
    child = subprocess.Popen([sys.executable, script_outside(tmp_path), CONJUGATE], cwd=tmp_path,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    for line in child.stdout:
        if " iter " in line:
            break
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    child.wait(timeout=30)
    latency = time.monotonic() - sent
    stderr = child.stderr.read()
    print(f"SIGINT to exit: {latency:.3f} s")
    assert child.returncode == -signal.SIGINT  # an uncaught KeyboardInterrupt
    assert "KeyboardInterrupt" in stderr
    assert not (tmp_path / "panels.csv").exists()
    assert latency < 1.0
