"""The analytical figures of Liu et al. 2018 (Figs. 11-13), drawn from `puncture figures` data.

`puncture figures --out DIR` computes the data with the C++ solver, writes it to
DIR/figures-data.json and calls draw_all(data, DIR), which writes each figure as PNG and SVG:

    fig11     uniaxial nominal stress against stretch of the material (Gent in the paper)
    fig12a    I1 along the reference radius near the tip for several friction coefficients,
              F / 2 pi G H A = 1, indenter radius 0.08 A
    fig12b    Part III stretch against friction for indenter radii 0.04, 0.08, 0.12 A, same force
    fig13a-e  loading curves to puncture: 1-4 mm lubricated (mu' = 0.18), 1 mm dry (1.95);
    fig13     the five panels on one page
    fig14     the balloons: a 1 mm flat punch on the inflated membrane (gas pressure held),
              lubricated (mu' = 0.18) vs dry (1.95), loading curves and puncture points
    probes    not in the paper: flat (sharp and rounded), sphere-tipped and cone probes of one
              radius without friction, their outlines to scale, loading curves and punctures

Figs. 12 and 13 show the ring-balance Part II equation (solid, the default) and the paper's
printed Eq. 18 (dashed) where they differ.  The paper's experimental data are not reproduced.
"""

import os

import matplotlib
import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

try:
    from . import plots
except ImportError:  # run from plot_cli.py as a script
    import plots

__all__ = ["draw_all", "fig11", "fig12a", "fig12b", "fig13_panel", "fig13", "fig14", "probes"]

EQUATION_NAMES = {
    "ring-balance": "ring balance (default)",
    "paper-eq18": "paper's Eq. 18 as printed",
}
EQUATION_STYLES = {"ring-balance": "-", "paper-eq18": "--"}
# Distinct hues (no two greens): Dark2 without its second green, then brown and grey.
SERIES_COLOURS = ["#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#e6ab02", "#a6761d", "#666666"]


def _values(xs):
    """A JSON list as a float array, null as NaN."""
    return np.array([np.nan if x is None else x for x in xs], dtype=float)


def _membrane(data):
    i = data["inputs"]
    return (f"A = {i['clamp_radius_mm']:g} mm, H = {i['thickness_mm']:g} mm, "
            f"{i['material_description']}, critical I1 = {i['critical_i1']:g}")


def _same(curve_a, curve_b, key_x, key_y):
    """True when two series coincide (then only one is drawn)."""
    xa, ya, xb, yb = (_values(c[k]) for c in (curve_a, curve_b) for k in (key_x, key_y))
    return xa.shape == xb.shape and np.allclose(xa, xb, equal_nan=True) and np.allclose(
        ya, yb, rtol=1e-9, equal_nan=True)


def _equation_legend(ax, **kwargs):
    handles = [Line2D([], [], color="black", lw=1.6, ls=EQUATION_STYLES[e],
                      label=EQUATION_NAMES[e]) for e in EQUATION_STYLES]
    return ax.legend(handles=handles, title="Part II equation", **kwargs)


def fig11(data):
    d = data["fig11"]
    stretch = _values(d["stretch"])
    stress = _values(d["stress_mpa"])
    neo = _values(d["neo_hookean_stress_mpa"])
    with matplotlib.rc_context(plots.STYLE):
        fig = Figure(figsize=(6.5, 4.8), layout="constrained")
        ax = fig.add_subplot()
        ax.plot(stretch, stress, color="black", lw=1.8, label=d["material"])
        ax.plot(stretch, neo, color="#1f77b4", lw=1.4, ls="--",
                label=f"neo-Hookean, G = {d['shear_modulus_mpa']:g} MPa")
        lock = d.get("locking_stretch")
        if lock:
            ax.axvline(lock, color=plots.CRITICAL_COLOUR, ls=":", lw=1.2,
                       label=f"locking stretch {lock:.3g} (I1 = 3 + J_lim)")
        finite = stress[np.isfinite(stress)]
        ax.set_ylim(0, min(finite.max(), 4.0 * np.nanmax(neo)) if finite.size else 1)
        ax.set_xlim(1, stretch[-1] * 1.03)
        ax.set_xlabel("stretch λ")
        ax.set_ylabel("nominal stress [MPa]")
        ax.legend(loc="upper left", framealpha=0.9)
        ax.set_title("Fig. 11: uniaxial tension of the membrane's rubber\n"
                     "(the paper's measured curves are not reproduced)")
    return fig


