"""The collapse search and sweeps from Python, as numpy structured arrays."""
import numpy as np
import polydem
import pytest
from conftest import deck

PILLAR = deck("examples/verification/rocking_onset.toml")  # b/h = 0.25: rocks from 0.25 g


def test_collapse_search_bisection_and_ramp(tmp_path):
    rows = []
    r = polydem.collapse_search(PILLAR, [0.0], "both", low_g=0.1, high_g=0.5, tolerance_g=0.1, rise_time=0.2,
                                hold_time=0.8, ramp_rate_g=1.0, threads=1, out=tmp_path, progress=rows.append)
    d = r.directions
    assert d.dtype.names[:2] == ("direction_deg", "bisection_g") and len(d) == 1
    assert d["low_g"][0] < d["bisection_g"][0] < d["high_g"][0] and d["high_g"][0] - d["low_g"][0] <= 0.1
    assert 0.2 < d["bisection_g"][0] < 0.45          # above the static onset b/h = 0.25 g, up to the bracket
    assert 0.25 < d["ramp_g"][0] < 0.45              # the mechanism forms above the onset
    assert len(r.trials) == len(rows) == d["bisection_runs"][0] + 1
    assert set(r.trials["method"]) == {"constant", "ramp"}  # a bisection trial is a constant acceleration
    assert r.lowest_g == pytest.approx(min(d["bisection_g"][0], d["ramp_g"][0]))
    assert (tmp_path / "collapse.json").exists()


def test_sweep_matches_single_runs():
    scene = polydem.Scene.from_deck(PILLAR, set={"ground_motion.kind": "constant", "ground_motion.acceleration_g": 0.1,
                                                       "simulation.end_time": 0.6})
    seen = []
    r = polydem.sweep(scene, vary={"ground_motion.acceleration_g": [0.1, 0.45]}, threads=1, progress=seen.append)
    p = r.points
    assert list(p["ground_motion.acceleration_g"]) == [0.1, 0.45] and len(seen) == 2
    assert p["status"][0] == "intact" and p["status"][1] != "intact"
    one = polydem.run(scene, set={"ground_motion.acceleration_g": 0.45}, threads=1, progress=False)
    assert p["peak_displacement"][1] == one.assessment["peak_displacement_m"]
    assert p["steps"][1] == one.steps
    assert p["dislodged"][1] == one.assessment["dislodged"]["count"]


def test_sweep_bad_key_raises_before_running():
    with pytest.raises(polydem.DeckError) as e:
        polydem.sweep(PILLAR, vary={"joint.frction_angle": [30, 40]}, progress=False)
    assert e.value.key == "joint.frction_angle"


TIP = deck("examples/spire/tip_pulse.toml")  # one block: runs of about 0.05 s


def test_ensemble_matches_the_command_line(tmp_path):
    """polydem.ensemble and `polydem ensemble` run the same replicas: the
    same draws and outcomes, bit for bit, and the same distributions."""
    import csv
    from conftest import polydem_cli
    setting = {"simulation.end_time": 1.2}
    seen = []
    r = polydem.ensemble(TIP, 4, seed=5, threads=1, progress=seen.append, set=setting)
    assert len(r.replicas) == len(seen) == 4 and r.summary["replicas"] == 4 and r.summary["seed"] == 5
    assert r.replicas["friction_angle_shift_deg"][0] == 0 and r.replicas["normal_stiffness_factor"][0] == 1
    assert np.all(np.abs(r.replicas["friction_angle_shift_deg"]) <= 0.5)
    assert np.all(np.abs(r.replicas["shear_stiffness_factor"] - 1) <= 0.05)
    out = tmp_path / "cli"
    done = polydem_cli("ensemble", TIP, "--replicas", 4, "--seed", 5, "--jobs", 2, "--threads", 1,
                       "--set", "simulation.end_time=1.2", "--out", out)
    assert done.returncode == 0, done.stderr
    with open(out / "replicas.csv") as f:
        rows = list(csv.DictReader(f))
    for name in ("friction_angle_shift_deg", "time_shift_s", "largest_initial_speed_m_s", "peak_tip_displacement_m",
                 "residual_displacement_m"):
        assert [float(x[name]) for x in rows] == list(r.replicas[name]), name
    assert [x["status"] for x in rows] == list(r.replicas["status"])
    with open(out / "ensemble.csv") as f:
        summary = next(csv.DictReader(f))
    d = r.summary["distributions"]["peak_tip_displacement_m"]
    assert d["n"] == 4
    assert (float(summary["peak_tip_displacement_m_p16"]), float(summary["peak_tip_displacement_m_median"]),
            float(summary["peak_tip_displacement_m_p84"])) == (d["p16"], d["median"], d["p84"])
    assert sum(r.summary["status_counts"].values()) == 4
    assert np.isnan(r.replicas["max_bed_opening_m"]).all()  # no walking recorded: not measured


