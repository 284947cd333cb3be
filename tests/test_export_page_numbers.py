"""The HTML page's panel prints numbers as ``xaml3d camera`` does (6 significant digits,
Python's ``%.6g``): its ``num`` function run by node on values a laid-out viewport and an
effective far plane give (299.06542056074767 printed 299.065, 100000 kept 100000)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

PAGE_JS = Path(__file__).resolve().parent.parent / "xaml3d" / "export" / "page.js"
NODE = shutil.which("node") or shutil.which("nodejs")
VALUES = [299.06542056074767, 1.9403099548670644, 100000.0, 200000.0, 1e-05, 0.0001,
          123456.7, 1234567.0, -0.0125, 0.5, 2.0, 1e21, 4.875e-05, 0.999999949, 9.9999996,
          120.0, 1.5e-07, -3e10, 0.1 + 0.2, 0.0, -0.0]  # fmt: skip


@pytest.mark.skipif(NODE is None, reason="node is absent (.ci/run installs it with npm)")
def test_page_num_prints_like_python_g6():
    source = PAGE_JS.read_text("utf-8")
    (num,) = re.findall(r"^function num\(x\) \{.*?^\}", source, flags=re.S | re.M)
    script = f"{num}\nconsole.log(JSON.stringify({json.dumps(VALUES)}.map(num)));"
    out = subprocess.run([NODE, "-e", script], capture_output=True, timeout=60, check=True)
    got = json.loads(out.stdout)
    assert got == [f"{x:.6g}" if x != 0 else "0" for x in VALUES]
    assert got[:4] == ["299.065", "1.94031", "100000", "200000"]
