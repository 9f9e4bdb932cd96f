"""Matplotlib figures of routh's results, drawn in the one style of routh's figures: the colours
(Okabe–Ito), line widths, dashes, markers and fonts are read from the extension module
(``routh.plot_style()``, the table ``routh::style`` of the Rust SVGs), so that the two renderers
agree and there is no second copy. Imported lazily (matplotlib is optional).

Every figure reads in monochrome: each verdict has its own stroke (thick solid, thin solid,
dashed, dotted; inverse hyperbolic orbits long-dashed) and each event its own marker; the
legend lists only what is drawn; event labels are placed clear of one another (and of the
markers and, where they can be, of the curves), on a leader line when they stand away from
their marker.
"""

import io

import numpy as np

from . import _routh

#: The style table of ``routh::style`` (``routh.plot_style()``).
THE_STYLE = _routh.plot_style()
VERDICTS = ("secularly_stable", "gyroscopically_stabilized", "unstable", "degenerate")


def _linestyle(look):
    """matplotlib's line style of a look: solid, or dashes in units of the line width."""
    if look["dash"] is None:
        return "-"
    on, off = look["dash"]
    w = look["width"]
    return (0, (on / w, off / w))


def _looks(group, names):
    return {n: (THE_STYLE[group][n]["color"], _linestyle(THE_STYLE[group][n])) for n in names}


#: Colour and line style of each verdict, in the order of the legend.
STYLE = _looks("verdict", VERDICTS)
#: The legend's name of each verdict.
VERDICT_LABEL = {n: THE_STYLE["verdict"][n]["label"] for n in VERDICTS}
#: Line width (points) of each verdict.
WIDTH = {n: THE_STYLE["verdict"][n]["width"] for n in VERDICTS}
EVENT_KINDS = ("fold", "branch_point", "hamiltonian_hopf", "arnold_degenerate", "resonance")
#: Marker of each event (``"O"`` in the table is an open circle).
EVENT_MARK = {k: THE_STYLE["event"][k]["marker"] for k in EVENT_KINDS}
EVENT_NAME = {k: THE_STYLE["event"][k]["label"] for k in EVENT_KINDS}
#: The default label of each component of γ on the vertical axis (as routh::plot::DiagramAxis).
GAMMA_LABEL = ("γ₁", "γ₂", "γ₃ (cosine of the tilt)")
FONT = THE_STYLE["font"]
#: The Python verdicts of ``classify_circle`` as the verdicts they are drawn with.
CIRCLE_VERDICT = {"stable": "secularly_stable", "unstable": "unstable", "degenerate": "degenerate"}


def _axes(ax):
    if ax is None:
        import matplotlib.pyplot as plt

        w = THE_STYLE["column_width"]
        fig, ax = plt.subplots(figsize=(w, w), layout="constrained")
        fig._routh_own = True  # the legend may go below the axes
    return ax


def _fonts(ax):
    ax.xaxis.label.set_fontsize(FONT["label"])
    ax.yaxis.label.set_fontsize(FONT["label"])
    ax.tick_params(labelsize=FONT["tick"])
    for t in ax.xaxis.label, ax.yaxis.label:
        t.set_family(FONT["family"])


def _marker(kind_mark):
    """matplotlib's keyword arguments of a marker letter of the table (black, ``"O"`` open)."""
    if kind_mark == "O":
        return dict(marker="o", markerfacecolor="white", markeredgecolor="k", markeredgewidth=1.2)
    if kind_mark == "x":
        return dict(marker="x", color="k", markeredgewidth=1.5)
    if kind_mark == "@":  # ◎: an open circle with a dot
        return dict(marker=r"$\odot$", color="k", markeredgewidth=0.4)
    return dict(marker=kind_mark, color="k", markeredgecolor="white", markeredgewidth=0.6)


