"""A stability map over two inertia ratios, computed by `routh.study` on a local Dask cluster:
the heavy body J = diag(A, B, C) (A = 1), centre of mass on its third axis (m g l = 1), spinning
upright (γ = e₃) with cyclic momentum p_ψ = 2.5; the verdict of that steady motion over
(B/A, C/A). Where B = A the body is a Lagrange top: Maievskii's bound p² = 4·A·mgl holds for
every C, and its secular bound p² = mgl·C²/(C − A) gives the change from secular to gyroscopic
stability along that line.

    pip install './routh-py[dask]' matplotlib
    python examples/python/study.py [map.png] [--n 41] [--address tcp://host:8786]

Without `--address` the study runs on a LocalCluster of 2 worker processes on this machine.
"""

import argparse

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

import routh  # noqa: E402

P_PSI = 2.5


def upright(model, p_psi, **_):
    """The verdict of the upright steady motion γ = e₃ at p_ψ."""
    m = [s for s in model.steady_motions(p_psi) if abs(s.gamma[2] - 1) < 1e-9][0]
    return model.classify(m)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("png", nargs="?", default="study.png", help="the figure (default study.png)")
    ap.add_argument("--n", type=int, default=41, help="points per axis (default 41)")
    ap.add_argument("--address", default=None, help="a Dask scheduler's address")
    a = ap.parse_args()

    body = routh.Model(
        "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
        {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0},
    )
    b = np.linspace(0.5, 2.0, a.n)
    c = np.linspace(0.5, 2.0, a.n)
    # The inertia is a 3-vector parameter: the points are the bodies (1, B, C), and p_psi.
    points = [{"inertia": [1.0, bb, cc], "p_psi": P_PSI} for bb in b for cc in c]
    df = routh.study(upright, body, points, client=a.address)
    print(df["verdict"].value_counts(dropna=False).to_string())
    print("failed points:", int(df["error"].notna().sum()))

    names = list(routh.VERDICTS)
    code = df["verdict"].map({v: i for i, v in enumerate(names)}).fillna(-1).to_numpy()
    grid = code.reshape(len(b), len(c)).T  # rows: C/A, columns: B/A
    colours = ["#bbbbbb", "#1b9e77", "#7570b3", "#d95f02", "#e7298a"]  # failed, then VERDICTS
    fig, ax = plt.subplots(figsize=(6.4, 5.2))
    ax.pcolormesh(b, c, grid, cmap=ListedColormap(colours), vmin=-1.5, vmax=len(names) - 0.5,
                  shading="nearest")
    # The physical bodies satisfy the triangle inequalities C <= A + B, B <= A + C.
    ax.plot(b, 1 + b, "k--", lw=1, label="C = A + B")
    ax.plot(b[b >= 1.5], b[b >= 1.5] - 1, "k:", lw=1, label="B = A + C")
    handles = [plt.Rectangle((0, 0), 1, 1, color=colours[i + 1]) for i in range(len(names))]
    ax.legend(handles + ax.get_lines(), names + ["C = A + B", "B = A + C"], fontsize=8,
              loc="upper right", framealpha=0.9)
    ax.set_xlim(b[0], b[-1])
    ax.set_ylim(c[0], c[-1])
    ax.set_xlabel("B / A")
    ax.set_ylabel("C / A")
    ax.set_title(f"upright body, mgl = 1, p_ψ = {P_PSI}: verdict of γ = e₃ ({len(df)} bodies)")
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("wrote", a.png)


if __name__ == "__main__":
    main()
