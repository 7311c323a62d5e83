"""Figures of puncture results with matplotlib (no display needed: figures are drawn off-screen).

Every function takes results of the bindings (LoadingCurve, Equilibrium, PuncturePrediction) or
the CLI's JSON output loaded with json.load (`puncture curve --format json`, `puncture state
--format json`), writes the figure to `path` when given (.png, .svg or .pdf), and returns the
matplotlib Figure.

    loading_curve(curve, path)    force against depth, stages shaded, puncture marked
    profile(states, path)         deformed profiles, Parts I-III coloured, indenter to scale
    stretch_fields(state, path)   lambda1, lambda2 and I1 along the reference radius
    state_overview(state, path)   profile and fields of one state on one page
    inflation_curve(curve, path)  inflation test: pressure against pole stretch and volume,
                                  the limit point(s) and the burst marked

This module needs numpy and matplotlib only, not the compiled extension, so that the CLI's
--plot can use it on its JSON output.
"""

import os

import matplotlib
import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Polygon, Rectangle

__all__ = ["loading_curve", "profile", "stretch_fields", "state_overview", "inflation_curve",
           "save", "STYLE"]

# Colours of the membrane's parts, and of the loading stages (light, for shaded backgrounds).
PART_COLOURS = {1: "#1f77b4", 2: "#d95f02", 3: "#1b9e77"}
PART_NAMES = {
    1: "Part I (free)",
    2: "Part II (on the side)",
    3: "Part III (under the tip)",
}
STAGE_COLOURS = {
    "stick": "#d9d9d9",
    "slip_without_part_two": "#cfe2f3",
    "slip_with_part_two": "#fde3c8",
    "partial_slip": "#d9ead3",
}
CONFIGURATION_NAMES = {
    "unloaded": "unloaded",
    "stick": "held at the edge",
    "slip_without_part_two": "slip without Part II",
    "slip_with_part_two": "slip with Part II",
    "partial_slip": "partial slip (held core, slipping annulus)",
}
STAGE_NAMES = {
    "stick": "stick (held at the edge)",
    "slip_without_part_two": "slip without Part II",
    "slip_with_part_two": "slip with Part II",
    "partial_slip": "partial slip (held core, slipping annulus)",
}
# Line styles telling several states apart (their parts keep the part colours).
STATE_STYLES = ["-", "--", "-.", ":", (0, (5, 1, 1, 1, 1, 1))]
INDENTER_COLOUR = "#8c8c8c"
CRITICAL_COLOUR = "#c62828"

# Matplotlib settings used while a figure is drawn and saved.
STYLE = {
    "font.size": 10,
    "axes.titlesize": 10.5,
    "axes.labelsize": 10,
    "legend.fontsize": 9,
    "xtick.labelsize": 9,
    "ytick.labelsize": 9,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "svg.fonttype": "none",
    "savefig.dpi": 150,
}

_FORMATS = (".png", ".svg", ".pdf")


# --- the data, from the bindings or from the CLI's JSON -------------------------------------


def _token(value):
    """An enum's CLI token ('slip_with_part_two', 'stick', ...), from an enum or a string."""
    return getattr(value, "token", value)


def _info_from_problem(problem):
    g = problem.geometry
    return {
        "clamp_radius_mm": g.clamp_radius_mm,
        "indenter_radius_mm": problem.indenter.radius_mm,
        "indenter_outline": _curved_outline(problem.indenter),
        "thickness_mm": g.thickness_mm,
        "friction": problem.friction,
        "critical_i1": problem.critical_i1,
        "force_scale_n": problem.force_scale_n,
        "material": problem.material.description,
        "part_two_equation": _token(problem.part_two_equation),
        "stick": _stick_text(_token(problem.stick.rule), problem.stick.threshold),
    }


def _curved_outline(indenter):
    """A curved probe's meridian (r, height above the tip); None for the sharp flat punch, which
    is drawn as a rectangle."""
    if type(indenter).__name__ == "FlatPunch" and indenter.fillet_radius_mm == 0:
        return None
    return indenter.outline()


def _stick_text(rule, threshold):
    return rule if rule in ("none", "always") else f"{rule}:{threshold:g}"