def fig12a(data, *, r_max_factor=1.6):
    d = data["fig12a"]
    a = d["indenter_radius_mm"]
    big_a = data["inputs"]["clamp_radius_mm"]
    cases = d["cases"]
    frictions = sorted({c["friction"] for c in cases})
    colour = {mu: SERIES_COLOURS[k % len(SERIES_COLOURS)] for k, mu in enumerate(frictions)}
    with matplotlib.rc_context(plots.STYLE):
        fig = Figure(figsize=(9.5, 5.2), layout="constrained")
        ax = fig.add_subplot()
        ring = {c["friction"]: c for c in cases if c["part_two_equation"] == "ring-balance"}
        # Without Part II both equations give the same state: drawn once.
        same = {mu for mu, r in ring.items() if "failure" not in r and any(
            c["friction"] == mu and c["part_two_equation"] != "ring-balance"
            and "failure" not in c and _same(c, r, "R_mm", "I1") for c in cases)}
        failed = []
        past = []  # frictions whose state at this force lies beyond puncture (default equation)
        for c in cases:
            if "failure" in c:
                failed.append(f"μ' = {c['friction']:g}, {c['part_two_equation']}")
                continue
            if c["part_two_equation"] != "ring-balance" and c["friction"] in same:
                continue
            r, i1 = _values(c["R_mm"]), _values(c["I1"])
            keep = r <= r_max_factor * a
            label = None
            if c["part_two_equation"] == "ring-balance":
                label = f"μ' = {c['friction']:g}"
                if c["friction"] in same:
                    label += "\n(no Part II: both equations)"
                if i1.max() > data["inputs"]["critical_i1"]:
                    label += " (past puncture)"
                    past.append(c["friction"])
            ax.plot(r[keep], i1[keep], color=colour[c["friction"]],
                    ls=EQUATION_STYLES.get(c["part_two_equation"], "-"), lw=1.6, label=label)
        critical = data["inputs"]["critical_i1"]
        ax.axhline(critical, color=plots.CRITICAL_COLOUR, ls=":", lw=1.2,
                   label=f"critical I1 = {critical:g}")
        # The paper draws these states at one force whatever their puncture; above the critical
        # I1 the membrane would have punctured at a smaller force.
        top = ax.get_ylim()[1]
        ax.axhspan(critical, 2.0 * top, color=plots.CRITICAL_COLOUR, alpha=0.06, lw=0, zorder=0)
        ax.set_xlim(0, r_max_factor * a)
        ax.set_ylim(0, top)
        ax.set_xlabel("reference radius R [mm]")
        ax.set_ylabel("first invariant I1")
        # Outside the axes: the curves fill the plot.
        first = ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), title="friction")
        ax.add_artist(first)
        _equation_legend(ax, loc="lower left", bbox_to_anchor=(1.02, 0.0))
        note = f"; no solution: {', '.join(failed)}" if failed else ""
        if past:
            ax.text(0.99, 0.985, "shaded: I1 above critical, states past puncture\n(the membrane "
                    "would have punctured at a smaller force;\ndrawn at this force as in the "
                    "paper)", transform=ax.transAxes, ha="right", va="top", fontsize=8.5,
                    color=plots.CRITICAL_COLOUR)
        ax.set_title(
            f"Fig. 12(a): I1 near the tip at F / 2πGHA = {d['normalized_force']:g}, "
            f"a = {a:g} mm (a/A = {a / big_a:.2g}){note}\n{_membrane(data)}")
    return fig


