"""The models of `polydem analytic` from Python: each against the command
line's --json (every number the Python value to the command line's 12
significant digits) or a closed form."""
import json
import math

import numpy as np
import pytest
import polydem
from conftest import deck, polydem_cli

PILLAR = deck("examples/verification/rocking_onset.toml")  # 0.5 x 0.5 x 2 m on a fixed base, phi 30 deg
COARSE_SPIRE = '[spire]\ncourse_height = 1.0\nstones_per_face = 1\njoint_pattern = "aligned"\n'
WALL_CLOCK = {"build_s", "solve_s", "initial_mesh_s", "seconds", "wall_s"}


def cli_json(*args):
    p = polydem_cli("analytic", *args, "--json")
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)


def assert_as_printed(py, cli, path="$"):
    """py (full precision) is what the command line printed as cli."""
    if isinstance(cli, dict):
        assert isinstance(py, dict) and list(py) == list(cli), path
        for k in cli:
            if k not in WALL_CLOCK:
                assert_as_printed(py[k], cli[k], f"{path}.{k}")
    elif isinstance(cli, list):
        assert len(py) == len(cli), path
        for i, (a, b) in enumerate(zip(py, cli)):
            assert_as_printed(a, b, f"{path}[{i}]")
    elif isinstance(cli, float) or (isinstance(py, float) and not isinstance(cli, bool)):
        assert float(f"{float(py):.12g}") == cli, f"{path}: {py!r} printed {cli!r}"
    else:
        assert py == cli and type(py) is type(cli), f"{path}: {py!r} vs {cli!r}"


def test_static_lambda_is_eq_1_and_the_command_line():
    r = polydem.analytical.static_lambda(r_b=1.06, H=9.4, h_c=5.0)
    assert r["lambda_eq1"] == 3 * 1.06 / 9.4
    assert r["lambda_eq2_at_h_c"] > r["lambda_eq2_governing"]
    assert_as_printed(r, cli_json("lambda", "--r_b", "1.06", "--H", "9.4", "--h_c", "5"))
    assert polydem.analytical.static_lambda()["inputs"]["h_c_m"] == 9.4  # h_c defaults to H


def test_beam_modes_are_naguleswarans_and_the_command_line():
    r = polydem.analytical.beam(section="octagon", modes=3)
    assert [round(m["Omega"], 2) for m in r["modes"]] == [5.32, 15.21, 30.02]
    assert_as_printed(r, cli_json("beam", "--section", "octagon", "--modes", "3"))


def test_rocking_matches_the_command_line():
    args = dict(body="block", b=0.2, h=1.0, load="pulse", a_p=0.5, T_p=0.5, t_end=3.0)
    r = polydem.analytical.rocking(every=0.1, **args)
    assert r["history"].shape[1] == 4 and r["history_columns"][1] == "theta_rad"
    printed = cli_json("rocking", "--body", "block", "--b", "0.2", "--h", "1", "--load", "pulse", "--a_p", "0.5",
                       "--T_p", "0.5", "--t_end", "3")
    r["history"] = r["history"].tolist()
    assert_as_printed(r, printed)
    full = polydem.analytical.rocking(**args)["history"]  # every step
    assert len(full) > len(r["history"]) and full[-1].tolist() == r["history"][-1]


def test_rocking_uplifts_at_once_above_tan_alpha():
    r = polydem.analytical.rocking(body="block", b=0.2, h=1.0, load="constant", a=0.25, t_end=2.0)
    assert r["properties"]["uplift_g"] == math.tan(math.atan(0.2))
    assert r["uplifted"] and r["t_uplift_s"] == 0.0 and r["overturned"] and r["mode"] == "mode II"


def test_collapse_diagram_matches_the_command_line():
    r = polydem.analytical.collapse_diagram(body="cone", r_b=0.3834, H=3.4, Tp_min=0.25, Tp_max=2.0, Tp_count=3,
                                            points=20)
    assert [c["T_p_s"] for c in r["columns"]] == [0.25, 1.125, 2.0]
    assert_as_printed(r, cli_json("collapse-diagram", "--body", "cone", "--r_b", "0.3834", "--H", "3.4", "--Tp_min",
                                  "0.25", "--Tp_max", "2", "--Tp_count", "3", "--points", "20"))


def test_cracked_cone_p_matches_the_command_line():
    r = polydem.analytical.cracked_cone_p(count=4)
    assert [p["H_bar_m"] for p in r["curve"]][::3] == [3.4, 9.4]
    p = [c["p_rad_s"] for c in r["curve"]]
    assert p == sorted(p, reverse=True) and abs(r["p_max_rad_s"] - p[0]) < 1e-9 * p[0]  # the tip alone rocks fastest
    assert_as_printed(r, cli_json("cracked-cone-p", "--count", "4"))


def test_refined_lambda_matches_the_command_line(tmp_path):
    path = tmp_path / "coarse_spire.toml"
    path.write_text(COARSE_SPIRE)
    r = polydem.analytical.refined_lambda(str(path), no_windows=True)
    assert r["windows"] == 0 and r["lambda_refined"] <= r["lambda_eq1"]
    assert_as_printed(r, cli_json("refined-lambda", "--deck", path, "--no-windows"))
    # A Scene with the override gives the same.
    scene = polydem.Scene.from_deck(path)
    assert polydem.analytical.refined_lambda(scene, no_windows=True) == r