def _info_from_json(inputs):
    m = inputs["material"]
    law = m["law"]
    if "j_lim" in m:
        law += f" (J_lim = {m['j_lim']:g})"
    elif "alpha" in m:
        law += f" (alpha = {m['alpha']:g})"
    return {
        "clamp_radius_mm": inputs["clamp_radius_mm"],
        "indenter_radius_mm": inputs["indenter_radius_mm"],
        "indenter_outline": (list(zip(inputs["indenter_outline"]["r_mm"],
                                      inputs["indenter_outline"]["height_mm"]))
                             if "indenter_outline" in inputs else None),
        "thickness_mm": inputs["thickness_mm"],
        "friction": inputs["friction"],
        "critical_i1": inputs["critical_i1"],
        "force_scale_n": inputs["force_scale_n"],
        "material": f"{law}, G = {m['shear_modulus_mpa']:g} MPa",
        "part_two_equation": inputs["part_two_equation"],
        "stick": _stick_text(inputs["stick"]["rule"], inputs["stick"].get("threshold", 0.0)),
    }


def _info(obj):
    if isinstance(obj, dict):
        return _info_from_json(obj["inputs"]) if "inputs" in obj else {}
    problem = getattr(obj, "problem", None)
    return _info_from_problem(problem) if problem is not None else {}


def _describe(info):
    """One line naming the problem, for titles."""
    if not info:
        return ""
    text = (
        f"a = {info['indenter_radius_mm']:g} mm, A = {info['clamp_radius_mm']:g} mm, "
        f"H = {info['thickness_mm']:g} mm, {info['material']}, μ' = {info['friction']:g}"
    )
    if info.get("stick", "none") != "none":
        text += f", stick {info['stick']}"
    if info.get("part_two_equation") == "paper-eq18":
        text += ", Part II: paper's Eq. 18"
    return text


class _Curve:
    """A loading curve as plain arrays."""

    def __init__(self, obj):
        self.info = _info(obj)
        if isinstance(obj, dict):
            curve = obj["curve"]
            points = curve["points"]
            self.depth = np.array([p["depth_mm"] for p in points], dtype=float)
            self.force = np.array([p["force_n"] for p in points], dtype=float)
            self.configuration = [p["configuration"] for p in points]
            self.beyond = np.array([bool(p.get("beyond_puncture", 0)) for p in points], dtype=bool)
            switch = curve.get("stick_slip") or {}
            self.switch = (
                (switch["depth_mm"], switch["force_stuck_n"], switch["force_sliding_n"])
                if switch.get("occurs")
                else None
            )
            onset = curve.get("part_two_onset")
            self.onset_depth = onset["depth_mm"] if onset else None
            p = obj.get("puncture") or {}
            self.puncture = (
                (p["depth_mm"], p["force_n"], p.get("crack_location", ""))
                if p.get("found")
                else None
            )
        else:
            self.depth = np.asarray(obj.depth_mm, dtype=float)
            self.force = np.asarray(obj.force_n, dtype=float)
            self.configuration = [_token(c) for c in obj.configuration]
            self.beyond = np.asarray(obj.beyond_puncture, dtype=bool)
            s = obj.stick_slip
            self.switch = (s.depth_mm, s.force_stuck_n, s.force_sliding_n) if s.occurs else None
            self.onset_depth = obj.part_two_onset_depth_mm
            p = obj.puncture
            self.puncture = (p.depth_mm, p.force_n, p.crack_location) if p.ok else None
        if self.puncture is not None and self.depth.size and self.puncture[0] > self.depth[-1] * (
            1 + 1e-9
        ):
            self.puncture = None  # the curve ends before puncture (max_depth_mm)


