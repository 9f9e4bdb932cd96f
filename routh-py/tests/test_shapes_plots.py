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
    """verdicts[j][i] is at (x[i], y[j]), and the plot draws it there."""
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


# --- The one style of both renderers (routh::style), and what the figures draw -------------------


def _mpl():
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.colors as mcolors
    import matplotlib.pyplot as plt

    return plt, mcolors


def test_plot_style_is_one_table_with_told_apart_verdicts():
    style = routh.plot_style()
    verdicts = style["verdict"]
    assert set(verdicts) == set(routh.VERDICTS)
    assert set(style["event"]) == set(routh.EVENT_KINDS)
    assert set(style["orbit_verdict"]) == set(routh.ORBIT_STABILITIES)
    okabe_ito = {"#000000", "#E69F00", "#56B4E9", "#009E73", "#F0E442", "#0072B2", "#D55E00",
                 "#CC79A7"}
    looks = list(verdicts.values())
    for i, a in enumerate(looks):
        assert a["color"] in okabe_ito
        for b in looks[i + 1:]:
            # Told apart in colour, and without colour by width or dashes, and in an atlas by hatch.
            assert a["color"] != b["color"]
            assert (a["width"], a["dash"]) != (b["width"], b["dash"])
            assert a["hatch"] != b["hatch"]
    assert 7 <= style["font"]["annotation"] <= style["font"]["label"]
    # A journal's column, 3.4 in (the Rust figures' PlotOptions::column()).
    assert style["column_width"] == 3.4


def test_diagram_colours_legend_and_axes_follow_the_style(top):
    plt, mcolors = _mpl()
    from routh._plot import THE_STYLE

    d = top.bifurcation_diagram((0.0, 5.0))
    ax = d.plot()
    assert ax.get_xlabel() == "p_ψ"
    assert ax.get_ylabel() == "γ₃ (cosine of the tilt)"
    label_of = {v["label"]: k for k, v in THE_STYLE["verdict"].items()}
    legend = ax.figure.legends[0] if ax.figure.legends else ax.get_legend()
    listed = {t.get_text() for t in legend.get_texts()}
    drawn = set()
    for line in ax.get_lines():
        colour = mcolors.to_hex(line.get_color()).upper()
        for key, look in THE_STYLE["verdict"].items():
            if colour == look["color"] and len(line.get_xdata()) > 1:
                drawn.add(key)
                assert line.get_linewidth() == look["width"], key
    # The legend lists the verdicts drawn and no other.
    assert {label_of[t] for t in listed if t in label_of} == drawn
    assert drawn == {"secularly_stable", "gyroscopically_stabilized", "unstable", "degenerate"} - {
        "degenerate"} | ({"degenerate"} & drawn)
    plt.close("all")


def test_circles_drawn_with_their_classify_circle_verdict(top):
    plt, mcolors = _mpl()
    from routh._plot import THE_STYLE, plot_diagram

    d = top.bifurcation_diagram((0.0, 5.0))
    circles = [b for b in d.branches if not b.isolated]
    assert circles and all(set(b.verdicts) == {"degenerate"} for b in circles)
    ax = plot_diagram(d, circles=top)
    degenerate = THE_STYLE["verdict"]["degenerate"]["color"]
    stable = THE_STYLE["verdict"]["secularly_stable"]["color"]
    ringed = [l for l in ax.get_lines() if l.get_marker() == "o" and len(l.get_xdata()) > 1]
    assert ringed
    # The tilted circles of the Lagrange top beyond the branch point are stable modulo the
    # symmetry (the doubly amended potential has a minimum there: test_api checks it).
    assert all(mcolors.to_hex(l.get_color()).upper() != degenerate for l in ringed)
    assert any(mcolors.to_hex(l.get_color()).upper() == stable for l in ringed)
    plt.close("all")


