"""Figures of the calibrations, drawn from the CLI's JSON (`--format json`), which the CLI's
--plot hands to plot_cli.py: the uniaxial fit (data, fit and residuals), the puncture band
(one-at-a-time ranges and the puncture points) and the J_lim scan (predicted puncture force
against J_lim, the measured force and the estimate)."""

import matplotlib
import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle

if __package__:
    from .plots import CRITICAL_COLOUR, STYLE, _check_path, _finish
else:  # run by plot_cli.py as a script: its directory is on sys.path
    from plots import CRITICAL_COLOUR, STYLE, _check_path, _finish

PARAMETER_NAMES = {"critical_i1": "critical I1", "friction": "friction μ'", "j_lim": "J_lim",
                   "shear_modulus_mpa": "shear modulus G"}
PARAMETER_COLOURS = ["#1f77b4", "#d95f02", "#1b9e77", "#7570b3"]


def _parameter_text(p):
    unit = f" {p['unit']}" if p.get("unit") else ""
    if p.get("value") is None:
        return f"{p['name']} not determined"
    se = p.get("standard_error")
    return f"{p['name']} = {p['value']:.4g}" + (f" ± {se:.2g}" if se is not None else "") + unit


def uniaxial_fit(fit, path=None, *, title=None):
    """`puncture fit uniaxial --format json`: the measured nominal stress and the fitted law's
    against the stretch (top), the residuals with ± one residual standard deviation (bottom)."""
    _check_path(path)
    points = fit["points"]
    stretch = np.array([p["stretch"] for p in points])
    measured = np.array([p["nominal_stress_mpa"] for p in points])
    fitted = np.array([p["fitted_stress_mpa"] for p in points])
    residual = fitted - measured
    order = np.argsort(stretch)
    f = fit["fit"]
    with matplotlib.rc_context(STYLE):
        fig = Figure(figsize=(7.5, 6.5), layout="constrained")
        top, bottom = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": [2.2, 1]})
        top.plot(stretch, measured, "o", color="black", ms=5, mfc="white", label="measured")
        top.plot(stretch[order], fitted[order], color=CRITICAL_COLOUR, lw=1.8,
                 label=f"fitted {f['law']}")
        top.set_ylabel("nominal stress P [MPa]")
        top.legend(loc="upper left", title="; ".join(_parameter_text(p)
                                                    for p in f["parameters"]))
        bottom.axhline(0.0, color="#555555", lw=0.8)
        sd = f.get("residual_sd_mpa")
        if sd:
            bottom.axhspan(-sd, sd, color="#cccccc", alpha=0.5, lw=0,
                           label=f"± residual sd {sd:.2g} MPa")
            bottom.legend(loc="upper left")
        bottom.plot(stretch, residual, "o", color="black", ms=4)
        bottom.set_ylabel("fit − data [MPa]")
        bottom.set_xlabel("stretch λ")
        test = f.get("test", "uniaxial")
        fig.suptitle(title if title is not None else
                     f"{test.capitalize()} test fitted with {f['law']} "
                     f"({len(points)} points, rms residual {f['rms_residual_mpa']:.3g} MPa)")
    return _finish(fig, path)


def uniaxial_comparison(comparison, path=None, *, title=None):
    """`puncture fit uniaxial --compare LAWS --format json`: the measured nominal stress and
    every converged law's fit against the stretch (top, legend ranked by AIC with delta AIC),
    and each law's residuals (bottom)."""
    _check_path(path)
    points = comparison["points"]
    stretch = np.array([p["stretch"] for p in points])
    measured = np.array([p["nominal_stress_mpa"] for p in points])
    order = np.argsort(stretch)
    ranking = {r["law"]: r for r in comparison["ranking"]}
    with matplotlib.rc_context(STYLE):
        fig = Figure(figsize=(8.0, 7.0), layout="constrained")
        top, bottom = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": [2.2, 1]})
        top.plot(stretch, measured, "o", color="black", ms=5, mfc="white", label="measured")
        bottom.axhline(0.0, color="#555555", lw=0.8)
        for k, f in enumerate(comparison["fits"]):
            fitted = np.array(f.get("fitted_stress_mpa") or [])
            if len(fitted) != len(stretch):
                continue  # not converged
            colour = f"C{k % 10}"  # matplotlib's ten distinct colours, one per law
            delta = ranking.get(f["law"], {}).get("delta_aic")
            label = f["law"] + (f" (ΔAIC {delta:.3g})" if delta is not None else
                                f" ({f['status']})")
            top.plot(stretch[order], fitted[order], lw=1.5, color=colour, label=label)
            bottom.plot(stretch[order], (fitted - measured)[order], "o-", ms=3, lw=0.8,
                        color=colour)
        top.set_ylabel("nominal stress P [MPa]")
        top.legend(loc="upper left", title="ranked by AIC")
        bottom.set_ylabel("fit − data [MPa]")
        bottom.set_xlabel("stretch λ")
        test = comparison["inputs"].get("test", "uniaxial")
        fig.suptitle(title if title is not None else
                     f"{test.capitalize()} test: {len(comparison['fits'])} laws compared "
                     f"({len(points)} points)")
    return _finish(fig, path)


def _found(samples):
    return [s for s in samples if s.get("found")]


