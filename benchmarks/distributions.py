#!/usr/bin/env python3
"""Whether the distributions polydem reports move with the time step, into
benchmarks/results/distributions.csv (table `distributions`, docs/ensembles.md):

    /usr/bin/python3 benchmarks/distributions.py build/polydem [--case C]...
        [--setting S]... [--jobs 2] [--force] [--out DIR]

Every ensemble runs the joints as the default does (clipped as they move,
re-sampled pair by pair), or, in the settings named "re-sampled at
detection, ...", re-sampled pair by pair with their points and areas fixed
between (`simulation.joint_sampling = "detection"`), or, in those named
"scene trigger, ...", re-sampled scene-wide
(`simulation.detection_trigger = "scene"`, as the first ensembles were
measured). The same ensembles at the deck's safety
factor (0.8) and at half of it
(`simulation.safety_factor = 0.4`, half the time step); the walking also
at the contact margin halved and doubled (`simulation.contact_margin`, the
automatic margin the deck's own runs report in summary.json, scaled; run
after the safety factor 0.8), under split damping
(`simulation.damping_scheme = "split"`) and with friction bounded by the
joints' whole normal force, spring and dashpot (`joint.friction_normal_force
= "total"`, docs/deck.md):

  tipT      the spire's 3.4 m tip under one-sine pulses of period T = 0.6,
            1.0 and 2.0 s (cases tip0.6, tip1.0, tip2.0;
            examples/spire/tip_pulse.toml, run until the tip is at rest):
            20 replicas at a_p by 0.1 g about the boundary (0.5-2.0 g at
            0.6 s, 0.5-1.2 g at 1.0 and 2.0 s), then, where the
            probability of collapse steps from none to all within one
            0.1 g interval, at every 0.01 g inside it
            (scripts/bands_refine.py); the 50 % collapse boundary and its
            16-84 % band, or the bracket of a step sharper than the grid
            (docs/ensembles.md, "Bands along an intensity axis")
  walking4  the whole spire under the earthquake deck's record x4
            (examples/spire/earthquake.toml), 5 replicas
            (--walking-replicas): the median and 16-84 % of the largest
            residual and largest transient opening of vertical and of bed
            joints, the median of the top course's largest residual
            vertical opening (the course that walks most), and the 5-95 %
            interval of the median of the largest residual vertical
            opening over the replicas resampled (bootstrap): how far the
            median of so few runs may stray

Every run is `nice -n 10 polydem ... --threads 1`, --jobs at a time. Each
case and setting is a `polydem sweep` in DIR/<case>_<setting> (default
DIR out/distributions), resumable: an interrupted benchmark runs only what
is missing. The walking sweep at the safety factor 0.8 varies the scale over
2, 4 and 6 (--walking-scales; the scale 4 is compared, docs/spire.md draws
all three). Every scene-wide setting also runs with the detection travel at
half the margin (", travel half the margin": `simulation.detection_travel =
1`). The
CSV keeps one row per (case, setting, quantity) with the machine, CPU,
commit and date; a (case, setting) already in it is skipped unless --force.
"""
import argparse
import csv
import datetime
import json
import os
import random
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
import timings_csv  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
CSV = os.path.join(ROOT, "benchmarks", "results", "distributions.csv")
FIELDS = ["machine", "cpu", "commit", "date", "case", "setting", "quantity", "value", "unit"]
# Every setting is run at the default (the joints clipped as they move,
# re-sampled pair by pair, docs/contact.md), re-sampled pair by pair at
# detection ("re-sampled at detection, ...") and, as measured before
# either became the default, scene-wide ("scene trigger, ..."); scene-wide
# also with the detection travel at half the margin (the deck's 1 m is
# taken as that), where the margin also sets how often the joints are
# re-sampled (docs/contact.md, "The detection travel").
BASE = {"safety factor 0.8": [], "safety factor 0.4": ["--set", "simulation.safety_factor=0.4"],
        "friction on total": ["--set", "joint.friction_normal_force=total"],
        "margin x0.5": None, "margin x2": None,  # the automatic margin scaled (margin_args)
        "split damping": ["--set", "simulation.damping_scheme=split"],
        "merged corner stones": ["--set", "spire.corner_stones=merged"],
        "merged corner stones, margin 3.05 mm": ["--set", "spire.corner_stones=merged",
                                                 "--set", "simulation.contact_margin=0.003046"]}
SCENE_SETTING = "scene trigger, "
SCENE = ["--set", "simulation.detection_trigger=scene"]
DETECTION_SETTING = "re-sampled at detection, "
DETECTION = ["--set", "simulation.joint_sampling=detection"]
PREFIXES = {SCENE_SETTING: SCENE, DETECTION_SETTING: DETECTION}
HALF = ", travel half the margin"
SETTINGS = dict(BASE)
SETTINGS.update({DETECTION_SETTING + s: v for s, v in BASE.items()})
SETTINGS.update({SCENE_SETTING + s: v for s, v in BASE.items()})
SETTINGS.update({SCENE_SETTING + s + HALF: (None if v is None else v + ["--set", "simulation.detection_travel=1"])
                 for s, v in BASE.items()})