def fig12b(data):
    d = data["fig12b"]
    series = d["series"]
    radii = sorted({s["indenter_radius_mm"] for s in series})
    colour = {a: SERIES_COLOURS[k % len(SERIES_COLOURS)] for k, a in enumerate(radii)}
    with matplotlib.rc_context(plots.STYLE):
        fig = Figure(figsize=(9.5, 5.2), layout="constrained")
        ax = fig.add_subplot()
        for s in series:
            mu, stretch = _values(s["friction"]), _values(s["part_three_stretch"])
            label = (f"a = {s['indenter_radius_mm']:g} mm (a/A = {s['radius_ratio']:g})"
                     if s["part_two_equation"] == "ring-balance" else None)
            ax.plot(mu, stretch, color=colour[s["indenter_radius_mm"]],
                    ls=EQUATION_STYLES.get(s["part_two_equation"], "-"), lw=1.6, label=label)
        # The paper's two friction coefficients, marked on a top axis.
        for mu in (0.18, 1.95):
            ax.axvline(mu, color="#777777", ls=":", lw=1.0)
        top = ax.secondary_xaxis("top")
        top.set_xticks([0.18, 1.95], ["lubricated 0.18", "dry 1.95"], fontsize=8.5)
        ax.set_xlim(0, max(_values(series[0]["friction"])))
        ax.set_ylim(bottom=1.0)
        ax.set_xlabel("friction coefficient μ'")
        ax.set_ylabel("Part III stretch Λ (under the tip)")
        first = ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), title="indenter radius")
        ax.add_artist(first)
        _equation_legend(ax, loc="lower left", bbox_to_anchor=(1.02, 0.0))
        ax.set_title(f"Fig. 12(b): stretch under the tip at F / 2πGHA = "
                     f"{d['normalized_force']:g}\n{_membrane(data)}")
    return fig


def _panel_title(panel):
    kind = "dry" if panel["friction"] > 1 else "lubricated"
    return (f"({panel['label']}) a = {panel['indenter_radius_mm']:g} mm, {kind}, "
            f"μ' = {panel['friction']:g}")


def _draw_fig13_panel(ax, panel, *, legend_fontsize=None):
    curves = panel["curves"]
    handles, failed = [], []
    ring = next((c for c in curves if c["part_two_equation"] == "ring-balance"), None)
    for c in curves:
        eq = c["part_two_equation"]
        if "failure" in c:
            failed.append(f"{EQUATION_NAMES[eq]}: {c['failure']['message']}")
            continue
        if eq != "ring-balance" and ring and "failure" not in ring and \
                _same(c, ring, "depth_mm", "force_n"):
            continue
        depth, force = _values(c["depth_mm"]), _values(c["force_n"])
        colour = "black" if eq == "ring-balance" else "#1f5fa8"
        p = c.get("puncture")
        text = (f"{EQUATION_NAMES[eq]}:\npuncture {p['force_n']:.3g} N at {p['depth_mm']:.3g} mm"
                if p else EQUATION_NAMES[eq])
        (line,) = ax.plot(depth, force, color=colour, ls=EQUATION_STYLES[eq], lw=1.6,
                          label=text)
        handles.append(line)
        if p:
            ax.plot([p["depth_mm"]], [p["force_n"]], "X", color=plots.CRITICAL_COLOUR, ms=9,
                    mec="white", mew=0.7, zorder=5)
    mark = Line2D([], [], ls="none", marker="X", color=plots.CRITICAL_COLOUR, ms=9,
                  mec="white", label="predicted puncture (I1 = critical I1)")
    handles.append(mark)
    # The axes fit the default (solid) curve: the printed equation's dashed curve runs on to a
    # far deeper puncture (its numbers are in the legend) and would squeeze the default one into
    # a corner.
    if ring and "failure" not in ring:
        depth, force = _values(ring["depth_mm"]), _values(ring["force_n"])
        ax.set_xlim(0, 1.35 * depth.max())
        ax.set_ylim(0, 1.75 * force.max())  # head room for the legend
        for line in handles[1:-1]:  # the other equation's curve, if drawn
            x, y = line.get_xdata(), line.get_ydata()
            if x.max() > ax.get_xlim()[1] or y.max() > ax.get_ylim()[1]:
                line.set_label(line.get_label() + " (off the axes)")
    else:
        ax.set_xlim(left=0)
        ax.set_ylim(bottom=0)
    ax.set_xlabel("indentation depth δ [mm]")
    ax.set_ylabel("indenter force F [N]")
    ax.legend(handles=handles, loc="upper left", framealpha=0.9, fontsize=legend_fontsize)
    ax.set_title(_panel_title(panel))
    return failed


