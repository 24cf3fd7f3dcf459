"""`import trigspline` registers the xarray accessor when xarray is installed,
and works without xarray (the accessor is then absent)."""
import subprocess
import sys


def _run(code):
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)


def test_accessor_registered_by_import_trigspline():
    p = _run("import trigspline, xarray as xr, numpy as np\n"
             "da = xr.DataArray(np.array([0.0, 1.0, 4.0]), dims='t', coords={'t': [0.0, 1.0, 2.0]})\n"
             "print(hasattr(da, 'trigspline'))\n"
             "print(float(da.trigspline.interp(t=[0.5], shape='positive')[0]) >= 0)")
    assert p.returncode == 0, p.stderr
    assert p.stdout.split() == ["True", "True"]


def test_import_without_xarray():
    # xarray made unimportable: the package imports, nothing registers
    p = _run("import sys\nsys.modules['xarray'] = None\nimport trigspline\n"
             "print('xarray' in sys.modules and sys.modules['xarray'] is None)\n"
             "print(trigspline.Spline([0, 1, 2], [1.0, 2.0, 1.5])(0.5) > 0)")
    assert p.returncode == 0, p.stderr
    assert p.stdout.split() == ["True", "True"]