class _State:
    """One equilibrium: the fields along the membrane as plain arrays."""

    def __init__(self, obj):
        self.info = _info(obj)
        if isinstance(obj, dict):
            state = obj.get("state", obj)
            rows = state["fields"]
            self.part = np.array([r["part"] for r in rows], dtype=int)
            col = lambda name: np.array([r[name] for r in rows], dtype=float)  # noqa: E731
            self.R, self.r, self.z = col("R_mm"), col("r_mm"), col("z_mm")
            self.lambda1, self.lambda2, self.i1 = col("lambda1"), col("lambda2"), col("I1")
            self.force_n = state["force_n"]
            self.depth_mm = state["depth_mm"]
            self.configuration = state["configuration"]
            self.max_i1 = state["max_i1"]
            self.max_i1_R = state["max_i1_reference_radius_mm"]
            self.beyond = bool(state.get("beyond_puncture", False))
        else:
            if not hasattr(obj, "fields") and hasattr(obj, "state"):  # a PuncturePrediction
                obj = obj.state
                self.info = self.info or _info(obj)
            f = obj.fields
            self.part = np.asarray(f.part, dtype=int)
            self.R = np.asarray(f.reference_radius_mm, dtype=float)
            self.r = np.asarray(f.radius_mm, dtype=float)
            self.z = np.asarray(f.deflection_mm, dtype=float)
            self.lambda1 = np.asarray(f.radial_stretch, dtype=float)
            self.lambda2 = np.asarray(f.hoop_stretch, dtype=float)
            self.i1 = np.asarray(f.first_invariant, dtype=float)
            self.force_n = obj.force_n
            self.depth_mm = obj.depth_mm
            self.configuration = _token(obj.configuration)
            self.max_i1 = obj.max_first_invariant
            self.max_i1_R = obj.max_first_invariant_reference_radius_mm
            self.beyond = bool(obj.beyond_puncture)
        if not self.R.size:
            raise ValueError("the state has no fields (solved with record_fields off?)")
        # What the plots need of the problem, from the fields when the result does not carry it.
        info = dict(self.info)
        info.setdefault("clamp_radius_mm", float(self.R[-1]))
        if "indenter_radius_mm" not in info:
            touching = self.part > 1
            info["indenter_radius_mm"] = float(self.r[touching].max()) if touching.any() else None
        self.info = info

    def label(self):
        text = f"F = {self.force_n:.3g} N, δ = {self.depth_mm:.3g} mm"
        return text + " (BEYOND PUNCTURE)" if self.beyond else text

    def segments(self):
        """(part, slice) runs of consecutive samples in the same part, each sharing its end
        sample with the next run so that the line is continuous."""
        runs, start = [], 0
        for i in range(1, len(self.part) + 1):
            if i == len(self.part) or self.part[i] != self.part[start]:
                runs.append((int(self.part[start]), slice(start, min(i + 1, len(self.part)))))
                start = i
        return runs


def _states(obj):
    if isinstance(obj, (list, tuple)):
        return [_State(s) for s in obj]
    return [_State(obj)]


# --- drawing ---------------------------------------------------------------------------------


def _stage_intervals(c):
    """[(token, depth_from, depth_to)] of the stages along the curve."""
    tokens = list(c.configuration)
    if len(tokens) > 1 and tokens[0] == "unloaded":
        tokens[0] = tokens[1]
    intervals = []
    for i, t in enumerate(tokens):
        if intervals and intervals[-1][0] == t:
            intervals[-1][2] = c.depth[i]
            continue
        if intervals:
            previous = intervals[-1][0]
            boundary = 0.5 * (c.depth[i - 1] + c.depth[i])
            if previous == "stick" and c.switch is not None:
                boundary = c.switch[0]
            elif t == "slip_with_part_two" and c.onset_depth is not None:
                boundary = c.onset_depth
            intervals[-1][2] = boundary
            intervals.append([t, boundary, c.depth[i]])
        else:
            intervals.append([t, c.depth[0], c.depth[0]])
    return [tuple(i) for i in intervals]


def draw_loading_curve(ax, curve, *, label=None, colour="black", shade=True, annotate=True):
    """Draws one loading curve on `ax`: the stages shaded (when shade), the puncture marked."""
    c = curve if isinstance(curve, _Curve) else _Curve(curve)
    handles = []
    if shade:
        seen = set()
        for token, lo, hi in _stage_intervals(c):
            ax.axvspan(lo, hi, color=STAGE_COLOURS.get(token, "white"), lw=0, zorder=0)
            if token not in seen:
                seen.add(token)
                handles.append(Patch(color=STAGE_COLOURS.get(token, "white"),
                                     label=STAGE_NAMES.get(token, token)))
    # Past the puncture point the curve is the model's continuation: drawn dashed and grey.
    intact = np.flatnonzero(~c.beyond)
    end = int(intact[-1]) + 1 if intact.size else 0
    (line,) = ax.plot(c.depth[:end], c.force[:end], color=colour, lw=1.8, zorder=3,
                      label=label or "model: force F")
    handles.insert(0, line)
    if end < c.depth.size:
        (past,) = ax.plot(c.depth[max(end - 1, 0):], c.force[max(end - 1, 0):], color="grey",
                          lw=1.4, ls="--", zorder=3, label="beyond puncture (already punctured)")
        handles.insert(1, past)
    if c.puncture is not None:
        d, f, where = c.puncture
        (mark,) = ax.plot([d], [f], "X", color=CRITICAL_COLOUR, ms=10, mec="white", mew=0.8,
                          zorder=5, label="puncture (I1 = critical I1)")
        handles.append(mark)
        if annotate:
            # above-left of the mark: the curve rises to it from below-left
            ax.annotate(f"puncture\nF = {f:.4g} N, δ = {d:.4g} mm", (d, f),
                        xytext=(-14, 2), textcoords="offset points", ha="right", va="bottom",
                        fontsize=9, color=CRITICAL_COLOUR, zorder=6)
    if c.switch is not None and annotate:
        d, f_stuck, f_slide = c.switch
        ax.annotate(f"stick → slip\n{f_stuck:.3g} → {f_slide:.3g} N", (d, f_stuck),
                    xytext=(-10, 6), textcoords="offset points", ha="right", va="bottom",
                    fontsize=9, zorder=6)
    ax.set_xlabel("indentation depth δ [mm]")
    ax.set_ylabel("indenter force F [N]")
    ax.set_xlim(0, c.depth[-1] * 1.02 if c.depth.size else 1)
    ax.set_ylim(0, max(c.force.max() if c.force.size else 1, 1e-12) * 1.2)
    return handles