def test_ensemble_courses_match_the_command_line(tmp_path):
    """With output.walking the Python summary's courses are courses.csv's."""
    import csv
    from conftest import polydem_cli
    column = deck("examples/verification/column_rocking.toml")
    r = polydem.ensemble(column, 3, seed=2, threads=1, progress=False, set={"output.walking": True})
    out = tmp_path / "cli"
    done = polydem_cli("ensemble", column, "--replicas", 3, "--seed", 2, "--jobs", 2, "--threads", 1,
                       "--set", "output.walking=true", "--out", out)
    assert done.returncode == 0, done.stderr
    with open(out / "courses.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == len(r.summary["courses"]) == 4
    for row, c in zip(rows, r.summary["courses"]):
        assert float(row["level_m"]) == c["level_m"] and int(row["bed_joints"]) == c["bed_joints"]
        for name in ("residual_bed_largest_m", "max_bed_m"):
            assert c[name]["n"] == 3
            assert float(row[f"{name}_median"]) == c[name]["median"], name


def test_ensemble_bad_input_raises_before_running():
    with pytest.raises(ValueError):
        polydem.ensemble(TIP, 0, progress=False)
    with pytest.raises(polydem.DeckError) as e:
        polydem.ensemble(TIP, 2, set={"ensemble.stiffness": 0.9}, progress=False)
    assert e.value.key == "ensemble.stiffness"


def _pulse_suite(tmp_path):
    """Two one-sine pulses of peak 1 g (T = 1 s and 0.7 s, the second at
    suite scale 0.8) as two-column records, and their suite file."""
    import math
    for name, period in (("pulse10", 1.0), ("pulse07", 0.7)):
        n = round(period / 0.01)
        lines = ["time_s,acceleration_g"]
        lines += [f"{i * 0.01:.2f},{1.0 if i == n // 4 else math.sin(2 * math.pi * i * 0.01 / period)!r}"
                  for i in range(n + 1)]
        (tmp_path / f"{name}.csv").write_text("\n".join(lines) + "\n")
    suite = tmp_path / "suite.toml"
    suite.write_text('[[record]]\nfile = "pulse10.csv"\n[[record]]\nfile = "pulse07.csv"\nscale = 0.8\n')
    return suite


def test_ida_matches_the_command_line(tmp_path):
    """polydem.ida and `polydem ida` run the same searches: the same IMs,
    states and responses, bit for bit, and the same capacities table."""
    import csv
    from conftest import polydem_cli
    suite = _pulse_suite(tmp_path)
    seen = []
    r = polydem.ida(TIP, suite, tolerance=0.05, max_runs=6, threads=1, progress=seen.append, out=tmp_path / "py",
                    set={"simulation.end_time": 2.5})
    assert len(r.runs) == len(seen) == 12 and list(r.records["record"]) == ["pulse10", "pulse07"]
    out = tmp_path / "cli"
    done = polydem_cli("ida", suite, TIP, "--tolerance", 0.05, "--max-runs", 6, "--jobs", 2, "--threads", 1,
                       "--set", "simulation.end_time=2.5", "--out", out)
    assert done.returncode == 0, done.stderr
    with open(out / "ida.csv") as f:
        rows = list(csv.DictReader(f))
    assert [x["record"] for x in rows] == list(r.runs["record"])
    assert [x["state"] for x in rows] == list(r.runs["state"])
    for csv_name, name in (("im", "im"), ("scale", "scale"), ("peak_tip_displacement_m", "peak_tip_displacement"),
                           ("residual_displacement_m", "residual_displacement")):
        assert [float(x[csv_name]) for x in rows] == list(r.runs[name]), name
    assert (out / "capacities.csv").read_text() == (tmp_path / "py" / "capacities.csv").read_text()
    # Six runs each: the hunt's IMs 0.05, 0.1, 0.2, 0.35, 0.55, 0.8 g; the
    # first pulse collapses the tip at the last.
    assert list(r.runs["im"][:6]) == [0.05, 0.1, 0.2, 0.35, 0.55, 0.8]
    assert r.records["collapse_im"][0] == 0.8 and np.isnan(r.records["collapse_im"][1])
    stripes = polydem.ida(TIP, suite, stripes=[0.5, 0.9], threads=1, progress=False, set={"simulation.end_time": 2.5})
    assert list(stripes.runs["im"]) == [0.5, 0.9, 0.5, 0.9] and stripes.runs["scale"][3] == 0.9 / 0.8


def test_ida_bad_input_raises_before_running(tmp_path):
    suite = _pulse_suite(tmp_path)
    bad = tmp_path / "bad.toml"
    bad.write_text('[[record]]\nfile = "pulse10.csv"\nscale = -1\n')
    with pytest.raises(polydem.DeckError) as e:
        polydem.ida(TIP, bad, progress=False)
    assert e.value.key == "record[1].scale" and e.value.line == 3
    with pytest.raises(ValueError):
        polydem.ida(TIP, suite, im="pgv", progress=False)
    with pytest.raises(polydem.DeckError):
        polydem.ida(TIP, suite, im="sa", period=0, progress=False)
