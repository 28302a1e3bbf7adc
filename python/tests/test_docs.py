# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every Python block of docs/python.md runs as written, from the
repository root, and ends without an error."""
import os
import re
import subprocess
import sys

import pytest

from conftest import SOURCE

DOC = os.path.join(SOURCE, "docs", "python.md")
BLOCKS = re.findall(r"```python\n(.*?)```", open(DOC, encoding="utf-8").read(), re.S)


def test_the_doc_has_an_example_per_family():
    assert len(BLOCKS) == 8


@pytest.mark.parametrize("number", range(len(BLOCKS)))
def test_doc_example_runs(number):
    run = subprocess.run([sys.executable, "-c", BLOCKS[number]], cwd=SOURCE,
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