def test_event_labels_do_not_overlap_and_carry_values(gyrostat):
    plt, _ = _mpl()
    from routh._plot import plot_diagram

    d = gyrostat.bifurcation_diagram((0.0, 5.0))
    assert len(d.events) >= 2
    ax = plot_diagram(d, values=True, xlabel="p_ψ (kg m² s⁻¹)")
    assert ax.get_xlabel() == "p_ψ (kg m² s⁻¹)"
    fig = ax.figure
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    texts = [t for t in ax.texts if t.get_text()]
    assert texts and all(" at " in t.get_text() for t in texts)
    # Mirror-image events (the same kind at the same point) are named once.
    assert len({t.get_text() for t in texts}) == len(texts)
    from matplotlib.text import Text

    # The texts' own boxes (an annotation's extent takes in its leader line too).
    boxes = [Text.get_window_extent(t, r) for t in texts]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not a.overlaps(b), (a, b)
    plt.close("all")


def test_atlas_has_a_legend_of_what_it_draws_and_named_axes(top):
    plt, _ = _mpl()
    from routh._plot import THE_STYLE, plot_atlas

    atlas = routh.stability_atlas(lambda mgl, p: (top.with_params(mgl=mgl), p), [0, 0, 1],
                                  (0.5, 2.0), (0.5, 5.0), nx=9, ny=9)
    ax = plot_atlas(atlas, xlabel="mgl", ylabel="p_ψ")
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("mgl", "p_ψ")
    legend = ax.figure.legends[0] if ax.figure.legends else ax.get_legend()
    listed = {t.get_text() for t in legend.get_texts()}
    # A verdict at a node or two alone shows as no region, and is not listed.
    cells = [v for row in atlas.verdicts for v in row if v is not None]
    present = {v for v in set(cells) if cells.count(v) >= max(2, 81 // 500)}
    assert {THE_STYLE["verdict"][v]["label"] for v in present} <= listed
    absent = set(routh.VERDICTS) - present
    assert not {THE_STYLE["verdict"][v]["label"] for v in absent} & listed
    kinds = {b.kind for b in atlas.boundaries}
    assert {THE_STYLE["boundary"][k]["label"] for k in kinds} <= listed
    plt.close("all")


def test_figures_save_as_pdf_png_and_svg_at_column_width(top, tmp_path):
    plt, _ = _mpl()
    d = top.bifurcation_diagram((0.0, 5.0))
    ax = d.plot()
    w, _h = ax.figure.get_size_inches()
    assert abs(w - routh.plot_style()["column_width"]) < 1e-9
    for ext in ("pdf", "png", "svg"):
        path = tmp_path / f"d.{ext}"
        ax.figure.savefig(path)
        assert path.stat().st_size > 1000
    assert (tmp_path / "d.pdf").read_bytes().startswith(b"%PDF")
    plt.close("all")


def test_mirror_image_events_are_named_once_and_crowded_labels_kept_apart():
    plt, _ = _mpl()
    from matplotlib.text import Text

    from routh._plot import _axes, place_labels

    ax = _axes(None)
    ax.plot([0.0, 1.0], [0.0, 1.0], color="k")
    # Two mirror images (same name, same point) and six events a hair apart.
    items = [(0.5, 0.5, "fold"), (0.5, 0.5, "fold")]
    items += [(0.3 + 0.004 * k, 0.3, f"branch point {k}") for k in range(6)]
    texts = place_labels(ax, items)
    assert [t.get_text() for t in texts].count("fold") == 1
    assert len(texts) == 7
    fig = ax.figure
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    boxes = [Text.get_window_extent(t, r) for t in texts]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not a.overlaps(b), (a, b)
    plt.close("all")


def test_section_plot_has_no_title_unless_asked_and_names_its_level():
    """The Poincaré section as the Rust SVG: no title by default (a journal's caption goes below
    the figure), (p_ψ, E) in the legend with a true minus sign; a title when given (to
    ``routh._plot.plot_section``)."""
    plt, _ = _mpl()
    body = routh.Model("kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
                       {"inertia": [1.0, 2.0, 3.0], "mgl": 1.5})
    s = body.poincare_section(0.0, -1.0, orbits=2, crossings=5)
    ax = s.plot()
    assert ax.get_title() == ""
    texts = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any(t.startswith("p_ψ = 0, E = −1") for t in texts), texts
    plt.close(ax.figure)
    from routh._plot import plot_section

    ax = plot_section(s, title="A section")
    assert ax.get_title() == "A section"
    plt.close(ax.figure)