def test_dem_frequency_matches_the_command_line(tmp_path):
    path = tmp_path / "coarse_spire.toml"
    path.write_text(COARSE_SPIRE)
    options = dict(settle=0.02, duration=0.05, threads=2)
    r = polydem.analytical.dem_frequency(str(path), no_windows=True, **options)
    assert r["status"] == "intact" and r["samples"] == len(r["t"]) == len(r["u"])
    csv = tmp_path / "tip.csv"
    printed = cli_json("dem-frequency", "--deck", path, "--no-windows", "--settle", "0.02", "--duration", "0.05",
                       "--threads", "2", "--csv", csv)
    t, u = r.pop("t"), r.pop("u")
    assert_as_printed(r, printed)
    rows = np.loadtxt(csv, delimiter=",", skiprows=1)
    assert [float(f"{x:.9g}") for x in t] == list(rows[:, 0])
    assert [float(f"{x:.9g}") for x in u] == list(rows[:, 1])


def test_limit_lp_is_the_pillars_bound_and_the_command_line():
    r = polydem.analytical.limit_lp(PILLAR, phi=[10, 30], direction=90, pyramid="inscribed", method="simplex")
    lam = [c["inscribed"]["lambda"] for c in r["cases"]]
    assert abs(lam[0] - math.tan(math.radians(10))) < 1e-9  # slides: tan phi
    assert abs(lam[1] - 0.25) < 1e-9                         # rocks: b/h
    assert_as_printed(r, cli_json("limit-lp", "--deck", PILLAR, "--phi", "10,30", "--direction", "90",
                                  "--pyramid", "inscribed", "--method", "simplex"))
    both = polydem.analytical.limit_lp(polydem.Scene.from_deck(PILLAR))  # the deck's phi, both pyramids
    assert both["cases"][0]["friction_angle_deg"] == 30.0
    assert set(both["cases"][0]) >= {"circumscribed", "inscribed"}


def test_arch_thickness_matches_the_command_line():
    r = polydem.analytical.arch_thickness(voussoirs=[3, 9])
    assert r["cases"][0]["falls"] == 0.0                     # 3 voussoirs stand however thin
    assert abs(r["cases"][1]["t_over_R"] - 0.1015) < 1e-3   # tests/studies/arch_thickness_test.cpp
    assert_as_printed(r, cli_json("arch-thickness", "--voussoirs", "3,9"))


def test_fragility_from_lists_and_from_csv_match_the_command_line(tmp_path):
    rng = np.random.default_rng(4)
    capacity = 0.4 * np.exp(0.3 * rng.standard_normal(25))
    record, im, state = [], [], []
    for i, c in enumerate(capacity):
        record += [f"r{i}", f"r{i}"]
        im += [0.5 * c, c]
        state += ["intact", "collapsed"]
    csv = tmp_path / "runs.csv"
    csv.write_text("record,im,state\n" + "".join(f"{r},{x!r},{s}\n" for r, x, s in zip(record, im, state)))
    r = polydem.analytical.fragility(im=im, state=state, record=record, bootstrap=100, out=tmp_path / "py")
    collapsed = r["states"][2]
    assert collapsed["status"] == "fitted"
    # Uncensored IDA: the log-moments of the capacities.
    assert math.isclose(collapsed["theta"], math.exp(np.mean(np.log(capacity))), rel_tol=1e-12)
    assert math.isclose(collapsed["beta"], np.std(np.log(capacity)), rel_tol=1e-12)
    assert r["im"].shape == collapsed["probability"].shape == collapsed["low"].shape
    assert (tmp_path / "py" / "fragility_curves.csv").exists()
    p = polydem_cli("analytic", "fragility", csv, "--out", tmp_path / "cli", "--bootstrap", "100", "--no-plot", "--json")
    assert p.returncode == 0, p.stderr
    cli = json.loads(p.stdout)
    assert cli["states"][2]["theta"] == collapsed["theta"]
    assert cli["states"][2]["high"] == collapsed["high"].tolist()
    assert polydem.analytical.fragility(csv=csv, bootstrap=100)["states"][2]["low"].tolist() == cli["states"][2]["low"]
    with pytest.raises(ValueError):
        polydem.analytical.fragility(im=[0.1, -0.2], state=["intact", "collapsed"])


def test_synthetic_suite_matches_the_command_line_bit_for_bit(tmp_path):
    r = polydem.analytical.synthetic_suite(6.0, 30.0, 600.0, count=2, seed=9, out=tmp_path / "py")
    a = r["records"][1]["acceleration_m_s2"]
    assert a[0] == 0.0 and a.size > 1000 and r["records"][1]["name"] == "synthetic_02"
    p = polydem_cli("analytic", "synthetic", "--magnitude", "6", "--distance", "30", "--vs30", "600", "--count", "2",
                    "--seed", "9", "--out", tmp_path / "cli")
    assert p.returncode == 0, p.stderr
    for f in ("synthetic_01.csv", "synthetic_02.csv", "suite.toml", "records.csv"):
        assert (tmp_path / "py" / f).read_bytes() == (tmp_path / "cli" / f).read_bytes(), f
    written = np.loadtxt(tmp_path / "cli" / "synthetic_02.csv", delimiter=",", skiprows=5)
    assert np.array_equal(written[:, 1], a)
