"""Figures from the bindings, from the CLI's JSON, and through the CLI's --plot and figures."""

import json
import os
import struct
import subprocess
import sys

import numpy as np
import pytest

import puncture as pu

pytest.importorskip("matplotlib")
from puncture import plots  # noqa: E402

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == PNG_SIGNATURE, f"{path} is not a PNG"
    return struct.unpack(">II", head[16:24])


def check_png(path, min_width=800):
    width, height = png_size(path)
    assert width >= min_width and height >= 500
    assert os.path.getsize(path) > 20_000  # drawn, not blank


def check_svg(path, label="[mm]"):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    assert "<svg" in text and "</svg>" in text
    assert "<text" in text and label in text  # labels kept as text


@pytest.fixture(scope="module")
def default_curve():
    return pu.loading_curve(pu.Problem(), points=60)


def test_loading_curve_png_and_svg(tmp_path, default_curve):
    fig = plots.loading_curve(default_curve, tmp_path / "curve.png")
    plots.loading_curve(default_curve, tmp_path / "curve.svg")
    check_png(tmp_path / "curve.png")
    check_svg(tmp_path / "curve.svg")
    ax = fig.axes[0]
    assert ax.get_xlabel() == "indentation depth δ [mm]"
    assert ax.get_ylabel() == "indenter force F [N]"
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "slip without Part II" in labels and "slip with Part II" in labels
    assert any("puncture" in label for label in labels)


def test_loading_curve_with_a_stick_stage(tmp_path):
    curve = pu.loading_curve(pu.Problem(stick="force:0.3"), points=40)
    fig = plots.loading_curve(curve, tmp_path / "stick.png")
    check_png(tmp_path / "stick.png")
    labels = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert "stick (held at the edge)" in labels
    texts = [t.get_text() for t in fig.axes[0].texts]
    assert any(t.startswith("stick → slip") for t in texts)


def test_profile_of_several_loads(tmp_path, default_curve):
    problem = pu.Problem()
    states = [pu.solve_at_force(problem, f) for f in (0.1, 0.3)] + [default_curve.puncture]
    fig = plots.profile(states, tmp_path / "profile.png")
    plots.profile(states, tmp_path / "profile.svg")
    check_png(tmp_path / "profile.png")
    check_svg(tmp_path / "profile.svg")
    whole, tip = fig.axes[:2]
    assert whole.get_xlabel() == "radius r [mm]" and "[mm]" in whole.get_ylabel()
    assert whole.get_aspect() == 1.0 and tip.get_aspect() == 1.0  # to scale
    # the indenter, to scale: a rectangle 2a wide
    rectangles = [p for p in whole.patches if type(p).__name__ == "Rectangle"]
    assert any(abs(r.get_width() - 4.0) < 1e-12 for r in rectangles)


def test_profile_draws_a_curved_probe_to_scale(tmp_path):
    a = 2.0
    state = pu.solve_at_depth(pu.Problem(indenter=pu.SphereTipped(a), friction=0.0), 10.0)
    fig = plots.profile([state], tmp_path / "profile.png")
    whole = fig.axes[0]
    polygons = [p for p in whole.patches if type(p).__name__ == "Polygon"]
    assert len(polygons) == 1
    xy = polygons[0].get_xy()
    tip = xy[:, 1].min()
    assert tip == pytest.approx(-state.depth_mm, abs=1e-12)
    # below the equator every vertex lies on the hemisphere about (0, tip + a), on both sides
    lower = xy[xy[:, 1] < tip + a - 1e-9]
    assert len(lower) >= 40 and lower[:, 0].min() < 0 < lower[:, 0].max()
    assert np.allclose(np.hypot(lower[:, 0], lower[:, 1] - (tip + a)), a, atol=1e-12)


