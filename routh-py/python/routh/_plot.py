"""Matplotlib figures of routh's results, in the styles of the Rust SVGs: stable solid,
unstable dashed, events marked and named. Imported lazily (matplotlib is optional)."""

import io

import numpy as np

#: Colour and line style of each verdict (as routh::plot).
STYLE = {
    "secularly_stable": ("#1f77b4", "-"),
    "gyroscopically_stabilized": ("#2ca02c", "-"),
    "unstable": ("#d62728", "--"),
    "degenerate": ("#7f7f7f", ":"),
}
EVENT_MARK = {"fold": "o", "branch_point": "s", "hamiltonian_hopf": "D",
              "arnold_degenerate": "^", "resonance": "v"}
EVENT_NAME = {"fold": "fold", "branch_point": "branch point", "hamiltonian_hopf": "Hamiltonian–Hopf",
              "arnold_degenerate": "Arnold D = 0", "resonance": "resonance"}


def _axes(ax):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots()
    return ax


def _runs(ax, x, y, names, style, seen):
    """Draw `y` against `x` in runs of equal `names[i]`, each run in `style[name]` (colour, line
    style) and joined to the next; a name is put in the legend once (`seen` collects them)."""
    start = 0
    for i in range(1, len(names) + 1):
        if i == len(names) or names[i] != names[start]:
            colour, ls = style[names[start]]
            hi = min(i + 1, len(names))
            label = names[start].replace("_", " ") if names[start] not in seen else None
            seen.add(names[start])
            ax.plot(x[start:hi], y[start:hi], color=colour, linestyle=ls, label=label)
            start = i


def plot_diagram(diagram, ax=None, component=2):
    """Draw `diagram` (s against γ[component]) on `ax` (a new one if None); returns the axes."""
    ax = _axes(ax)
    seen = set()
    for b in diagram.branches:
        _runs(ax, b.s, b.gamma[:, component], list(b.verdicts), STYLE, seen)
    # Names alternate above and below their marks, so that close events stay readable.
    for k, e in enumerate(sorted(diagram.events, key=lambda e: e.s)):
        ax.plot([e.s], [e.gamma[component]], marker=EVENT_MARK[e.kind], color="k", linestyle="none")
        ax.annotate(EVENT_NAME[e.kind], (e.s, e.gamma[component]), textcoords="offset points",
                    xytext=(4, 6) if k % 2 == 0 else (4, -14), fontsize=8)
    ax.set_xlabel("s")
    ax.set_ylabel(f"γ{component + 1}")
    if seen:
        ax.legend(fontsize=8)
    return ax