def _normalised_axis(ax, scale):
    if scale:
        sec = ax.secondary_yaxis("right", functions=(lambda f: f / scale, lambda n: n * scale))
        sec.set_ylabel("normalised force F / 2πGHA")


def _draw_indenter(ax, x0, x1, y0, y1, outline=None):
    """The probe from its tip at height y0 up to y1: a rectangle from x0 to x1 (the sharp flat
    punch), or its meridian `outline` ((r, height above the tip) pairs) on the right half,
    mirrored when x0 < 0, continued straight up its shank."""
    if not outline:
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, facecolor=INDENTER_COLOUR,
                               alpha=0.35, edgecolor="#555555", lw=1.0, zorder=1))
        return
    right = [(r, y0 + h) for r, h in outline] + [(outline[-1][0], y1)]
    left = [(-r, y) for r, y in reversed(right)] if x0 < 0 else [(0.0, y1)]
    ax.add_patch(Polygon(right + left, closed=True, facecolor=INDENTER_COLOUR, alpha=0.35,
                         edgecolor="#555555", lw=1.0, zorder=1))


def draw_profile(ax, states):
    """Full cross-section (both halves) of each state, to scale, with the indenter and clamp."""
    states = states if isinstance(states, list) else _states(states)
    info = states[0].info
    big_a = info["clamp_radius_mm"]
    a = info.get("indenter_radius_mm")
    deepest = max(s.depth_mm for s in states)
    top = 0.08 * max(deepest, big_a) + 2.0
    if a:
        _draw_indenter(ax, -a, a, -deepest, top, info.get("indenter_outline"))
    for k, s in enumerate(states):
        style = STATE_STYLES[k % len(STATE_STYLES)]
        for part, sl in s.segments():
            for sign in (1, -1):
                ax.plot(sign * s.r[sl], -s.z[sl], color=PART_COLOURS[part], lw=1.6, ls=style,
                        zorder=3)
    # the clamping rings
    for sign in (1, -1):
        ax.plot([sign * big_a, sign * (big_a + 0.08 * big_a)], [0, 0], color="black", lw=4,
                solid_capstyle="butt", zorder=4)
    ax.set_aspect("equal")
    ax.set_xlim(-1.15 * big_a, 1.15 * big_a)
    ax.set_ylim(-deepest - 0.06 * max(deepest, big_a) - 1.0, top)
    ax.set_xlabel("radius r [mm]")
    ax.set_ylabel("height above the clamp plane −z [mm]")


def draw_profile_tip(ax, states):
    """The membrane near the indenter's tip: height above the tip against r, right half."""
    states = states if isinstance(states, list) else _states(states)
    a = states[0].info.get("indenter_radius_mm") or max(s.r[s.part == 3].max() for s in states)
    part_two_heights = [(s.depth_mm - s.z[s.part == 2]).max() for s in states
                        if (s.part == 2).any()]
    height = max([3.0 * a] + [1.3 * h for h in part_two_heights])
    width = max(2.5 * a, 0.9 * height)
    _draw_indenter(ax, 0, a, 0, height * 1.05, states[0].info.get("indenter_outline"))
    for k, s in enumerate(states):
        style = STATE_STYLES[k % len(STATE_STYLES)]
        keep = s.r <= width * 1.05
        for part, sl in s.segments():
            idx = np.arange(len(s.part))[sl]
            idx = idx[keep[idx]]
            if idx.size:
                ax.plot(s.r[idx], s.depth_mm - s.z[idx], color=PART_COLOURS[part], lw=1.6,
                        ls=style, zorder=3)
    ax.set_aspect("equal")
    ax.set_xlim(0, width)
    ax.set_ylim(-0.08 * height, height)
    ax.set_xlabel("radius r [mm]")
    ax.set_ylabel("height above the indenter's tip [mm]")


