"""Rich display of routh's results in Jupyter: small HTML tables (``_repr_html_``), with the
figure inlined as SVG where one exists and matplotlib is installed (a notebook shows the HTML in
preference to the SVG, so the HTML carries the figure)."""

import html

import numpy as np


def _fmt(x):
    if isinstance(x, (float, np.floating)):
        return f"{x:.6g}"
    if isinstance(x, np.ndarray):
        return np.array2string(x, precision=6, separator=", ")
    return html.escape(str(x))


def _table(rows, head=None):
    out = ['<table class="routh">']
    if head:
        out.append("<tr>" + "".join(f"<th>{html.escape(h)}</th>" for h in head) + "</tr>")
    for r in rows:
        out.append("<tr>" + "".join(f"<td>{_fmt(c)}</td>" for c in r) + "</tr>")
    out.append("</table>")
    return "".join(out)


def _figure(result, method="plot", size=(6, 4)):
    """The inline SVG of ``result.<method>()``, or "" without matplotlib."""
    try:
        from ._plot import svg_of

        svg = svg_of(result, method, size)
    except ImportError:
        return ""
    return svg[svg.find("<svg"):]


def motion_html(m):
    """A steady motion as an HTML table of its fields."""
    return "<b>SteadyMotion</b>" + _table([
        ("gamma", m.gamma), ("p_psi", m.p_psi), ("psi_dot", m.psi_dot), ("mu", m.mu),
        ("energy", m.energy), ("amended_potential", m.amended_potential),
        ("isolated", m.isolated),
    ])


def report_html(r):
    """A stability report as an HTML table."""
    return "<b>StabilityReport</b>" + _table([
        ("verdict", r.verdict), ("degree_of_instability", r.degree_of_instability),
        ("restricted_hessian_eigenvalues", r.restricted_hessian_eigenvalues),
        ("f2_roots", r.f2_roots),
    ])


def certificate_html(c):
    """A certificate: its summary and its motions."""
    head = _table([("complete", c.complete), ("p_psi", c.p_psi), ("boxes", c.boxes),
                   ("undecided", c.undecided)])
    motions = _table([(m.gamma, m.psi_dot, m.energy, m.isolated) for m in c.motions],
                     head=("gamma", "psi_dot", "energy", "isolated"))
    return "<b>Certificate</b>" + head + motions


def diagram_html(d):
    """A bifurcation diagram: its branches, its events and the figure."""
    branches = _table(
        [(k, len(b.verdicts), b.s[0] if len(b.s) else "", b.s[-1] if len(b.s) else "",
          ", ".join(dict.fromkeys(b.verdicts)), b.isolated) for k, b in enumerate(d.branches)],
        head=("branch", "points", "s from", "s to", "verdicts", "isolated"))
    events = _table([(e.kind, e.s, e.gamma, e.branch, e.before, e.after) for e in d.events],
                    head=("event", "s", "gamma", "branch", "before", "after"))
    return ("<b>BifurcationDiagram</b>" + branches + events + _figure(d))


def atlas_html(a):
    """A stability atlas: the grid, the count of each verdict, the boundaries and the figure."""
    counts = {}
    for row, lost in zip(a.verdicts, a.lost):
        for v, gone in zip(row, lost):
            v = v if v is not None else ("(lost)" if gone else "(no steady motion)")
            counts[v] = counts.get(v, 0) + 1
    grid = _table([("x", f"{a.x[0]:.6g} .. {a.x[-1]:.6g} ({len(a.x)} nodes)"),
                   ("y", f"{a.y[0]:.6g} .. {a.y[-1]:.6g} ({len(a.y)} nodes)")])
    verdicts = _table(list(counts.items()),
                      head=("verdict", "nodes"))
    bounds = _table([(b.kind, len(b.points)) for b in a.boundaries], head=("boundary", "points"))
    return "<b>StabilityAtlas</b>" + grid + verdicts + bounds + _figure(a)


def trajectory_svg(tr):
    """The apex locus of a trajectory as SVG, or None without attitude or matplotlib."""
    if tr.attitude is None:
        return None
    try:
        from ._plot import svg_of

        return svg_of(tr, "plot_apex", (5, 5))
    except ImportError:
        return None


def trajectory_html(tr):
    """A trajectory: its span, the drifts of its first integrals, and the apex locus."""
    t, e, p = tr.t, tr.energy, tr.p_psi
    g = np.linalg.norm(tr.gamma, axis=1)
    rows = [("points", len(t)), ("t", f"{t[0]:.6g} .. {t[-1]:.6g}" if len(t) else ""),
            ("max |E − E₀|", float(np.abs(e - e[0]).max()) if len(e) else 0.0),
            ("max |p_ψ − p_ψ₀|", float(np.abs(p - p[0]).max()) if len(p) else 0.0),
            ("max ||γ| − 1|", float(np.abs(g - 1.0).max()) if len(g) else 0.0),
            ("attitude", tr.attitude is not None)]
    fig = ""
    if tr.attitude is not None:
        svg = trajectory_svg(tr)
        fig = svg[svg.find("<svg"):] if svg else ""
    return f"<b>{type(tr).__name__}</b>" + _table(rows) + fig