def plot_atlas(atlas, ax=None):
    """Draw `atlas`: verdict regions coloured, boundary curves drawn and named."""
    from matplotlib.colors import ListedColormap

    ax = _axes(ax)
    names = list(STYLE)
    # verdicts[j][i] is at (x[i], y[j]): row j of `codes` is y[j], as pcolormesh reads it.
    codes = np.full((len(atlas.y), len(atlas.x)), np.nan)
    for j, row in enumerate(atlas.verdicts):
        for i, v in enumerate(row):
            if v is not None:
                codes[j, i] = names.index(v)
    cmap = ListedColormap([STYLE[n][0] for n in names])
    ax.pcolormesh(atlas.x, atlas.y, codes, cmap=cmap, vmin=-0.5, vmax=len(names) - 0.5,
                  shading="nearest", alpha=0.35)
    for b in atlas.boundaries:
        if len(b.points):
            ax.plot(b.points[:, 0], b.points[:, 1], "k-", lw=1.2)
            mid = b.points[len(b.points) // 2]
            ax.annotate(EVENT_NAME[b.kind], mid, fontsize=8)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    return ax


def svg_of(result, method="plot", size=(6, 4)):
    """The SVG text of ``result.<method>(ax=...)`` (for Jupyter's ``_repr_svg_``), drawn on a
    figure that is not left open in pyplot (no second copy shows in a notebook)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=size)
    ax = fig.add_subplot()
    getattr(result, method)(ax=ax)
    buf = io.StringIO()
    fig.savefig(buf, format="svg")
    return buf.getvalue()


def apex_path(attitude, axis=(0.0, 0.0, 1.0)):
    """The points ``R(t) a`` in space of the body axis ``a`` along the attitudes, (n, 3).

    ``attitude`` is an (n, 4) array of unit quaternions in scipy's order (x, y, z, w), as
    ``Trajectory.attitude``; the rotation is ``a' = a + w t + v × t`` with ``t = 2 v × a``.
    """
    q = np.asarray(attitude, dtype=float)
    a = np.asarray(axis, dtype=float)
    norm = np.linalg.norm(a)
    if not (norm > 0 and np.isfinite(a).all()):
        raise ValueError(f"axis {axis!r} is not a finite non-zero vector")
    a = a / norm
    v, w = q[:, :3], q[:, 3:4]
    t = 2.0 * np.cross(v, a)
    return a + w * t + np.cross(v, t)


def plot_apex(trajectory, ax=None, axis=(0.0, 0.0, 1.0)):
    """Draw the apex locus of `trajectory` (which has an attitude) as the Rust SVG does
    (``routh::plot::apex_locus_svg``): the path in space of the body axis `axis` on the unit
    sphere, seen from above (x right, y up); the part on the upper hemisphere solid, below
    dotted; start a ring, end a filled dot; the horizon |(x, y)| = 1 dashed where it falls in the
    square, padded frame. Returns the axes."""
    pts = apex_path(trajectory.attitude, axis)
    if not np.isfinite(pts).all():
        raise ValueError("non-finite attitude")
    ax = _axes(ax)
    x0, x1 = pts[:, 0].min(), pts[:, 0].max()
    y0, y1 = pts[:, 1].min(), pts[:, 1].max()
    half = max(0.5 * max(x1 - x0, y1 - y0), 1e-3) * 1.1
    cx, cy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
    xr, yr = (cx - half, cx + half), (cy - half, cy + half)
    a = np.linspace(0.0, 2.0 * np.pi, 721)
    hx, hy = np.cos(a), np.sin(a)
    inside = (hx > xr[0]) & (hx < xr[1]) & (hy > yr[0]) & (hy < yr[1])
    if inside.any():
        ax.plot(hx, hy, color="#787878", linestyle="--", lw=1, label="horizon")
    upper = pts[:, 2] >= 0.0
    cuts = np.flatnonzero(np.diff(upper.astype(int))) + 1
    labelled = set()
    for run in np.split(np.arange(len(pts)), cuts):
        if len(run) == 0:
            continue
        up = bool(upper[run[0]])
        name = "upper hemisphere" if up else "lower hemisphere"
        label = None if name in labelled else name
        labelled.add(name)
        ax.plot(pts[run, 0], pts[run, 1], color="k", lw=2 if up else 1.5,
                linestyle="-" if up else ":", label=label)
    ax.plot([pts[0, 0]], [pts[0, 1]], marker="o", markersize=10, markerfacecolor="none",
            markeredgecolor="k", markeredgewidth=2, linestyle="none", label="start")
    ax.plot([pts[-1, 0]], [pts[-1, 1]], marker="o", markersize=7, color="k", linestyle="none",
            label="end")
    ax.set_xlim(*xr)
    ax.set_ylim(*yr)
    ax.set_aspect("equal")
    ax.set_xlabel("x (space, horizontal)")
    ax.set_ylabel("y (space, horizontal)")
    ax.legend(fontsize=8)
    return ax


#: Colour and line style of each orbit stability: those of routh::plot's orbit figures
#: (elliptic green solid, parabolic purple, hyperbolic red dashed, inverse hyperbolic orange
#: dotted), so that the two renderers agree.
ORBIT_STYLE = {
    "elliptic": ("#008237", "-"),
    "parabolic": ("#5a0082", "-"),
    "hyperbolic": ("#cd1e1e", "--"),
    "inverse_hyperbolic": ("#c86e00", ":"),
}
#: Event marks as the SVG: folds ▲, branch points ●, period doublings ◆.
ORBIT_EVENT_MARK = {"fold": "^", "branch_point": "o", "period_doubling": "D"}
ORBIT_EVENT_NAME = {"fold": "fold", "branch_point": "branch point", "period_doubling": "period doubling"}
def index_axis(k):
    """The stability index on the figure's vertical axis, as ``routh::plot::stability_index_axis``:
    ``k`` itself on [-1, 1], and one unit a decade beyond, ``±(1 + log10|k|)`` (k = ±10 at ±2,
    ±100 at ±3): near a separatrix k grows without bound, and what matters is where it crosses
    ±1."""
    k = np.asarray(k, dtype=float)
    big = np.abs(k) > 1
    out = k.copy()
    out[big] = np.sign(k[big]) * (1 + np.log10(np.abs(k[big])))
    return out


def _index_ticks(ax):
    lo, hi = ax.get_ylim()
    ticks, labels = [], []
    for t in range(int(np.floor(lo)), int(np.ceil(hi)) + 1):
        ticks.append(t)
        size = str(abs(t)) if abs(t) <= 1 else f"{10 ** (abs(t) - 1):g}"
        labels.append(("−" if t < 0 else "") + size)
    ax.set_yticks(ticks)
    ax.set_yticklabels(labels)


def plot_orbit_family(family, ax=None, quantity="stability_index"):
    """Draw a family of periodic orbits: ``quantity="stability_index"`` is the stability diagram
    (k against E on the axis of `index_axis`, the lines k = ±1 dotted, events marked and named);
    ``"period"`` is T against E. Elliptic parts solid, hyperbolic dashed. Returns the axes."""
    if quantity not in ("stability_index", "period"):
        raise ValueError(f"quantity must be 'stability_index' or 'period', got {quantity!r}")
    ax = _axes(ax)
    e = np.asarray(family.energy)
    y = np.asarray(getattr(family, quantity), dtype=float)
    if quantity == "stability_index":
        y = index_axis(y)
        for level in (-1.0, 1.0):
            ax.axhline(level, color="#555555", lw=0.8, linestyle=":")
    seen = set()
    _runs(ax, e, y, list(family.stability), ORBIT_STYLE, seen)
    for k, ev in enumerate(sorted(family.events, key=lambda ev: ev.energy)):
        yv = ev.orbit.stability_index if quantity == "stability_index" else ev.orbit.period
        if quantity == "stability_index":
            yv = float(index_axis([yv])[0])
        ax.plot([ev.energy], [yv], marker=ORBIT_EVENT_MARK[ev.kind], color="k", linestyle="none")
        ax.annotate(ORBIT_EVENT_NAME[ev.kind], (ev.energy, yv), textcoords="offset points",
                    xytext=(4, 6) if k % 2 == 0 else (4, -14), fontsize=8)
    ax.set_xlabel("E")
    ax.set_ylabel("k" if quantity == "stability_index" else "T")
    if quantity == "stability_index":
        _index_ticks(ax)
    if seen:
        ax.legend(fontsize=8)
    return ax


def plot_section(section, ax=None, fixed_points=None):
    """Draw a Poincaré section: each orbit's crossings as small dots of its own colour (θ against
    M_n), and `fixed_points` ((k, 2): a periodic orbit's crossings) as larger black marks.
    Returns the axes."""
    ax = _axes(ax)
    for pts in section.points:
        pts = np.asarray(pts)
        if len(pts):
            ax.plot(pts[:, 0], pts[:, 1], linestyle="none", marker=".", markersize=1.5)
    fp = None if fixed_points is None else np.asarray(fixed_points, dtype=float).reshape(-1, 2)
    if fp is not None and len(fp):
        ax.plot(fp[:, 0], fp[:, 1], linestyle="none", marker="x", markersize=8, color="k",
                label="periodic orbit")
        ax.legend(fontsize=8)
    ax.set_xlabel("θ")
    ax.set_ylabel("M_n")
    ax.set_title(f"p_ψ = {section.p_psi:g}, E = {section.energy:g}", fontsize=9)
    return ax