def _part_bands(ax, s, xscale):
    """Shades the reference-radius intervals of the parts."""
    for part, sl in s.segments():
        lo, hi = s.R[sl][0], s.R[sl][-1]
        if xscale == "log" and lo <= 0:
            lo = 1e-9
        ax.axvspan(lo, hi, color=PART_COLOURS[part], alpha=0.07, lw=0, zorder=0)


def _radius_axis(ax, s, xscale):
    if xscale == "log":
        ax.set_xscale("log")
        positive = s.R[s.R > 0]
        ax.set_xlim(positive.min() * 0.5 if positive.size else 1e-3, s.R[-1] * 1.05)
    else:
        ax.set_xlim(0, s.R[-1])


def _plot_by_part(ax, s, x, y, style, xscale, label=None):
    x = np.where((x <= 0) & (xscale == "log"), np.nan, x) if xscale == "log" else x
    first = True
    for part, sl in s.segments():
        xs, ys = x[sl], y[sl]
        if part == 3 and xscale == "log" and sl.stop - sl.start > 1:
            # Part III is homogeneous: draw it from the left edge of the axis (R = 0 is not on a
            # log axis) to the corner, then the jump across the corner.
            last = sl.stop - 2  # the last sample of Part III; sl.stop - 1 starts the next part
            xs = np.array([1e-12, x[last], x[sl.stop - 1]])
            ys = np.array([y[sl.start], y[last], y[sl.stop - 1]])
        ax.plot(xs, ys, style, color=PART_COLOURS[part], lw=1.6, zorder=3,
                label=label if first else None)
        first = False


def draw_stretches(ax, state, *, xscale="log"):
    s = state if isinstance(state, _State) else _State(state)
    _part_bands(ax, s, xscale)
    _plot_by_part(ax, s, s.R, s.lambda1, "-", xscale)
    _plot_by_part(ax, s, s.R, s.lambda2, "--", xscale)
    _radius_axis(ax, s, xscale)
    # Head room for the legend above every curve.
    ax.set_ylim(0, 1.5 * max(s.lambda1.max(), s.lambda2.max()))
    ax.set_ylabel("principal stretch")
    ax.set_xlabel("reference radius R [mm]")
    handles = [
        Line2D([], [], color="black", lw=1.6, ls="-", label="λ1 (meridional)"),
        Line2D([], [], color="black", lw=1.6, ls="--", label="λ2 = r/R (hoop)"),
    ]
    handles += [Patch(color=PART_COLOURS[p], alpha=0.6, label=PART_NAMES[p])
                for p in sorted(set(s.part.tolist()))]
    ax.legend(handles=handles, loc="upper right", ncol=2, framealpha=0.9)


def draw_invariant(ax, state, *, xscale="log", critical_i1=None):
    s = state if isinstance(state, _State) else _State(state)
    _part_bands(ax, s, xscale)
    _plot_by_part(ax, s, s.R, s.i1, "-", xscale, label="I1")
    critical = critical_i1 if critical_i1 is not None else s.info.get("critical_i1")
    handles = []
    if critical is not None:
        line = ax.axhline(critical, color=CRITICAL_COLOUR, ls="--", lw=1.2, zorder=2,
                          label=f"critical I1 = {critical:g}")
        handles.append(line)
    (mark,) = ax.plot([max(s.max_i1_R, 1e-12) if xscale == "log" else s.max_i1_R], [s.max_i1],
                      "o", color="black", ms=5, zorder=4,
                      label=f"largest I1 = {s.max_i1:.4g} at R = {s.max_i1_R:.3g} mm")
    handles.append(mark)
    _radius_axis(ax, s, xscale)
    # Head room for the legend above the curve and the critical line.
    ax.set_ylim(0, max(s.i1.max(), critical or 0) * 1.3)
    ax.set_ylabel("first invariant I1")
    ax.set_xlabel("reference radius R [mm]")
    ax.legend(handles=handles, loc="upper right", framealpha=0.9)


# --- the public figures ----------------------------------------------------------------------


def save(fig, path):
    """Writes `fig` to `path`; the format follows the suffix (.png, .svg or .pdf)."""
    path = os.fspath(path)
    suffix = os.path.splitext(path)[1].lower()
    if suffix not in _FORMATS:
        raise ValueError(f"path: the figure's file name must end in .png, .svg or .pdf, got "
                         f"'{path}'")
    metadata = {"Date": None} if suffix in (".svg", ".pdf") else None
    with matplotlib.rc_context(STYLE):
        fig.savefig(path, metadata=metadata)


