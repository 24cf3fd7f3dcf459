"""scripts/gallery.py (the gallery of make demo): it runs, every figure is
written, and every figure is shown with the code that made it (the code on
the page is the code that ran: each entry's text is executed)."""
import html
import os
import re
import subprocess
import sys

import pytest

from conftest import REPO

for mod in ("pandas", "xarray", "matplotlib"):
    pytest.importorskip(mod, reason="installed by make test (python-deps)")

SCRIPT = os.path.join(REPO, "scripts", "gallery.py")


@pytest.mark.filterwarnings("ignore")
def test_gallery_page(tmp_path):
    out = tmp_path / "gallery"
    r = subprocess.run([sys.executable, SCRIPT, str(out)], cwd=REPO, capture_output=True,
                       text=True)
    assert r.returncode == 0, r.stderr
    page = (out / "index.html").read_text(encoding="utf-8")
    figures = re.findall(r'<figure id="([a-z_]+)">.*?<img src="([a-z_]+)\.png" alt="[^"]+">'
                         r'.*?<pre><code>(.*?)</code></pre></figure>', page, flags=re.S)
    assert len(figures) >= 6
    for name, img, code in figures:
        assert name == img
        with open(out / (img + ".png"), "rb") as fh:
            assert fh.read(8) == b"\x89PNG\r\n\x1a\n"
        code = html.unescape(code)
        assert "trigspline" in code and "fig" in code
        compile(code, name, "exec")
    assert "<script" not in page
    # the two figure kinds of the package: a heatmap and a date axis
    names = [f[0] for f in figures]
    assert "percent_surface" in names and "rain_dates" in names
