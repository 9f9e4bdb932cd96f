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
EVENT_MARK = {"fold": "o", "branch_point": "s", "hamiltonian_hopf": "D"}
EVENT_NAME = {"fold": "fold", "branch_point": "branch point", "hamiltonian_hopf": "Hamiltonian–Hopf"}


def _axes(ax):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots()
    return ax


def plot_diagram(diagram, ax=None, component=2):
    """Draw `diagram` (s against γ[component]) on `ax` (a new one if None); returns the axes."""
    ax = _axes(ax)
    seen = set()
    for b in diagram.branches:
        s, g, v = b.s, b.gamma[:, component], b.verdicts
        start = 0
        for i in range(1, len(v) + 1):
            if i == len(v) or v[i] != v[start]:
                colour, ls = STYLE[v[start]]
                hi = min(i + 1, len(v))
                label = v[start].replace("_", " ") if v[start] not in seen else None
                seen.add(v[start])
                ax.plot(s[start:hi], g[start:hi], color=colour, linestyle=ls, label=label)
                start = i
    for e in diagram.events:
        ax.plot([e.s], [e.gamma[component]], marker=EVENT_MARK[e.kind], color="k", linestyle="none")
        ax.annotate(EVENT_NAME[e.kind], (e.s, e.gamma[component]), textcoords="offset points",
                    xytext=(4, 4), fontsize=8)
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
    codes = np.full((len(atlas.y), len(atlas.x)), np.nan)
    for i, col in enumerate(atlas.verdicts):
        for j, v in enumerate(col):
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


def svg_of(result):
    """The SVG text of `result.plot()` (for Jupyter's `_repr_svg_`)."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4))
    result.plot(ax=ax)
    buf = io.StringIO()
    fig.savefig(buf, format="svg")
    plt.close(fig)
    return buf.getvalue()