def _check_path(path):
    if path is not None:
        suffix = os.path.splitext(os.fspath(path))[1].lower()
        if suffix not in _FORMATS:
            raise ValueError(f"path: the figure's file name must end in .png, .svg or .pdf, got "
                             f"'{os.fspath(path)}'")


def _finish(fig, path):
    if path is not None:
        save(fig, path)
    return fig


def _profile_legends(ax, states):
    """The parts (and, for several states, the loads) legends, outside `ax` on its right: the
    profiles of deep states fill the plots."""
    parts = sorted(set().union(*(set(s.part.tolist()) for s in states)))
    handles = [Patch(color=PART_COLOURS[p], label=PART_NAMES[p]) for p in parts]
    handles.append(Patch(facecolor=INDENTER_COLOUR, alpha=0.35, edgecolor="#555555",
                         label="indenter"))
    legend = ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.03, 1.0))
    if len(states) > 1:
        ax.add_artist(legend)
        loads = [Line2D([], [], color="black", lw=1.6, ls=STATE_STYLES[k % len(STATE_STYLES)],
                        label=s.label()) for k, s in enumerate(states)]
        ax.legend(handles=loads, loc="lower left", bbox_to_anchor=(1.03, 0.0), handlelength=3.0,
                  title="load")


def loading_curve(curve, path=None, *, title=None):
    """Force against depth, from zero to puncture: the stages shaded (stick, slip without
    Part II, slip with Part II), the stick -> slip switch and the puncture marked."""
    _check_path(path)
    c = _Curve(curve)
    with matplotlib.rc_context(STYLE):
        fig = Figure(figsize=(7.5, 5.0), layout="constrained")
        ax = fig.add_subplot()
        handles = draw_loading_curve(ax, c)
        _normalised_axis(ax, c.info.get("force_scale_n"))
        ax.legend(handles=handles, loc="upper left", framealpha=0.9)
        ax.set_title(title if title is not None else "Loading curve\n" + _describe(c.info))
    return _finish(fig, path)


def profile(states, path=None, *, title=None):
    """Deformed profiles of one or more states (e.g. at chosen loads), to scale: the whole
    membrane on the left, the region at the indenter's tip on the right; Parts I-III coloured,
    the indenter drawn at the deepest state's depth."""
    _check_path(path)
    ss = _states(states)
    with matplotlib.rc_context(STYLE):
        fig = Figure(figsize=(12.0, 5.4), layout="constrained")
        left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.9, 1]})
        draw_profile(left, ss)
        draw_profile_tip(right, ss)
        _profile_legends(right, ss)
        left.set_title("whole membrane (to scale)")
        right.set_title("at the tip (to scale)")
        loads = ss[0].label() if len(ss) == 1 else f"{len(ss)} loads"
        fig.suptitle(title if title is not None
                     else f"Deformed profile: {loads}\n{_describe(ss[0].info)}")
    return _finish(fig, path)


def stretch_fields(state, path=None, *, xscale="log", critical_i1=None, title=None):
    """lambda1, lambda2 and I1 along the reference radius R, parts shaded, with the critical I1
    (from the state's problem, or critical_i1).  xscale 'log' (default) or 'linear'."""
    _check_path(path)
    if xscale not in ("log", "linear"):
        raise ValueError(f"xscale: expected 'log' or 'linear', got '{xscale}'")
    s = _State(state)
    with matplotlib.rc_context(STYLE):
        fig = Figure(figsize=(7.5, 7.0), layout="constrained")
        top, bottom = fig.subplots(2, 1, sharex=True)
        draw_stretches(top, s, xscale=xscale)
        draw_invariant(bottom, s, xscale=xscale, critical_i1=critical_i1)
        top.set_xlabel("")
        fig.suptitle(title if title is not None
                     else f"Stretches at {s.label()}\n{_describe(s.info)}")
    return _finish(fig, path)


