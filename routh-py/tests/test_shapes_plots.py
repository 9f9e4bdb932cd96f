"""numpy shapes and dtypes, reprs, figures, and the notebook-style example end to end."""

import os
import subprocess
import sys

import numpy as np
import pytest

import routh
from conftest import ROOT


def test_report_shapes(top):
    m = top.steady_motions(2.2)[0]
    assert m.gamma.shape == (3,) and m.gamma.dtype == np.float64
    r = top.classify(m)
    assert r.restricted_hessian_eigenvalues.shape == (2,)
    assert r.restricted_hessian_eigenvalues.dtype == np.float64
    assert r.f2_roots.shape == (4,) and r.f2_roots.dtype == np.complex128
    assert isinstance(r.degree_of_instability, int)
    assert "StabilityReport" in repr(r) and "SteadyMotion" in repr(m)


def test_gil_released_during_work(top):
    # A Python thread can only run while the diagram is computed if the GIL is released:
    # some of its timestamps fall strictly inside the call.
    import threading
    import time

    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            stop.wait(0.001)

    t = threading.Thread(target=ticker)
    t.start()
    time.sleep(0.01)
    t0 = time.perf_counter()
    top.bifurcation_diagram((0.0, 5.0))
    t1 = time.perf_counter()
    stop.set()
    t.join()
    assert any(t0 < x < t1 for x in ticks), (t1 - t0, len(ticks))


def test_plots_and_svg(top):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    d = top.bifurcation_diagram((0.0, 5.0))
    ax = d.plot()
    styles = {l.get_linestyle() for l in ax.get_lines()}
    assert "--" in styles and "-" in styles  # unstable dashed, stable solid
    names = {t.get_text() for t in ax.texts}
    assert {"Hamiltonian–Hopf", "branch point"} <= names
    svg = d._repr_svg_()
    assert svg.lstrip().startswith("<?xml") and "<svg" in svg
    base = top
    atlas = routh.stability_atlas(lambda mgl, p: (base.with_params(mgl=mgl), p), [0, 0, 1],
                                  (0.5, 2.0), (0.5, 5.0), nx=6, ny=6)
    assert atlas.plot() is not None
    assert "<svg" in atlas._repr_svg_()


def test_atlas_plot_places_each_cell_on_square_and_non_square_grids(top):
    """verdicts[j][i] is at (x[i], y[j]), and the plot draws it there (issue 34)."""
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    from routh._plot import STYLE

    names = list(STYLE)
    for nx, ny in [(6, 6), (7, 4), (3, 9)]:
        atlas = routh.stability_atlas(lambda mgl, p: (top.with_params(mgl=mgl), p), [0, 0, 1],
                                      (0.5, 2.0), (0.5, 5.0), nx=nx, ny=ny)
        assert len(atlas.verdicts) == ny and all(len(r) == nx for r in atlas.verdicts)
        assert len(atlas.lost) == ny and all(len(r) == nx for r in atlas.lost)
        # (mgl, p) = (0.5, 5): secularly stable (p² > 6.25 mgl); (2, 0.5): unstable.
        assert atlas.verdicts[ny - 1][0] == "secularly_stable"
        assert atlas.verdicts[0][nx - 1] == "unstable"
        ax = atlas.plot()
        codes = np.asarray(ax.collections[0].get_array()).reshape(ny, nx)
        assert codes[ny - 1, 0] == names.index("secularly_stable")
        assert codes[0, nx - 1] == names.index("unstable")
        for j in range(ny):
            for i in range(nx):
                v = atlas.verdicts[j][i]
                if v is not None:
                    assert codes[j, i] == names.index(v)
        import matplotlib.pyplot as plt

        plt.close("all")


def test_nonlinear_diagram_plots_its_resonances(top):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    d = top.bifurcation_diagram((0.0, 5.0), nonlinear=True)
    ax = d.plot()
    names = {t.get_text() for t in ax.texts}
    kinds = {e.kind for e in d.events}
    assert "resonance" in kinds or "arnold_degenerate" in kinds, kinds
    assert "Hamiltonian–Hopf" in names


def test_example_script_end_to_end(tmp_path):
    pytest.importorskip("matplotlib")
    env = dict(os.environ, MPLBACKEND="Agg", ROUTH_FIGURE=str(tmp_path / "d.png"))
    r = subprocess.run([sys.executable, str(ROOT / "examples" / "python" / "heavy_top.py")],
                       capture_output=True, text=True, timeout=300, env=env)
    assert r.returncode == 0, r.stderr
    assert "hamiltonian_hopf at p_psi = 2.0000" in r.stdout
    assert "branch_point at p_psi = 2.5000" in r.stdout
    assert "gyroscopically_stabilized" in r.stdout
    assert "U_r = " in r.stdout and "nutation between" in r.stdout
    assert (tmp_path / "d.png").stat().st_size > 1000


def test_progress_flag_and_packaged_stubs(top):
    import pathlib

    d = routh.bifurcation_diagram(lambda s: (top, s), (0.0, 5.0), progress=True)
    assert len(d.events) == 2
    pkg = pathlib.Path(routh.__file__).parent
    assert (pkg / "py.typed").exists() and (pkg / "__init__.pyi").exists()


@pytest.mark.parametrize("doc", ["README.md", "docs/python.md"])
def test_documented_python_runs(doc, capsys, monkeypatch):
    # The notebook-style examples of the README and the guide, executed as written.
    pytest.importorskip("matplotlib")
    import re

    import matplotlib

    matplotlib.use("Agg")
    blocks = re.findall(r"```python\n(.*?)```", (ROOT / doc).read_text(), re.S)
    monkeypatch.chdir(ROOT)  # the blocks name files from the repository's root
    assert blocks
    for code in blocks:
        exec(compile(code, doc, "exec"), {})
    out = capsys.readouterr().out
    assert "gyroscopically_stabilized" in out