def test_probe_outlines():
    # the cone: the tip sphere up to its tangency with the cone, then the generatrix at the
    # half-angle from the axis to the shank
    rt, alpha, shank = 0.2, 30.0, 2.0
    points = np.array(pu.Cone(shank, alpha, rt).outline())
    tangency = np.radians(90.0 - alpha)
    sphere = points[:-1]
    assert np.allclose(np.hypot(sphere[:, 0], sphere[:, 1] - rt), rt, atol=1e-15)
    assert sphere[-1] == pytest.approx([rt * np.sin(tangency), rt * (1 - np.cos(tangency))])
    (r0, h0), (r1, h1) = points[-2], points[-1]
    assert r1 == shank and (r1 - r0) / (h1 - h0) == pytest.approx(np.tan(np.radians(alpha)))
    # the rounded flat punch: the flat face, then a quarter circle of the fillet's radius
    rho = 0.5
    face = np.array(pu.FlatPunch(2.0, fillet_radius_mm=rho).outline())
    assert face[0].tolist() == [0.0, 0.0] and face[-1] == pytest.approx([2.0, rho])
    assert np.allclose(np.hypot(face[1:, 0] - (2.0 - rho), face[1:, 1] - rho), rho, atol=1e-15)
    assert pu.FlatPunch(2.0).outline() == [(0.0, 0.0), (2.0, 0.0)]
    # the ball over its equator to the rod
    ball = np.array(pu.Ball(1.0, 3.0).outline())
    assert np.allclose(np.hypot(ball[:, 0], ball[:, 1] - 3.0), 3.0, atol=1e-15)
    assert ball[-1][0] == pytest.approx(1.0) and ball[-1][1] > 3.0  # on the upper hemisphere


def test_stretch_fields(tmp_path):
    state = pu.solve_at_force(pu.Problem(), 0.5)
    for scale in ("log", "linear"):
        fig = plots.stretch_fields(state, tmp_path / f"fields_{scale}.png", xscale=scale)
        check_png(tmp_path / f"fields_{scale}.png")
    top, bottom = fig.axes[:2]
    assert bottom.get_xlabel() == "reference radius R [mm]"
    labels = [t.get_text() for t in bottom.get_legend().get_texts()]
    assert "critical I1 = 95.2" in labels
    plots.stretch_fields(state, tmp_path / "fields.svg")
    check_svg(tmp_path / "fields.svg")


def test_plots_of_held_and_unloaded_states(tmp_path):
    held = pu.solve_at_force(pu.Problem(stick="always"), 0.5)
    plots.state_overview(held, tmp_path / "held.png")
    check_png(tmp_path / "held.png")
    flat = pu.solve_at_depth(pu.Problem(), 0.0)
    plots.state_overview(flat, tmp_path / "flat.png")
    check_png(tmp_path / "flat.png")


def test_plots_from_cli_json(tmp_path, cli):
    curve_json = cli.json("curve", "--points", "30", "--stick", "depth:10")
    plots.loading_curve(curve_json, tmp_path / "curve.png")
    check_png(tmp_path / "curve.png")
    state_json = cli.json("state", "--force", "0.4")
    plots.profile(state_json, tmp_path / "profile.png")
    plots.stretch_fields(state_json, tmp_path / "fields.png")
    plots.state_overview(state_json, tmp_path / "state.png")
    for name in ("profile", "fields", "state"):
        check_png(tmp_path / f"{name}.png")


def test_bad_file_name_is_a_value_error(tmp_path, default_curve):
    with pytest.raises(ValueError, match=r"must end in \.png, \.svg or \.pdf"):
        plots.loading_curve(default_curve, tmp_path / "curve.jpg")
    with pytest.raises(ValueError, match="xscale"):
        plots.stretch_fields(default_curve.puncture, tmp_path / "x.png", xscale="cubic")


@pytest.mark.parametrize("suffix", [".png", ".svg"])
def test_cli_plot_curve(tmp_path, cli, suffix):
    target = tmp_path / f"curve{suffix}"
    rc, out, err = cli.run("curve", "--points", "30", "--format", "csv", "--plot", target)
    assert rc == 0, err
    assert out.startswith("depth_mm,force_n,")  # the results are still written
    (check_png if suffix == ".png" else check_svg)(target)


def test_cli_plot_fit_curve(tmp_path, cli):
    """fit curve --plot: the records, the fitted curves and the residuals, from the fit's JSON."""
    here = os.path.dirname(os.path.abspath(__file__))
    record = os.path.join(here, "..", "..", "tests", "cli", "indentation_record.csv")
    target = tmp_path / "fit.png"
    rc, out, err = cli.run("fit", "curve", record, "--free", "shear-modulus,jlim",
                           "--contact-depth", "2", "--plot", target)
    assert rc == 0, err
    assert "shear-modulus" in out  # the report is still written
    check_png(target)


def test_cli_plot_state(tmp_path, cli):
    target = tmp_path / "state.png"
    rc, out, err = cli.run("state", "--depth", "20", "--plot", target)
    assert rc == 0, err
    assert "Equilibrium at depth 20 mm" in out
    check_png(target)


