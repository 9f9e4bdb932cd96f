"""Periodic motions of a heavy asymmetric body from Python (as examples/periodic.rs): the
swings born at the hanging position (a Lyapunov family), where they are stable against
out-of-plane perturbations, their period against the energy, the orbits of twice the period born
at a period doubling, and a Poincaré section with the family's orbit as a fixed point.

    pip install ./routh-py matplotlib && python examples/python/periodic.py [OUT_DIR]
"""

import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import routh  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
out = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out, exist_ok=True)

# Principal moments (1, 3, 6) about the fixed point, centre of mass off the axes.
body = routh.Model.from_file(os.path.join(here, "..", "models", "asymmetric_top.toml"))
hanging = min(body.steady_motions(0.0), key=lambda s: s.energy)
print(f"hanging position: gamma = {hanging.gamma.round(6)}, E = {hanging.energy:.6f}")

family = body.lyapunov_family(hanging, 0, max_orbits=60)
print(f"{len(family)} orbits, ended: {family.stop}")
for e in family.events:
    print(f"  {e.kind:16s} at E = {e.energy:+.9f}  T = {e.orbit.period:.6f}  {e.before} -> {e.after}")

# The energy intervals where the swing is elliptic (linearly stable out of the plane).
runs, start = [], None
for e, s in zip(family.energy, family.stability):
    if s == "elliptic" and start is None:
        start = e
    if s != "elliptic" and start is not None:
        runs.append((start, prev))
        start = None
    prev = e
if start is not None:
    runs.append((start, prev))
print("stable swings for E in", ", ".join(f"[{a:.4f}, {b:.4f}]" for a, b in runs))

fig, (k_ax, t_ax) = plt.subplots(1, 2, figsize=(10, 4))
family.plot(ax=k_ax)
family.plot(ax=t_ax, quantity="period")
fig.tight_layout()
fig.savefig(os.path.join(out, "periodic_family.png"), dpi=120)

doubling = [e for e in family.events if e.kind == "period_doubling"]
if doubling:
    d = body.period_doubled_family(doubling[0], max_orbits=20)
    print(f"period doubling at E = {doubling[0].energy:.9f}: {len(d)} orbits of period "
          f"{d.orbits[0].period:.6f} (2T = {2 * doubling[0].orbit.period:.6f})")

# The plane through the hanging position that the swings cross: γ·n = 0 with n the body's
# second axis made orthogonal to the hanging γ.
g = hanging.gamma
n = np.array([0.0, 1.0, 0.0]) - g[1] * g
orbit = family.orbits[len(family.orbits) // 4]
section = body.poincare_section(0.0, orbit.energy, normal=n, orbits=40, crossings=150)
fixed = body.orbit_crossings(orbit, normal=n)
print(f"the orbit at E = {orbit.energy:.6f} ({orbit.stability}) crosses the section at {fixed.round(6).tolist()}")
fig, ax = plt.subplots(figsize=(6, 5))
section.plot(ax=ax, fixed_points=fixed)
fig.tight_layout()
fig.savefig(os.path.join(out, "periodic_section.png"), dpi=120)
print(f"wrote {out}/periodic_family.png and {out}/periodic_section.png")