def fig13_panel(data, label):
    panel = next(p for p in data["fig13"]["panels"] if p["label"] == label)
    with matplotlib.rc_context(plots.STYLE):
        fig = Figure(figsize=(7.0, 5.0), layout="constrained")
        ax = fig.add_subplot()
        failed = _draw_fig13_panel(ax, panel)
        ax.set_title(f"Fig. 13{_panel_title(panel)}\n{_membrane(data)}"
                     + ("\nno curve: " + "; ".join(failed) if failed else ""))
    return fig


def fig13(data):
    panels = data["fig13"]["panels"]
    with matplotlib.rc_context(plots.STYLE):
        fig = Figure(figsize=(15.0, 9.0), layout="constrained")
        axes = fig.subplots(2, 3).ravel()
        for ax, panel in zip(axes, panels):
            _draw_fig13_panel(ax, panel, legend_fontsize=8)
        for ax in axes[len(panels):]:
            ax.axis("off")
            ax.text(0.0, 0.9,
                    "Loading curves to puncture, displacement control.\n"
                    "Solid: Part II by the vertical balance of a ring\n"
                    "(the default); dashed: the paper's printed Eq. 18\n"
                    "(--part-two-equation paper-eq18), drawn where\n"
                    "the two differ.  Crosses: predicted puncture.\n"
                    "The paper's measured curves are not reproduced.",
                    transform=ax.transAxes, va="top", fontsize=9.5)
        fig.suptitle(f"Fig. 13: loading curves to puncture; {_membrane(data)}")
    return fig


def fig14(data):
    """The paper's Fig. 14 situation: both frictions' loading curves, from the inflated pole."""
    d = data["fig14"]
    with matplotlib.rc_context(plots.STYLE):
        fig = Figure(figsize=(7.0, 5.0), layout="constrained")
        ax = fig.add_subplot()
        failed = []
        for colour, c in zip(SERIES_COLOURS, d["curves"]):
            kind = "dry" if c["friction"] > 1 else "lubricated"
            if "failure" in c:
                failed.append(f"{kind}: {c['failure']['message']}")
                continue
            p = c.get("puncture")
            text = f"{kind}, μ' = {c['friction']:g}"
            if p:
                text += f": puncture {p['force_n']:.3g} N at {p['depth_mm']:.3g} mm"
            depth, force = _values(c["depth_mm"]), _values(c["force_n"])
            # Before the face slides outward the model's friction points the wrong way: those
            # states are not the membrane's, drawn dotted.
            start = c.get("face_slides_outward_from_mm")
            valid = [d >= start for d in depth] if start is not None else [False] * len(depth)
            first = valid.index(True) if True in valid else len(depth)
            if first > 0:
                ax.plot(depth[:first + 1], force[:first + 1], color=colour, lw=1.0, ls=":",
                        alpha=0.8)
            ax.plot(depth[first:], force[first:], color=colour, lw=1.6, label=text)
            if p:
                ax.plot([p["depth_mm"]], [p["force_n"]], "X", color=plots.CRITICAL_COLOUR,
                        ms=9, mec="white", mew=0.7, zorder=5)
        ax.plot([], [], ls="none", marker="X", color=plots.CRITICAL_COLOUR, ms=9, mec="white",
                label="predicted puncture (I1 = critical I1)")
        ax.set_xlim(left=0)
        ax.set_ylim(bottom=0)
        ax.set_xlabel("indentation depth δ from the inflated pole [mm]")
        ax.set_ylabel("indenter force F [N]")
        ax.legend(loc="upper left", framealpha=0.9)
        ax.text(0.98, 0.03, "Coulomb sliding throughout; the face's material is taken to slide\n"
                "outward, which it does from the end of the dotted part on: dotted, it slides\n"
                "inward and the states are not the membrane's (docs/model.md §17)",
                transform=ax.transAxes, ha="right", va="bottom", fontsize=8, color="#444444")
        assumed = " (assumed: the paper gives none)" if d["pressure_assumed"] else ""
        ax.set_title(f"Fig. 14: flat punch a = {d['indenter_radius_mm']:g} mm on the membrane "
                     f"inflated by p = {d['pressure_mpa']:g} MPa{assumed}, held\n"
                     f"{_membrane(data)}"
                     + ("\nno curve: " + "; ".join(failed) if failed else ""), fontsize=9)
    return fig


