"""docs/tutorial.md runs: its ```python blocks, in order, as one script in a
fresh directory; then its outputs are checked (the figures, the netCDF file)
against what the page says."""
import os
import re

import numpy as np
import pytest

from conftest import REPO

for mod in ("pandas", "xarray", "matplotlib"):
    pytest.importorskip(mod, reason="installed by make test (python-deps)")

TUTORIAL = os.path.join(REPO, "docs", "tutorial.md")


def blocks(path):
    text = open(path, encoding="utf-8").read()
    return re.findall(r"^```python\n(.*?)^```$", text, flags=re.S | re.M)


@pytest.mark.filterwarnings("ignore:numpy.ndarray size changed")  # netCDF4 on import
def test_the_tutorial_runs(tmp_path, monkeypatch):
    import xarray as xr
    code = blocks(TUTORIAL)
    assert len(code) >= 8
    monkeypatch.chdir(tmp_path)
    ns = {"__name__": "__tutorial__"}
    for i, block in enumerate(code):
        exec(compile(block, "%s (block %d)" % (TUTORIAL, i + 1), "exec"), ns)
    import matplotlib.pyplot as plt
    plt.close("all")
    # what the text promises
    assert ns["s"].certified and ns["srf"].certified
    assert int(ns["hourly"].isna().sum()) == 5 and ns["hourly"].min() >= 0
    for png in ("rain_hourly.png", "cloud_cover.png"):
        with open(tmp_path / png, "rb") as fh:
            assert fh.read(8) == b"\x89PNG\r\n\x1a\n"
    with xr.open_dataarray(tmp_path / "cloud_cover_fine.nc") as da:
        v = da.values
        assert da.attrs["units"] == "%" and v.shape == (61, 91)
        assert v.min() >= 0 and v.max() <= 100
        # the field touches both bounds (the data hold 0 and 100) and the knots come back
        assert v.min() == 0 and v.max() == 100
        np.testing.assert_array_equal(v[::10, ::10], ns["cover"].T)
