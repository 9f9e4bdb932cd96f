"""The heavy (Lagrange) top from Python: its steady motions, their stability, and the
bifurcation diagram over the cyclic momentum (as examples/heavy_top.rs).

    pip install ./routh-py matplotlib && python examples/python/heavy_top.py
"""

import os

import matplotlib

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

ax = d.plot()
ax.set_xlabel("p_psi")
out = os.environ.get("ROUTH_FIGURE", "heavy_top_diagram.png")
plt.savefig(out)
print(f"diagram written to {out}")