def test_cli_plot_rejections(tmp_path, cli):
    rc, _, err = cli.run("puncture", "--plot", tmp_path / "p.png")
    assert rc == 1 and "--plot: draws a curve or a state" in err
    rc, _, err = cli.run("curve", "--plot", tmp_path / "p.jpg")
    assert rc == 1 and "--plot: the file name must end in .png, .svg or .pdf" in err
    rc, _, err = cli.run("curve", "--plot", tmp_path / "no" / "dir" / "p.png")
    assert rc == 1 and "--plot: cannot open" in err


def test_cli_plot_without_python_or_matplotlib(tmp_path, cli):
    target = tmp_path / "curve.png"
    rc, out, err = cli.run("curve", "--plot", target, env={"PUNCTURE_PYTHON": "/no/such/python"})
    assert rc == 3 and out == ""
    assert "plot failed: plots need Python 3 with matplotlib: cannot run the interpreter " \
           "'/no/such/python'" in err
    # A Python without its site packages: no numpy, no matplotlib.
    bare = tmp_path / "bare-python"
    bare.write_text(f'#!/bin/sh\nexec {sys.executable} -S "$@"\n')
    bare.chmod(0o755)
    rc, out, err = cli.run("curve", "--points", "5", "--format", "csv", "--plot", target,
                           env={"PUNCTURE_PYTHON": str(bare)})
    assert rc == 3
    assert out.startswith("depth_mm,")
    assert "cannot import" in err and "python3-matplotlib" in err
    assert f"plot failed: '{bare}' lacks numpy or matplotlib" in err
    assert not target.exists()


def test_plot_script_runs_without_the_extension(tmp_path, cli):
    """plot_cli.py, as the CLI runs it: a script next to plots.py, no compiled module."""
    data = tmp_path / "curve.json"
    data.write_text(json.dumps(cli.json("curve", "--points", "20")))
    script = os.path.join(os.path.dirname(plots.__file__), "plot_cli.py")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    p = subprocess.run([sys.executable, script, "curve", str(data), str(tmp_path / "c.png")],
                       capture_output=True, text=True, env=env)
    assert p.returncode == 0, p.stderr
    check_png(tmp_path / "c.png")
    p = subprocess.run([sys.executable, script, "bogus"], capture_output=True, text=True, env=env)
    assert p.returncode == 2 and "usage" in p.stderr


