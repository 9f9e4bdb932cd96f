"""The heavy (Lagrange) top from Python: its steady motions, their stability, the bifurcation
diagram over the cyclic momentum (as examples/heavy_top.rs), its amended potential in LaTeX,
and the apex locus of a fast top.

    pip install ./routh-py matplotlib && python examples/python/heavy_top.py
"""

import os

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import routh  # noqa: E402

# A₁ = 1, C = 1.25, m g l = 1: Maievskii's bound p² = 4A₁mgl (p = 2), the secular bound
# p² = mglC²/(C − A₁) (p = 2.5).
top = routh.Model(
    "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
    {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0},
)
for p in (1.5, 2.2, 3.0):
    for m in top.steady_motions(p):
        r = top.classify(m)
        print(f"p_psi = {p:4.1f}  gamma = {m.gamma.round(6)}  psi_dot = {m.psi_dot:8.5f}  "
              f"{r.verdict} (degree {r.degree_of_instability})")

d = top.bifurcation_diagram((0.0, 5.0))
for e in d.events:
    print(f"{e.kind} at p_psi = {e.s:.8f}: {e.before} -> {e.after}")

print("U_r =", top.latex().amended_potential)

# A fast top released with a small transverse spin: its apex loops (Goldstein §5.7).
tr = top.simulate_full([0.0, 0.3, 5.0], [0.6, 0.0, 0.8], 10.0, attitude=True,
                       times=np.linspace(0.0, 10.0, 2001))
psi, theta, _ = tr.euler_angles().T
print(f"nutation between {np.degrees(theta.min()):.2f} and {np.degrees(theta.max()):.2f} deg, "
      f"precession {np.degrees(psi[-1] - psi[0]):.1f} deg in t = 10, "
      f"energy drift {abs(tr.energy - tr.energy[0]).max():.1e}")

fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5))
d.plot(ax=left)
left.set_xlabel("p_psi")
left.set_title("heavy top: steady motions over p_psi")
tr.plot_apex(ax=right)
right.set_title("apex locus (seen from above)")
fig.tight_layout()
out = os.environ.get("ROUTH_FIGURE", "heavy_top_diagram.png")
fig.savefig(out)
print(f"diagram written to {out}")