def prefix_of(setting):
    """The setting's sampling prefix ("" for the default's)."""
    return next((p for p in PREFIXES if setting.startswith(p)), "")


def base_setting(setting):
    """The setting's name without its sampling and travel."""
    s = setting[len(prefix_of(setting)):]
    return s[:-len(HALF)] if s.endswith(HALF) else s


def setting_args(setting):
    return PREFIXES.get(prefix_of(setting), []) + SETTINGS[setting]


WALKING_ONLY = tuple(s for s in SETTINGS if base_setting(s) not in ("safety factor 0.8", "safety factor 0.4"))
TIP = os.path.join(ROOT, "examples", "spire", "tip_pulse.toml")
EARTHQUAKE = os.path.join(ROOT, "examples", "spire", "earthquake.toml")
TIP_RUN = ["--replicas", "20", "--quiet", "--band-axis", "ground_motion.acceleration_g",
           "--set", "simulation.end_time=20", "--set", "simulation.settle_velocity=0.01",
           "--set", "simulation.settle_time=0.5"]
# a_p by 0.1 g about each period's first rise of the collapse probability
# (docs/analytical.md: 1.46 g at 0.6 s, 0.67 at 1.0 s, 0.59 at 2.0 s)
GRID = {"0.6": (0.5, 2.0), "1.0": (0.5, 1.2), "2.0": (0.5, 1.2)}


def grid(period):
    lo, hi = GRID[period]
    return ",".join(f"{lo + 0.1 * i:.1f}" for i in range(int(round((hi - lo) / 0.1)) + 1))


def sweep(polydem, deck, args, out, jobs):
    cmd = ["nice", "-n", "10", polydem, "sweep", deck, "--jobs", str(jobs), "--threads", "1", "--out", out] + args
    print("$", " ".join(cmd), flush=True)
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if proc.returncode not in (0, 3):
        sys.exit(f"FAILED ({proc.returncode}):\n{proc.stdout}")
    return proc.stdout


def run_seconds(out):
    """The runs' own wall time, summed over the sweep's points (reused ones too)."""
    with open(os.path.join(out, "sweep.json")) as f:
        return f'{json.load(f)["run_seconds_total"]:.0f}'


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def tip_case(polydem, period, setting, out, jobs):
    base = TIP_RUN + setting_args(setting) + ["--vary", f"ground_motion.period={period}"]
    sweep(polydem, TIP, base + ["--vary", f"ground_motion.acceleration_g={grid(period)}"], out, jobs)
    refine = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "bands_refine.py"), "grid", out,
                             "--outcomes", "collapse"], stdout=subprocess.PIPE, text=True, check=True).stdout.split()
    if len(refine) == 2:  # the column's value and its refined list
        sweep(polydem, TIP, base + ["--vary", f"ground_motion.acceleration_g={refine[1]}"], out, jobs)
    # A fit can rest on one stray replica far below the step (one collapse
    # at 1.1 g under a step at 1.4-1.5 g): the 50 % bracket is refined to
    # 0.01 g whatever the fit's status, so that both settings are read alike.
    row = next(r for r in read(os.path.join(out, "bands.csv")) if r["outcome"] == "collapse")
    a = "ground_motion.acceleration_g"
    if row[a + "_below"] and row[a + "_above"]:
        lo, hi = float(row[a + "_below"]), float(row[a + "_above"])
        inside = [round(lo + 0.01 * k, 2) for k in range(1, int(round((hi - lo) / 0.01)))]
        if inside:
            done = {float(r[a]) for r in read(os.path.join(out, "ensembles.csv"))}
            values = sorted(done | set(inside))
            sweep(polydem, TIP, base + ["--vary", f"{a}=" + ",".join(f"{v:g}" for v in values)], out, jobs)
    row = next(r for r in read(os.path.join(out, "bands.csv")) if r["outcome"] == "collapse")
    a = "ground_motion.acceleration_g"
    got = {"collapse status": (row["status"], "-")}
    for q, key in (("collapse 16 %", "_16"), ("collapse 50 %", "_50"), ("collapse 84 %", "_84"),
                   ("collapse bracket below", "_below"), ("collapse bracket above", "_above")):
        if row[a + key] != "":
            got[q] = (row[a + key], "g")
    got["runs"] = (row["runs"], "-")
    got["run time summed"] = (run_seconds(out), "s")
    return got


def margin_args(setting, default_out):
    """The automatic contact margin of the deck as written (the default
    setting's runs report it in summary.json), scaled."""
    if SETTINGS[setting] is not None:
        return setting_args(setting)
    half = ["--set", "simulation.detection_travel=1"] if setting.endswith(HALF) else []
    points = os.path.join(default_out, "points")
    summary = next(os.path.join(points, d, "summary.json") for d in sorted(os.listdir(points))
                   if os.path.exists(os.path.join(points, d, "summary.json")))
    with open(summary) as f:
        margin = json.load(f)["contact_margin_m"]
    factor = 0.5 if base_setting(setting) == "margin x0.5" else 2.0
    return PREFIXES.get(prefix_of(setting), []) + ["--set", f"simulation.contact_margin={margin * factor!r}"] + half