def _smooth(x, y):
    """The points of a cubic Hermite curve through (x, y) (tangents the central differences in
    the axes' scale), eight pieces a segment: a run of few samples drawn smooth, its dashes laid
    along it (matplotlib runs a dash pattern on across the vertices of one line)."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    n = len(x)
    if n < 3 or n > 400 or not (np.isfinite(x).all() and np.isfinite(y).all()):
        # (An infinite k, say: the run is drawn as it is, its infinite points left out.)
        return x, y
    sx = max(np.ptp(x), 1e-300)
    sy = max(np.ptp(y), 1e-300)
    p = np.column_stack([x / sx, y / sy])
    m = np.empty_like(p)
    m[1:-1] = 0.5 * (p[2:] - p[:-2])
    m[0] = p[1] - p[0]
    m[-1] = p[-1] - p[-2]
    t = np.linspace(0.0, 1.0, 9)[:-1, None]
    h00, h10 = 2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t
    h01, h11 = -2 * t**3 + 3 * t**2, t**3 - t**2
    pieces = [h00 * p[i] + h10 * m[i] + h01 * p[i + 1] + h11 * m[i + 1] for i in range(n - 1)]
    out = np.vstack(pieces + [p[-1:]])
    return out[:, 0] * sx, out[:, 1] * sy


def _runs(ax, x, y, names, style, seen, widths=None, hidden=None, labels=None):
    """Draw `y` against `x` in runs of equal `names[i]`, each run in `style[name]` (colour, line
    style) and joined to the next; a name is put in the legend once (`seen` collects the names
    drawn). A run for which `hidden(xs, ys)` is true (under an event's marker) is not drawn."""
    start = 0
    lines = []
    for i in range(1, len(names) + 1):
        if i == len(names) or names[i] != names[start]:
            name = names[start]
            colour, ls = style[name]
            hi = min(i + 1, len(names))
            xs, ys = np.asarray(x[start:hi]), np.asarray(y[start:hi])
            if not (hidden is not None and hidden(xs, ys)):
                label = (labels or {}).get(name, name.replace("_", " ")) if name not in seen else None
                seen.add(name)
                sx, sy = _smooth(xs, ys)
                lw = (widths or {}).get(name, 1.0)
                lines.append(ax.plot(sx, sy, color=colour, linestyle=ls, lw=lw, label=label)[0])
            start = i
    return lines


def _legend(ax):
    """The legend below the axes, in two columns (a column-wide figure has no room beside)."""
    handles, labels = ax.get_legend_handles_labels()
    # Verdicts in the table's order, then the rest as drawn.
    order = [t["label"] for g in ("verdict", "orbit_verdict") for t in THE_STYLE[g].values()]
    rank = {name: k for k, name in enumerate(order)}
    pairs = sorted(zip(handles, labels), key=lambda hl: rank.get(hl[1], len(rank)))
    _put_legend(ax, [h for h, _ in pairs], [l for _, l in pairs])


def _put_legend(ax, handles, labels=None):
    """Below the axes in two columns on a figure of our own (a column wide: no room beside);
    at matplotlib's best place inside the axes on the caller's."""
    if not handles:
        return
    labels = labels if labels is not None else [h.get_label() for h in handles]
    kw = dict(fontsize=FONT["legend"], handlelength=2.6, columnspacing=1.0)
    if getattr(ax.figure, "_routh_own", False):
        ncol = 2 if max(len(l) for l in labels) <= 20 else 1
        ax.figure.legend(handles, labels, loc="outside lower center", ncol=ncol, frameon=False,
                         **kw)
    else:
        ax.legend(handles, labels, loc="best", framealpha=0.9, **kw)


def _value(v):
    """Four significant digits, a true minus sign."""
    s = f"{v:.4g}"
    return s.replace("-", "−", 1)


def place_labels(ax, items, fontsize=None):
    """Write each ``(x, y, text)`` beside its point, placed so that no two labels overlap and none
    covers a marker or, where it can be helped, a line: positions around the point are tried
    nearest first, then farther out on a leader line. Labels with the same text at the same point
    (the mirror images of a symmetric event) are written once. Returns the texts."""
    fontsize = fontsize or FONT["annotation"]
    fig = ax.figure
    ax.autoscale_view()
    fig.draw_without_rendering()  # the layout, limits and transforms as they will be
    to_px = ax.transData.transform
    scale = fig.dpi / 72.0
    area = ax.get_window_extent()
    markers = []
    for (x, y, _) in items:
        cx, cy = to_px((x, y))
        r = 5 * scale
        markers.append((cx - r, cy - r, cx + r, cy + r))
    curve_px = []
    for line in ax.get_lines():
        xy = line.get_xydata()
        if len(xy) > 1:
            curve_px.append(to_px(xy))
    curve_px = np.vstack(curve_px) if curve_px else np.empty((0, 2))
    placed, texts, seen = [], [], set()

    def overlaps(a, b, m=1.0):
        return a[0] < b[2] + m and b[0] < a[2] + m and a[1] < b[3] + m and b[1] < a[3] + m

    for (x, y, text) in items:
        cx, cy = to_px((x, y))
        key = (text, round(cx), round(cy))
        if key in seen:
            continue
        seen.add(key)
        w = 0.62 * fontsize * scale * len(text)
        h = 1.25 * fontsize * scale

        def free(b, strict):
            inside = b[0] >= area.x0 and b[2] <= area.x1 and b[1] >= area.y0 and b[3] <= area.y1
            if not inside or any(overlaps(b, p) for p in placed):
                return False
            if any(overlaps(b, m) for m in markers):
                return False
            if strict and len(curve_px):
                c = curve_px
                hit = (c[:, 0] >= b[0]) & (c[:, 0] <= b[2]) & (c[:, 1] >= b[1]) & (c[:, 1] <= b[3])
                if hit.any():
                    return False
            return True

        chosen = None
        for strict in (True, False):
            for ring, d in enumerate((6, 16, 30, 48, 70)):
                d *= scale
                for (ox, oy) in ((d, d), (d, -d - h), (-d - w, d), (-d - w, -d - h),
                                 (d, -h / 2), (-d - w, -h / 2), (-w / 2, d), (-w / 2, -d - h)):
                    b = (cx + ox, cy + oy, cx + ox + w, cy + oy + h)
                    if free(b, strict):
                        chosen = (b, ring > 0)
                        break
                if chosen:
                    break
            if chosen:
                break
        if chosen is None:
            chosen = ((cx + 6 * scale, cy + 6 * scale, cx + 6 * scale + w, cy + 6 * scale + h), False)
        b, leader = chosen
        placed.append(b)
        # Text anchored at its box's lower-left corner, in display pixels.
        xy_text = ax.transData.inverted().transform((b[0], b[1] + 0.15 * h))
        kw = dict(arrowprops=dict(arrowstyle="-", color="#6E6E6E", lw=0.6, shrinkA=0,
                                  shrinkB=4)) if leader else {}
        t = ax.annotate(text, (x, y), xytext=tuple(xy_text), textcoords="data",
                        fontsize=fontsize, family=FONT["family"], ha="left", va="bottom",
                        bbox=dict(boxstyle="square,pad=0.1", fc="white", ec="none", alpha=0.8),
                        annotation_clip=False, **kw)
        texts.append(t)
    return texts


def _near_event(events_xy, xlim, ylim):
    """Whether a run lies wholly within 5 % of the axes of an event (the sample or two where a
    test is inconclusive exactly at the event, under its marker)."""
    sx, sy = (xlim[1] - xlim[0]) or 1.0, (ylim[1] - ylim[0]) or 1.0

    def hidden(xs, ys):
        for (ex, ey) in events_xy:
            if np.all(np.hypot((xs - ex) / sx, (ys - ey) / sy) <= 0.05):
                return True
        return False

    return hidden


def _circle_verdicts(diagram, model, axis):
    """The verdict of ``model.classify_circle`` at each point of each branch of circles (the
    others as they are): the steady motion at ``s`` nearest the branch's γ, from
    ``model.steady_motions(s)``. Only for a diagram over the momentum p_ψ of ``model``."""
    e = np.asarray(axis, float) / np.linalg.norm(axis)
    out = []
    for b in diagram.branches:
        verdicts = list(b.verdicts)
        if not b.isolated:
            for i, s in enumerate(np.asarray(b.s)):
                motions = model.steady_motions(float(s))
                if not motions:
                    continue
                # A circle's motions differ by a turn about the axis: matched by γ·e and by the
                # length of γ's part across e.
                g = np.asarray(b.gamma)[i]

                def key(v):
                    v = np.asarray(v, float)
                    along = float(v @ e)
                    return np.array([along, float(np.linalg.norm(v - along * e))])

                m = min(motions, key=lambda m: float(np.linalg.norm(key(m.gamma) - key(g))))
                if np.linalg.norm(key(m.gamma) - key(g)) > 1e-6:
                    continue
                verdicts[i] = CIRCLE_VERDICT[model.classify_circle(m, axis).verdict]
        out.append(verdicts)
    return out


def plot_diagram(diagram, ax=None, component=2, xlabel="p_ψ", ylabel=None, values=False,
                 circles=None, axis=(0.0, 0.0, 1.0)):
    """Draw `diagram` (s against γ[component]) on `ax` (a new one, a journal column wide, if
    None); returns the axes. `xlabel`: the name of the family's parameter (p_ψ by default; the
    parameter's name, with its unit, for a family over a parameter); `ylabel`: the component's
    name by default. `values=True` writes each event's value beside its marker. `circles`: the
    model, to draw each branch of circles of steady motions with the verdict of
    ``model.classify_circle`` about `axis` (a diagram over p_ψ of that model) rather than
    ``classify``'s "degenerate"."""
    ax = _axes(ax)
    verdicts = ([list(b.verdicts) for b in diagram.branches] if circles is None
                else _circle_verdicts(diagram, circles, axis))
    events = sorted(diagram.events, key=lambda e: e.s)
    pts = [(e.s, float(np.asarray(e.gamma)[component])) for e in events]
    xs = np.concatenate([np.asarray(b.s) for b in diagram.branches] + [[p[0] for p in pts]])
    ys = np.concatenate([np.asarray(b.gamma)[:, component] for b in diagram.branches]
                        + [[p[1] for p in pts]])
    hidden = _near_event(pts, (xs.min(), xs.max()), (ys.min(), ys.max())) if len(xs) else None
    seen = set()
    for b, v in zip(diagram.branches, verdicts):
        lines = _runs(ax, b.s, np.asarray(b.gamma)[:, component], v, STYLE, seen, WIDTH, hidden,
                      VERDICT_LABEL)
        if not b.isolated:
            for line in lines:
                line.set_marker("o")
                line.set_markersize(3.5)
                line.set_markerfacecolor("white")
                line.set_markevery(0.08)
    if any(not b.isolated for b in diagram.branches):
        ax.plot([], [], color="k", lw=0.8, marker="o", markersize=3.5, markerfacecolor="white",
                label="circle of steady motions")
    kinds_drawn = []
    for e, (x, y) in zip(events, pts):
        kw = _marker(EVENT_MARK[e.kind])
        label = None if e.kind in kinds_drawn else EVENT_NAME[e.kind]
        kinds_drawn.append(e.kind)
        ax.plot([x], [y], linestyle="none", markersize=6, zorder=5, label=label, **kw)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel or GAMMA_LABEL[component])
    _fonts(ax)
    _legend(ax)
    labels = []
    for e, (x, y) in zip(events, pts):
        name = EVENT_NAME[e.kind] if e.resonance is None else e.resonance
        labels.append((x, y, f"{name} at {_value(e.s)}" if values else name))
    place_labels(ax, labels)
    return ax