def puncture_band(band, path=None, *, title=None):
    """`puncture calibrate band --format json`: the puncture force's range over each
    parameter's interval, one at a time (left, widest first), and every puncture point computed,
    with the nominal one and the band (right)."""
    _check_path(path)
    nominal = band["nominal"]
    sens = sorted(band["sensitivities"], key=lambda s: abs(s["force_change_n"]))
    with matplotlib.rc_context(STYLE):
        fig = Figure(figsize=(12.0, 5.0), layout="constrained")
        left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1.2]})
        for k, s in enumerate(sens):
            forces = [x["force_n"] for x in _found(s["samples"])]
            if not forces:
                continue
            left.barh(k, max(forces) - min(forces), left=min(forces), height=0.55,
                      color=PARAMETER_COLOURS[k % len(PARAMETER_COLOURS)])
        left.set_yticks(range(len(sens)),
                        [PARAMETER_NAMES.get(s["parameter"], s["parameter"]) for s in sens])
        if nominal.get("found"):
            left.axvline(nominal["force_n"], color="black", lw=1.2, label="nominal")
            left.legend(loc="lower right")
        b = band["band"]
        for edge in (b["force_min_n"], b["force_max_n"]):
            left.axvline(edge, color="#888888", lw=1, ls="--")
        margin = 0.05 * (b["force_max_n"] - b["force_min_n"])
        left.set_xlim(b["force_min_n"] - margin, b["force_max_n"] + margin)
        left.set_ylim(-0.6, len(sens) - 0.4)
        left.set_xlabel("puncture force F [N] (dashed: the band's ends)")
        left.set_title("one parameter at a time over its interval")
        right.add_patch(Rectangle(
            (b["depth_min_mm"], b["force_min_n"]), b["depth_max_mm"] - b["depth_min_mm"],
            b["force_max_n"] - b["force_min_n"], facecolor="#dddddd", edgecolor="#888888",
            label="band (corners and one at a time)"))
        for k, s in enumerate(sens):
            found = _found(s["samples"])
            right.plot([x["depth_mm"] for x in found], [x["force_n"] for x in found], "o-",
                       color=PARAMETER_COLOURS[k % len(PARAMETER_COLOURS)], ms=4, lw=1,
                       label=PARAMETER_NAMES.get(s["parameter"], s["parameter"]))
        corners = _found(band.get("corners", []))
        if corners:
            right.plot([x["depth_mm"] for x in corners], [x["force_n"] for x in corners], "s",
                       color="#555555", ms=5, mfc="white", label="corners")
        if nominal.get("found"):
            right.plot([nominal["depth_mm"]], [nominal["force_n"]], "*", color=CRITICAL_COLOUR,
                       ms=14, mec="white", label="nominal puncture")
        right.set_xlabel("puncture depth δ [mm]")
        right.set_ylabel("puncture force F [N]")
        right.legend(loc="upper left", fontsize=9)
        right.set_title("puncture points")
        right.autoscale_view()
        fig.suptitle(title if title is not None else
                     f"Puncture band: F from {b['force_min_n']:.4g} to {b['force_max_n']:.4g} N"
                     f", δ from {b['depth_min_mm']:.4g} to {b['depth_max_mm']:.4g} mm")
    return _finish(fig, path)


def j_lim_scan(report, path=None, *, title=None):
    """`puncture calibrate jlim --format json`: the predicted puncture force against J_lim
    (the scan), the measured force and the J_lim that predicts it, and the neo-Hookean limit
    (J_lim → ∞).  Near J_lim = critical I1 − 3 the force grows without bound (locking)."""
    _check_path(path)
    e = report["estimate"]
    scan = e["scan"]
    j = np.array([s["j_lim"] for s in scan])
    force = np.array([s["puncture_force_n"] for s in scan])
    ok = np.isfinite(force)
    with matplotlib.rc_context(STYLE):
        fig = Figure(figsize=(7.5, 5.0), layout="constrained")
        ax = fig.add_subplot()
        ax.loglog(j[ok], force[ok], color="black", lw=1.6, label="predicted puncture force")
        ax.axhline(e["force_n"], color="#1f77b4", lw=1.2, ls="--",
                   label=f"measured {e['force_n']:.4g} N")
        if e.get("neo_hookean_force_n"):
            ax.axhline(e["neo_hookean_force_n"], color="#888888", lw=1, ls=":",
                       label=f"neo-Hookean limit {e['neo_hookean_force_n']:.4g} N")
        critical = report.get("inputs", {}).get("problem", {}).get("critical_i1")
        if critical:
            ax.axvline(critical - 3.0, color=CRITICAL_COLOUR, lw=1, ls=":",
                       label=f"critical I1 − 3 = {critical - 3.0:.4g}: locks at puncture")
        value = e["j_lim"].get("value")
        if e["j_lim"].get("found") and value is not None:
            ax.plot([value], [e["force_n"]], "o", color=CRITICAL_COLOUR, ms=8, mec="white",
                    label=f"J_lim = {value:.4g}")
        ax.set_xlabel("J_lim (Gent)")
        ax.set_ylabel("puncture force F [N]")
        ax.legend(loc="upper right")
        fig.suptitle(title if title is not None else "J_lim from one puncture force")
    return _finish(fig, path)