def median_interval(values, draws=4000, seed=1):
    """The 5 % and 95 % points of the median of `values` resampled with
    replacement (`draws` times, a fixed seed): how far the median of so few
    replicas may stray from the ensemble's own."""
    rng = random.Random(seed)
    meds = sorted(statistics.median(rng.choices(values, k=len(values))) for _ in range(draws))
    return meds[int(0.05 * draws)], meds[int(0.95 * draws)]


def walking_case(polydem, setting, out, jobs, default_out, scales_at_default, replicas):
    scales = scales_at_default if base_setting(setting) == "safety factor 0.8" else "4"
    sweep(polydem, EARTHQUAKE, ["--set", "output.snapshot_interval=0"] + margin_args(setting, default_out) + ["--quiet",
                                                    "--vary", f"ground_motion.scale={scales}", "--replicas",
                                                    str(replicas)],
          out, jobs)
    point = next(r for r in read(os.path.join(out, "ensembles.csv")) if float(r["ground_motion.scale"]) == 4)
    got = {"replicas": (point["replicas"], "-"), "run time summed": (run_seconds(out), "s")}
    values = []
    for r in read(os.path.join(out, "sweep.csv")):
        if float(r["ground_motion.scale"]) == 4 and int(r["ensemble.replica"]) < replicas:
            with open(os.path.join(out, "points", r["point"], "summary.json")) as f:
                values.append(json.load(f)["walking"]["residual_vertical_opening_m"])
    lo, hi = median_interval(values)
    got["residual_vertical_opening median 5 %"] = (repr(lo), "m")
    got["residual_vertical_opening median 95 %"] = (repr(hi), "m")
    for stem in ("residual_vertical_opening_m", "residual_bed_opening_m", "max_vertical_opening_m",
                 "max_bed_opening_m"):
        for p in ("p16", "median", "p84"):
            got[f"{stem[:-2]} {p}"] = (point[f"{stem}_{p}"], "m")
    courses = [r for r in read(os.path.join(out, "courses.csv")) if float(r["ground_motion.scale"]) == 4]
    top = max((r for r in courses if int(r["vertical_joints"]) > 0), key=lambda r: float(r["level_m"]))
    got["top course level"] = (top["level_m"], "m")
    for p in ("p16", "median", "p84"):
        got[f"top course residual vertical largest {p}"] = (top[f"residual_vertical_largest_m_{p}"], "m")
    return got


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("polydem")
    ap.add_argument("--case", action="append", choices=["tip0.6", "tip1.0", "tip2.0", "walking4"])
    ap.add_argument("--setting", action="append", choices=list(SETTINGS))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--walking-scales", default="2,4,6",
                    help="the record's scales at the safety factor 0.8 (the scale 4 is compared)")
    ap.add_argument("--walking-replicas", type=int, default=5,
                    help="replicas of each walking ensemble (5: the issue's least)")
    ap.add_argument("--force", action="store_true")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "distributions"))
    args = ap.parse_args()
    polydem = os.path.abspath(args.polydem)
    cases = args.case or ["tip0.6", "tip1.0", "tip2.0", "walking4"]
    settings = args.setting or list(SETTINGS)
    rows = read(CSV) if os.path.exists(CSV) else []
    done = {(r["case"], r["setting"]) for r in rows}
    machine = {"machine": timings_csv.machine(), "cpu": timings_csv.cpu()}
    commit = timings_csv.commit()
    for case in cases:
        for setting in settings:
            if (case, setting) in done and not args.force:
                print(f"{case}, {setting}: in the CSV (--force to run again)")
                continue
            if case != "walking4" and setting in WALKING_ONLY:
                continue
            out = os.path.join(args.out, f"{case}_{setting.replace(' ', '_')}")
            t0 = time.monotonic()
            trigger = prefix_of(setting)
            half = HALF if setting.endswith(HALF) else ""
            default = "walking4_" + (trigger + "safety factor 0.8" + half).replace(" ", "_")
            got = (walking_case(polydem, setting, out, args.jobs, os.path.join(args.out, default), args.walking_scales,
                                 args.walking_replicas)
                   if case == "walking4"
                   else tip_case(polydem, case[3:], setting, out, args.jobs))
            got["benchmark wall time"] = (f"{time.monotonic() - t0:.0f}", "s")
            # Read again: another benchmark process may have added its cases.
            rows = read(CSV) if os.path.exists(CSV) else []
            rows = [r for r in rows if (r["case"], r["setting"]) != (case, setting)]
            for q, (v, unit) in got.items():
                rows.append({**machine, "commit": commit, "date": datetime.date.today().isoformat(), "case": case,
                             "setting": setting, "quantity": q, "value": v, "unit": unit})
            with open(CSV + ".tmp", "w", newline="") as f:
                w = csv.DictWriter(f, FIELDS)
                w.writeheader()
                w.writerows(rows)
            os.replace(CSV + ".tmp", CSV)
            print(f"{case}, {setting}: " + ", ".join(f"{q} {v}" for q, (v, _) in got.items()), flush=True)


if __name__ == "__main__":
    main()
