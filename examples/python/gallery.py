"""Every kind of matplotlib figure of routh, written as PNG (300 dpi) and PDF at a journal's
column width, for docs/gallery.md:

    python examples/python/gallery.py docs/figures

(after ``pip install ./routh-py matplotlib``). The figures are those of the Rust gallery's
examples, drawn by the Python package in the same style (``routh.plot_style()``).
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import routh  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
OUT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python_gallery")
OUT.mkdir(parents=True, exist_ok=True)
BODY = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z"


def save(ax, name):
    for ext in ("png", "pdf"):
        ax.figure.savefig(OUT / f"python_{name}.{ext}", dpi=300)
    plt.close(ax.figure)
    print(OUT / f"python_{name}.png")


# The Lagrange top of examples/heavy_top.rs: A₁ = 1, C = 1.25, mgl = 1.
top = routh.Model(BODY, {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
d = top.bifurcation_diagram((0.0, 5.0))
save(d.plot(values=True, circles=top), "bifurcation_diagram")

atlas = routh.stability_atlas(lambda mgl, p: (top.with_params(mgl=mgl), p), [0, 0, 1],
                              (0.25, 2.0), (0.0, 5.0), nx=36, ny=41)
save(atlas.plot(xlabel="weight × distance mgl", ylabel="cyclic momentum p_ψ"), "atlas")

# Mode 0 of a heavy asymmetric top, its centre of mass off the axes (examples/periodic.rs).
asym = routh.Model.load(ROOT / "examples" / "models" / "asymmetric_top.toml")
hanging = min(asym.steady_motions(0.0), key=lambda s: s.energy)
family = asym.lyapunov_family(hanging, 0, max_orbits=60)
save(family.plot(), "orbit_family")
save(family.plot(quantity="period"), "orbit_periods")

# A Poincaré section of the heavy asymmetric body J = diag(1, 2, 3), mgl = 1.5.
body = routh.Model(BODY, {"inertia": [1.0, 2.0, 3.0], "mgl": 1.5})
swing = body.periodic_orbit([0, 0, 0], [0, np.sin(1.0), -np.cos(1.0)], 2 * np.pi / np.sqrt(1.5))
section = body.poincare_section(swing.p_psi, swing.energy, normal=[0, 1, 0], orbits=8,
                                crossings=60)
save(section.plot(), "section")

# The looping apex locus of a fast top (examples/heavy_top.rs).
fast = routh.Model(BODY, {"inertia": [1.0, 1.0, 0.6], "mgl": 1.0})
theta0, spin = 0.5, 6.0
slow = 1.0 / (0.6 * spin)
tr = fast.simulate([0.0, -slow * np.sin(theta0), spin], [0.0, np.sin(theta0), np.cos(theta0)],
                   6.0, attitude=True, times=np.linspace(0.0, 6.0, 3001))
save(tr.plot_apex(), "apex_locus")