def plot_atlas(atlas, ax=None, xlabel="first parameter", ylabel="second parameter"):
    """Draw `atlas`: verdict regions in their light tints and hatches, boundary curves on top
    (solid fold, dashed branch point, dotted Hamiltonian–Hopf) and a legend of what is drawn.
    Name the axes with the family's parameters (`xlabel`, `ylabel`: names and units)."""
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    ax = _axes(ax)
    names = list(STYLE)
    # verdicts[j][i] is at (x[i], y[j]): row j of `codes` is y[j], as pcolormesh reads it.
    codes = np.full((len(atlas.y), len(atlas.x)), np.nan)
    for j, row in enumerate(atlas.verdicts):
        for i, v in enumerate(row):
            if v is not None:
                codes[j, i] = names.index(v)
    fills = [THE_STYLE["verdict"][n]["fill"] for n in names]
    ax.pcolormesh(atlas.x, atlas.y, codes, cmap=ListedColormap(fills), vmin=-0.5,
                  vmax=len(names) - 0.5, shading="nearest")
    import matplotlib as mpl

    handles = []
    with mpl.rc_context({"hatch.color": "#8C8C8C", "hatch.linewidth": 0.5}):
        # A verdict seen at a node or two alone (on a boundary, where a test is inconclusive)
        # shows as no region: it is neither filled nor listed.
        few = max(2, codes.size // 500)
        for k, n in enumerate(names):
            mask = codes == k
            if mask.sum() < few:
                continue
            hatch = THE_STYLE["verdict"][n]["hatch"] or None
            # Over the cells (pcolormesh, the data as they are), each region's tint and hatch
            # filled to the contour half-way between its nodes and the others: its edge runs
            # along the traced boundary rather than in the grid's stair steps.
            ax.contourf(atlas.x, atlas.y, mask.astype(float), levels=[0.5, 1.5],
                        colors=[THE_STYLE["verdict"][n]["fill"]],
                        hatches=[hatch * 2 if hatch else None])
            handles.append(Patch(facecolor=THE_STYLE["verdict"][n]["fill"], edgecolor="#5A5A5A",
                                 hatch=(hatch * 2) if hatch else None, lw=0.5,
                                 label=THE_STYLE["verdict"][n]["label"]))
    if np.isnan(codes).any():
        handles.append(Patch(facecolor="white", edgecolor="#5A5A5A", lw=0.5,
                             label="no steady motion"))
    for kind in EVENT_KINDS:
        curves = [b for b in atlas.boundaries if b.kind == kind and len(b.points)]
        if not curves:
            continue
        look = THE_STYLE["boundary"][kind]
        for k, b in enumerate(curves):
            pts = np.asarray(b.points)
            ax.plot(pts[:, 0], pts[:, 1], color="white", lw=3.5 * look["width"], zorder=3)
            line, = ax.plot(pts[:, 0], pts[:, 1], color=look["color"], lw=look["width"],
                            linestyle=_linestyle(look), zorder=4)
            if k == 0:
                line.set_label(look["label"])
                handles.append(line)
    ax.set_xlim(min(atlas.x), max(atlas.x))
    ax.set_ylim(min(atlas.y), max(atlas.y))
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    _fonts(ax)
    _put_legend(ax, handles)
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
    ax.legend(fontsize=FONT["legend"])
    _fonts(ax)
    return ax


ORBIT_STABILITIES = ("elliptic", "parabolic", "hyperbolic", "inverse_hyperbolic")
#: Colour and line style of each orbit stability (the table's "orbit_verdict" group).
ORBIT_STYLE = _looks("orbit_verdict", ORBIT_STABILITIES)
ORBIT_WIDTH = {n: THE_STYLE["orbit_verdict"][n]["width"] for n in ORBIT_STABILITIES}
ORBIT_EVENT_KINDS = ("fold", "branch_point", "period_doubling", "twist_degenerate",
                     "third_order_resonance", "fourth_order_resonance")
#: Event marks as the SVG: folds ▲, branch points ●, period doublings ◆, a vanishing twist ■,
#: resonances of order three ○ and four ◎.
ORBIT_EVENT_MARK = {k: THE_STYLE["orbit_event"][k]["marker"] for k in ORBIT_EVENT_KINDS}
ORBIT_EVENT_NAME = {k: THE_STYLE["orbit_event"][k]["label"] for k in ORBIT_EVENT_KINDS}


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


#: At most this many ticks on the axis of `index_axis` (beyond, one every so many decades).
INDEX_TICKS = 12


_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def _index_label(t):
    """The value of k at ``t`` on the axis of `index_axis` (an integer), as the Rust SVGs write
    it (``routh::style::decade_label``): ``0``, ``1``, ``10``, ``100``, then ``10³``, ``10⁴``,
    … ``10³⁰⁰``, a true minus sign, never through a float (10**309 overflows one)."""
    n = abs(t) - 1
    if n <= 0:
        size = str(abs(t))
    elif n <= 2:
        size = str(10 ** n)
    else:
        size = "10" + str(n).translate(_SUPERSCRIPT)
    return ("−" if t < 0 else "") + size


def _index_ticks(ax):
    """Ticks at the decades of `index_axis` in the axes' limits, labelled with k: every decade
    when there are few, else one every 2, 5, 10, 20, 50, … decades (and always −1, 0, 1), so
    that k = 1e300 gives a dozen readable labels, not 300 (nor an OverflowError)."""
    lo, hi = ax.get_ylim()
    if not (np.isfinite(lo) and np.isfinite(hi)):
        return
    lo, hi = int(np.floor(lo)), int(np.ceil(hi))
    for step in (1, 2, 5, 10, 20, 50, 100, 200, 500):
        if hi - lo <= INDEX_TICKS * step:
            break
    ticks = [t for t in range(lo, hi + 1) if abs(t) <= 1 or (abs(t) - 1) % step == 0]
    ax.set_yticks(ticks)
    ax.set_yticklabels([_index_label(t) for t in ticks])


def plot_orbit_family(family, ax=None, quantity="stability_index", xlabel="E", values=False):
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
            ax.axhline(level, color=THE_STYLE["reference"]["parabolic_line"]["color"], lw=0.8,
                       linestyle=":")
    seen = set()
    _runs(ax, e, y, list(family.stability), ORBIT_STYLE, seen, ORBIT_WIDTH,
          labels={n: THE_STYLE["orbit_verdict"][n]["label"] for n in ORBIT_STABILITIES})
    labels = []
    drawn = set()
    for ev in sorted(family.events, key=lambda ev: ev.energy):
        yv = ev.orbit.stability_index if quantity == "stability_index" else ev.orbit.period
        if quantity == "stability_index":
            yv = float(index_axis([yv])[0])
        label = None if ev.kind in drawn else ORBIT_EVENT_NAME[ev.kind]
        drawn.add(ev.kind)
        ax.plot([ev.energy], [yv], linestyle="none", markersize=6, zorder=5, label=label,
                **_marker(ORBIT_EVENT_MARK[ev.kind]))
        name = ORBIT_EVENT_NAME[ev.kind]
        labels.append((ev.energy, yv, f"{name} at E = {_value(ev.energy)}" if values else name))
    ax.set_xlabel(xlabel)
    ax.set_ylabel("k" if quantity == "stability_index" else "T")
    if quantity == "stability_index":
        _index_ticks(ax)
    _fonts(ax)
    _legend(ax)
    place_labels(ax, labels)
    return ax


def plot_section(section, ax=None, fixed_points=None, title=None):
    """Draw a Poincaré section: each orbit's crossings as small dots of its own colour (θ against
    M_n), and `fixed_points` ((k, 2): a periodic orbit's crossings) as larger black marks; the
    legend says (p_ψ, E). No title unless `title` is given (as the Rust SVG). Returns the
    axes."""
    ax = _axes(ax)
    palette = THE_STYLE["palette"]
    for k, pts in enumerate(section.points):
        pts = np.asarray(pts)
        if len(pts):
            ax.plot(pts[:, 0], pts[:, 1], linestyle="none", marker=".", markersize=1.5,
                    color=palette[k % len(palette)])
    fp = None if fixed_points is None else np.asarray(fixed_points, dtype=float).reshape(-1, 2)
    if fp is not None and len(fp):
        ax.plot(fp[:, 0], fp[:, 1], linestyle="none", marker="x", markersize=8, color="k",
                label="periodic orbit")
    ax.plot([], [], linestyle="none",
            label=f"p_ψ = {_value(section.p_psi)}, E = {_value(section.energy)}")
    ax.legend(fontsize=FONT["legend"])
    ax.set_xlabel("θ")
    ax.set_ylabel("M_n")
    if title:
        ax.set_title(title, fontsize=FONT["title"])
    _fonts(ax)
    return ax


#: The curves of an orbit chart, in the order of the legend: their looks (the table's
#: "orbit_curve" group: black lines for the changes of linear stability, blue for the
#: resonances, purple for the twist, each kind its own dash).
ORBIT_CURVE_KINDS = ("fold", "branch_point", "period_doubling", "third_order_resonance",
                     "fourth_order_resonance", "twist_degenerate")


def plot_orbit_chart(chart, ax=None, xlabel=None):
    """Draw an orbit chart (``OrbitChart.plot``): every orbit of the families as a small mark at
    (x, h) in the colour of its linear stability (the regions: elliptic green, hyperbolic
    vermillion, …), the curves on top as lines in the look of their kind (a white halo under
    each), and a legend of what is drawn. x is labelled with the parameter's name (or
    `xlabel`), y with h = E − E_s. Returns the axes."""
    ax = _axes(ax)
    handles = []
    samples = np.asarray(chart.samples, dtype=float).reshape(-1, 3)
    stabilities = [o.stability for f in chart.families if f is not None for o in f.orbits]
    size = 9.0 if len(samples) < 400 else 4.0
    for name in ORBIT_STABILITIES:
        sel = np.array([s == name for s in stabilities], dtype=bool)
        if not sel.any():
            continue
        look = THE_STYLE["orbit_verdict"][name]
        h = ax.scatter(samples[sel, 0], samples[sel, 1], s=size, marker="s", color=look["color"],
                       alpha=0.35, linewidths=0, zorder=1, label=look["label"])
        handles.append(h)
    for kind in ORBIT_CURVE_KINDS:
        curves = [c for c in chart.curves if c.kind == kind and len(c)]
        if not curves:
            continue
        look = THE_STYLE["orbit_curve"][kind]
        for k, c in enumerate(curves):
            pts = np.asarray(c.points, dtype=float)
            ax.plot(pts[:, 0], pts[:, 1], color="white", lw=3.5 * look["width"], zorder=3,
                    solid_capstyle="butt")
            kw = {}
            if len(pts) == 1:  # a curve met at one x only: its point marked
                kw = _marker(THE_STYLE["orbit_event"][kind]["marker"])
                kw.pop("color", None)
                kw.update(markersize=5)
            line, = ax.plot(pts[:, 0], pts[:, 1], color=look["color"], lw=look["width"],
                            linestyle=_linestyle(look), zorder=4, **kw)
            if k == 0:
                line.set_label(look["label"])
                handles.append(line)
    x = np.asarray(chart.x, dtype=float)
    if len(x):
        ax.set_xlim(x.min(), x.max())
    ax.set_xlabel(xlabel or chart.parameter)
    ax.set_ylabel(r"$h = E - E_\mathrm{s}$")
    _fonts(ax)
    _put_legend(ax, handles)
    return ax