def test_cli_figures(tmp_path, cli):
    out_dir = tmp_path / "figures"
    rc, out, err = cli.run("figures", "--out", out_dir, "--points", "40")
    assert rc == 0, err
    names = ["fig11", "fig12a", "fig12b", "fig13a", "fig13b", "fig13c", "fig13d", "fig13e",
             "fig13", "fig14", "probes"]
    for name in names:
        check_png(out_dir / f"{name}.png", min_width=900)
        label = {"fig11": "stretch λ", "fig12b": "friction coefficient"}.get(name, "[mm]")
        check_svg(out_dir / f"{name}.svg", label=label)
        assert str(out_dir / f"{name}.png") in out
    data = json.loads((out_dir / "figures-data.json").read_text())
    panels = {p["label"]: p for p in data["fig13"]["panels"]}
    assert set(panels) == set("abcde")
    ring, eq18 = panels["b"]["curves"]
    assert ring["part_two_equation"] == "ring-balance" and eq18["part_two_equation"] == \
        "paper-eq18"
    # the same puncture points as the library (docs/model.md section 10)
    assert ring["puncture"]["force_n"] == pytest.approx(
        pu.predict_puncture(pu.Problem()).force_n, rel=1e-9)
    assert eq18["puncture"]["force_n"] == pytest.approx(3.3409, abs=1e-4)
    assert panels["e"]["friction"] == 1.95 and panels["e"]["indenter_radius_mm"] == 1.0
    # Fig. 14: the balloons, lubricated and dry, both punctured, the dry one later and harder
    fig14 = data["fig14"]
    assert fig14["indenter_radius_mm"] == 1.0 and fig14["pressure_assumed"]
    lubricated, dry = fig14["curves"]
    assert (lubricated["friction"], dry["friction"]) == (0.18, 1.95)
    assert dry["puncture"]["force_n"] > lubricated["puncture"]["force_n"]
    assert dry["puncture"]["depth_mm"] > lubricated["puncture"]["depth_mm"]
    series = data["fig12b"]["series"]
    assert sorted({s["radius_ratio"] for s in series}) == [0.04, 0.08, 0.12]
    # The probes: the library's puncture points (solved directly, whatever --points), the
    # rounded corner softer than the sharp one.
    probes = {p["key"]: p for p in data["probes"]["probes"]}
    assert list(probes) == ["flat", "rounded", "sphere-tipped", "cone"]
    for key, indenter in [("flat", pu.FlatPunch(2.0)),
                          ("rounded", pu.FlatPunch(2.0, fillet_radius_mm=0.5)),
                          ("sphere-tipped", pu.SphereTipped(2.0)),
                          ("cone", pu.Cone(2.0, 30.0, 0.2))]:
        expected = pu.predict_puncture(pu.Problem(indenter=indenter, friction=0.0))
        assert probes[key]["puncture"]["force_n"] == pytest.approx(expected.force_n, rel=1e-9)
        assert probes[key]["puncture"]["energy_mj"] > 0
        assert max(probes[key]["depth_mm"]) == pytest.approx(expected.depth_mm, rel=1e-9)
    assert probes["rounded"]["puncture"]["force_n"] < probes["flat"]["puncture"]["force_n"]
    outline = probes["cone"]["outline"]
    assert outline["r_mm"][0] == 0.0 and max(outline["r_mm"]) == pytest.approx(2.0)
    rc, _, err = cli.run("figures", "--out", out_dir, "--format", "json")
    assert rc == 1 and "--format: does not apply to 'figures'" in err
    # Drawn as a reader needs them: Fig. 13's axes fit the default (solid) curve, not the
    # printed equation's far deeper one; Fig. 12(a) names the states past puncture; Fig. 12(b)
    # is sampled finely enough (0.01 in friction) not to cut the bends where Part II vanishes.
    from puncture import paper_figures
    fig = paper_figures.fig13_panel(data, "b")
    ax = fig.axes[0]
    depth = max(ring["depth_mm"])
    assert depth < ax.get_xlim()[1] <= 1.5 * depth
    assert max(eq18["depth_mm"]) > ax.get_xlim()[1]
    assert any("off the axes" in t.get_text() for t in ax.get_legend().get_texts())
    from matplotlib.legend import Legend
    fig = paper_figures.fig12a(data)
    friction_legend = next(c for c in fig.axes[0].get_children()
                           if isinstance(c, Legend) and c.get_title().get_text() == "friction")
    labels = [t.get_text() for t in friction_legend.get_texts()]
    assert any("(past puncture)" in t for t in labels)
    colours = [line.get_color() for line in friction_legend.get_lines() if line.get_ls() == "-"]
    assert len(colours) >= 5 and len(set(colours)) == len(colours)
    frictions = series[0]["friction"]
    assert max(b - a for a, b in zip(frictions, frictions[1:])) <= 0.01 + 1e-12


# ----- calibrations: fit uniaxial, calibrate band, calibrate jlim ---------------------------

CLI_DATA = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "cli")


@pytest.mark.parametrize("args", [
    ("fit", "uniaxial", os.path.join(CLI_DATA, "uniaxial_gent.csv")),
    ("calibrate", "band", "--critical-i1-range", "90,100", "--jlim-range", "110,130"),
    ("calibrate", "jlim", "--puncture-force", "0.7"),
], ids=["uniaxial-fit", "band", "jlim"])
def test_cli_plot_calibrations(tmp_path, cli, args):
    target = tmp_path / "calibration.png"
    rc, out, err = cli.run(*args, "--plot", target)
    assert rc == 0, err
    assert out  # the report is still written
    check_png(target)


def test_uniaxial_fit_figure_draws_the_cli_numbers(cli):
    from puncture import calibration_plots
    data = cli.json("fit", "uniaxial", os.path.join(CLI_DATA, "uniaxial_gent.csv"))
    fig = calibration_plots.uniaxial_fit(data)
    top, bottom = fig.axes
    measured = [p["nominal_stress_mpa"] for p in data["points"]]
    fitted = [p["fitted_stress_mpa"] for p in data["points"]]
    assert list(top.lines[0].get_ydata()) == measured
    assert sorted(top.lines[1].get_ydata()) == sorted(fitted)
    residuals = bottom.lines[-1].get_ydata()
    assert list(residuals) == [f - m for f, m in zip(fitted, measured)]


def test_cli_plot_refused_where_nothing_is_drawn(tmp_path, cli):
    rc, _, err = cli.run("calibrate", "friction", "--indenter-radius", "1", "--puncture-force",
                         "1.72", "--hole-ratio", "1.58", "--plot", tmp_path / "f.png")
    assert rc == 1 and "--plot: draws 'fit uniaxial', 'fit curve', 'calibrate band' and 'calibrate jlim'" in err
    assert not (tmp_path / "f.png").exists()