def state_overview(state, path=None, *, title=None):
    """One state on one page: profile (whole membrane and tip), stretches and I1."""
    _check_path(path)
    s = _State(state)
    with matplotlib.rc_context(STYLE):
        fig = Figure(figsize=(12.0, 9.0), layout="constrained")
        grid = fig.add_gridspec(2, 2, width_ratios=[1.9, 1])
        whole = fig.add_subplot(grid[0, 0])
        tip = fig.add_subplot(grid[0, 1])
        fields = grid[1, :].subgridspec(1, 2)
        stretches = fig.add_subplot(fields[0, 0])
        invariant = fig.add_subplot(fields[0, 1])
        draw_profile(whole, [s])
        draw_profile_tip(tip, [s])
        _profile_legends(tip, [s])
        whole.set_title("deformed profile (to scale)")
        tip.set_title("at the tip")
        draw_stretches(stretches, s)
        draw_invariant(invariant, s)
        stretches.set_title("stretches")
        invariant.set_title("first invariant")
        fig.suptitle(title if title is not None
                     else f"Equilibrium at {s.label()} "
                     f"({CONFIGURATION_NAMES.get(s.configuration, s.configuration)})\n"
                     f"{_describe(s.info)}")
    return _finish(fig, path)


# --- the inflation (bulge) test --------------------------------------------------------------


class _InflationCurve:
    """An inflation curve from the bindings (InflationCurve) or from `puncture inflate --format
    json`: the columns, the extrema and the burst."""

    def __init__(self, obj):
        if isinstance(obj, dict):
            c = obj["curve"]
            points = c["points"]
            self.stretch = np.array([p["pole_stretch"] for p in points], dtype=float)
            self.pressure = np.array([p["pressure_mpa"] for p in points], dtype=float)
            self.volume = np.array([p["volume_mm3"] for p in points], dtype=float)
            self.extrema = [(e["kind"], e["pole_stretch"], e["pressure_mpa"], e["volume_mm3"])
                            for e in c["extrema"]]
            b = c["burst"]
            self.burst = ((b["pole_stretch"], b["pressure_mpa"], b["volume_mm3"])
                          if b["found"] else None)
            i = obj.get("inputs", {})
            m = i.get("material", {})
            law = m.get("law", "")
            if "j_lim" in m:
                law += f" (J_lim = {m['j_lim']:g})"
            elif "alpha" in m:
                law += f" (alpha = {m['alpha']:g})"
            self.info = {"clamp_radius_mm": i.get("clamp_radius_mm"),
                         "thickness_mm": i.get("thickness_mm"),
                         "material": f"{law}, G = {m.get('shear_modulus_mpa', 0):g} MPa",
                         "critical_i1": i.get("critical_i1"),
                         "pressure_scale_mpa": i.get("pressure_scale_mpa")}
        else:
            self.stretch = np.asarray(obj.pole_stretch, dtype=float)
            self.pressure = np.asarray(obj.pressure_mpa, dtype=float)
            self.volume = np.asarray(obj.volume_mm3, dtype=float)
            self.extrema = [(_token(e.kind), e.state.pole_stretch, e.state.pressure_mpa,
                             e.state.volume_mm3) for e in obj.extrema]
            b = obj.burst
            self.burst = ((b.state.pole_stretch, b.state.pressure_mpa, b.state.volume_mm3)
                          if b.ok else None)
            p = getattr(obj, "problem", None)
            self.info = {} if p is None else {
                "clamp_radius_mm": p.clamp_radius_mm,
                "thickness_mm": p.thickness_mm,
                "material": p.material.description,
                "critical_i1": p.critical_i1,
                "pressure_scale_mpa": p.pressure_scale_mpa(),
            }
        if self.burst is not None and self.burst[0] > self.stretch[-1] * (1 + 1e-12):
            self.burst = None  # beyond the end of the curve


def _inflation_title(info):
    if not info or info.get("clamp_radius_mm") is None:
        return ""
    return (f"A = {info['clamp_radius_mm']:g} mm, H = {info['thickness_mm']:g} mm, "
            f"{info['material']}, critical I1 = {info['critical_i1']:g}")