def probes(data):
    """Probes of one radius on the same membrane: outlines to scale, loading curves, punctures."""
    d = data["probes"]
    with matplotlib.rc_context(plots.STYLE):
        fig = Figure(figsize=(12.0, 5.2), layout="constrained")
        shapes, curves = fig.subplots(1, 2, width_ratios=[1, 2.4])
        stopped = []
        for colour, probe in zip(SERIES_COLOURS, d["probes"]):
            r, z = _values(probe["outline"]["r_mm"]), _values(probe["outline"]["z_mm"])
            shapes.plot(np.concatenate([-r[::-1], r]), np.concatenate([z[::-1], z]),
                        color=colour, lw=1.6)
            depth, force = _values(probe["depth_mm"]), _values(probe["force_n"])
            p = probe.get("puncture")
            label = probe["description"]
            if p:
                energy = f", {p['energy_mj']:.3g} mJ" if p.get("energy_mj") is not None else ""
                label += (f"\npuncture {p['force_n']:.3g} N at {p['depth_mm']:.3g} mm{energy}"
                          f" ({p['crack_location']})")
            elif "failure" in probe:
                label += "\nno puncture: the model ends first (below)"
                stopped.append(f"{probe['key']}: {probe['failure']['message']}")
            curves.plot(depth, force, color=colour, lw=1.6, label=label)
            if p:
                curves.plot([p["depth_mm"]], [p["force_n"]], "X", color=plots.CRITICAL_COLOUR,
                            ms=9, mec="white", mew=0.7, zorder=5)
        shapes.set_aspect("equal")
        shapes.set_xlabel("r [mm]")
        shapes.set_ylabel("height above the tip [mm]")
        shapes.set_title("the probes, to scale")
        curves.set_xlim(left=0)
        curves.set_ylim(bottom=0)
        curves.set_xlabel("indentation depth δ [mm]")
        curves.set_ylabel("indenter force F [N]")
        curves.legend(loc="upper left", fontsize=8, framealpha=0.9)
        curves.set_title("loading curves without friction; X: predicted puncture"
                         + ("\n" + "\n".join(stopped) if stopped else ""), fontsize=8)
        fig.suptitle(f"Probes of radius {d['indenter_radius_mm']:g} mm; {_membrane(data)}",
                     fontsize=10)
    return fig


def draw_all(data, out_dir, formats=(".png", ".svg")):
    """Writes every figure into out_dir in each format; returns the paths written."""
    os.makedirs(out_dir, exist_ok=True)
    figures = [("fig11", fig11(data)), ("fig12a", fig12a(data)), ("fig12b", fig12b(data))]
    figures += [(f"fig13{p['label']}", fig13_panel(data, p["label"]))
                for p in data["fig13"]["panels"]]
    figures.append(("fig13", fig13(data)))
    if "fig14" in data:
        figures.append(("fig14", fig14(data)))
    if "probes" in data:
        figures.append(("probes", probes(data)))
    written = []
    for name, fig in figures:
        for suffix in formats:
            path = os.path.join(out_dir, name + suffix)
            plots.save(fig, path)
            written.append(path)
    return written