def draw_inflation_curve(ax, curve, x="pole_stretch"):
    """Draws pressure against pole stretch (x='pole_stretch') or volume (x='volume') on `ax`,
    with the pressure's extrema and the burst marked; returns the legend handles."""
    c = curve if isinstance(curve, _InflationCurve) else _InflationCurve(curve)
    by_volume = x == "volume"
    xs = c.volume / 1e3 if by_volume else c.stretch
    (line,) = ax.plot(xs, c.pressure * 1e3, color="black", lw=1.8, zorder=3,
                      label="model: pressure p")
    handles = [line]
    seen = set()
    for kind, stretch, pressure, volume in c.extrema:
        maximum = kind == "maximum"
        label = ("pressure maximum (limit point)" if maximum else "pressure minimum")
        (mark,) = ax.plot([volume / 1e3 if by_volume else stretch], [pressure * 1e3],
                          "o" if maximum else "s", color="#1f77b4" if maximum else "#1b9e77",
                          ms=8, mec="white", mew=0.8, zorder=5,
                          label=label if kind not in seen else None)
        if kind not in seen:
            handles.append(mark)
            seen.add(kind)
        if not by_volume:
            ax.annotate(f"{'max' if maximum else 'min'} {pressure * 1e3:.4g} kPa\n"
                        f"at λ0 = {stretch:.4g}",
                        (stretch, pressure * 1e3), xytext=(0, 10 if maximum else -12),
                        textcoords="offset points", ha="center",
                        va="bottom" if maximum else "top", fontsize=9, zorder=6)
    if c.burst is not None:
        stretch, pressure, volume = c.burst
        (mark,) = ax.plot([volume / 1e3 if by_volume else stretch], [pressure * 1e3], "X",
                          color=CRITICAL_COLOUR, ms=10, mec="white", mew=0.8, zorder=5,
                          label="burst (largest I1 = critical I1)")
        handles.append(mark)
    ax.set_xlabel("enclosed volume V [cm³]" if by_volume else "pole stretch λ0")
    ax.set_ylabel("pressure p [kPa]")
    ax.set_xlim(0 if by_volume else 1, xs[-1] * 1.02)
    ax.set_ylim(0, max(c.pressure.max() * 1e3, 1e-12) * 1.25)
    return handles


def inflation_curve(curve, path=None, *, title=None):
    """The inflation (bulge) test: pressure against pole stretch (left) and against the
    enclosed volume (right), with the pressure's maximum (limit point) and minimum and the burst
    marked.  `curve`: puncture.inflation_curve(...) or `puncture inflate --format json`."""
    _check_path(path)
    c = _InflationCurve(curve)
    with matplotlib.rc_context(STYLE):
        fig = Figure(figsize=(11.0, 4.8), layout="constrained")
        left, right = fig.subplots(1, 2)
        handles = draw_inflation_curve(left, c)
        draw_inflation_curve(right, c, x="volume")
        scale = c.info.get("pressure_scale_mpa")
        if scale:
            kpa = scale * 1e3
            left.secondary_yaxis("right", functions=(lambda p: p / kpa, lambda n: n * kpa)
                                 ).set_ylabel("normalised pressure p A / (G H)")
        left.legend(handles=handles, loc="lower right", framealpha=0.9)
        left.set_title("pressure against the pole's stretch")
        right.set_title("pressure against the enclosed volume")
        fig.suptitle(title if title is not None
                     else "Inflation (bulge) test\n" + _inflation_title(c.info))
    return _finish(fig, path)


def fit_curves(fit, path=None, *, title=None):
    """`puncture fit curve --format json` drawn: each test's measured force against depth
    (points) with the fitted model (line) and, below, the residuals; measured (x) and fitted
    (o) puncture points where the records have them."""
    _check_path(path)
    tests = fit["tests"]
    with matplotlib.rc_context(STYLE):
        fig = Figure(figsize=(7.5, 6.5), layout="constrained")
        top, bottom = fig.subplots(2, 1, sharex=True, height_ratios=[3, 1])
        colours = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
        for k, t in enumerate(tests):
            colour = colours[k % len(colours)]
            name = os.path.basename(t["source"])
            depth = np.asarray(t["depth_mm"], dtype=float)
            top.plot(depth, t["force_n"], ".", ms=3, color=colour, label=f"{name} (measured)")
            top.plot(depth, t["model_force_n"], "-", lw=1.4, color=colour, label=f"{name} (fit)")
            bottom.plot(depth, t["residual_n"], ".", ms=3, color=colour)
            for key, marker in (("measured_puncture", "x"), ("model_puncture", "o")):
                p = t.get(key)
                if p:
                    top.plot(p["depth_mm"], p["force_n"], marker, ms=8, mfc="none",
                             color=colour)
        bottom.axhline(0.0, color="black", lw=0.8)
        top.set_ylabel("force [N]")
        bottom.set_ylabel("model - measured [N]")
        bottom.set_xlabel("depth from contact [mm]")
        top.legend(loc="upper left", framealpha=0.9, fontsize="small")
        estimates = ", ".join(
            f"{p['name']} = {p['value']:.4g}"
            + (f" ± {p['standard_error']:.2g}" if p["standard_error"] is not None else "")
            + (f" {p['unit']}" if p["unit"] else "")
            for p in fit["fit"]["free"])
        top.set_title(title if title is not None else
                      f"Force-depth fit: {estimates}\n(x measured puncture, o fitted)")
    return _finish(fig, path)
