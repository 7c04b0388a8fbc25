#!/usr/bin/env python3
"""How the spire's headline answers move with the numerical settings, into
benchmarks/results/convergence.csv (table `convergence`, docs/contact.md):

    /usr/bin/python3 benchmarks/convergence.py build/polydem [--case C]...
        [--setting S]... [--jobs 2] [--force] [--out DIR]

Each case is run once per setting, one setting changed at a time from the
deck's own (safety factor 0.8, automatic contact margin and detection
travel, the joints re-sampled pair by pair, explicit damping):

  settings  default; safety factor 0.4 and 0.2 (`simulation.safety_factor`);
            margin x0.5 and x2 (`simulation.contact_margin`, the automatic
            margin a short run of the same deck reports in summary.json,
            scaled); split damping (`simulation.damping_scheme = "split"`);
            detection travel x16, x8, x4, x2, x0.5 and x0.25
            (`simulation.detection_travel`, the automatic travel likewise
            scaled); the joints re-sampled scene-wide
            (`simulation.detection_trigger = "scene"`, "scene trigger") at
            its automatic travel (sixteen times the pair-by-pair one) with
            the same settings and at x0.125, x0.25, x0.5 and x2 of that
            travel; scene-wide, the same settings and
            the margin x0.125 and x0.25 with the detection travel at half the
            margin (`simulation.detection_travel = 1`, taken as half the
            margin: how often the subcontacts are re-sampled then follows the
            margin); the overlap joint model (`simulation.joint_model =
            "overlap"`, whose automatic travel is half the margin) at the
            margin x1, x0.5 and x2; the joints' points following the blocks
            (`simulation.joint_sampling = "step"`, "points following the
            blocks") at the default settings, safety factor 0.4, margin x0.5
            and x2, and travel x4 and x16; the joints clipped again
            (`simulation.joint_sampling = "clip"`) when a pair has moved by
            the detection travel ("joints clipped at the travel") at the
            default settings, safety factor 0.4 and 0.2, margin x0.5 and x2,
            split damping and travel x0.25, x4 and x16, and at every step
            (the travel 1e-12 m, "joints clipped every step") at the default
            settings, safety factor 0.4 and margin x0.5 and x2; and, a
            geometry rather than a numerical
            setting, the spire's corner halves merged (`spire.corner_stones =
            "merged"`, issue 31's stagger artefacts), at its own automatic
            margin and at the halves' (3.05 mm)
  cases     main      `polydem run --default`, the 0.1 g/s ramp: the ground
                      acceleration when the mechanism formed, the crack (angle
                      of the opened joints' principal axis, their heights,
                      their count), the stones dislodged, status and mode
            pulse25, pulse35, pulse50
                      `examples/spire/pulse.toml`, one sine of 0.25, 0.35 and
                      0.5 g, T_p = 1 s (the deck's end time and
                      stop_on_collapse): status, mode, stones dislodged, time
                      of collapse
            lambda    `polydem collapse examples/spire/constant_acceleration.toml
                      --direction 90 --method bisection` (onto a window face,
                      as the paper's lambda), bracket [0.155, 0.205] g
                      halved to 0.00625 g: its midpoint and ends, the crack

Every run is `nice -n 10 polydem ... --threads 1`, at most --jobs at a time:
the main job first, then the other cases, their safety factor 0.2 runs last.
The CSV keeps one row per (case, setting, quantity) with the machine, CPU,
commit and date; a (case, setting) already in it is skipped unless --force,
so an interrupted benchmark keeps what finished. Each (case, setting) also
records its wall time and, for `run`, its steps, time step, margin and the
energy ledger's numerical line."""
import argparse
import concurrent.futures
import csv
import datetime
import json
import os
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
import timings_csv  # noqa: E402

ROOT = timings_csv.ROOT
PATH = os.path.join(ROOT, "benchmarks", "results", "convergence.csv")
COLUMNS = ["machine", "cpu", "commit", "date", "case", "setting", "quantity", "value", "unit"]

# setting name -> (overrides, (what is scaled, factor) or None); the order is
# the table's. The default clips each pair's joint again when its blocks
# have moved by the detection travel and re-samples it pair by pair;
# "re-sampled at detection": the joints' points and areas fixed from one
# re-sampling to the next (`simulation.joint_sampling = "detection"`);
# "scene trigger": scene-wide (`simulation.detection_trigger = "scene"`,
# where the joints are re-sampled at detection), its travel factors of the
# scene-wide automatic travel, sixteen times the pair by pair one the runs
# scale. "travel half the margin": the detection
# travel at its largest, the margin's half (the deck's 1 m is taken as that).
HALF = ["simulation.detection_travel=1"]
SCENE = ['simulation.detection_trigger="scene"']
# the joints' points following the blocks between detections (simulation.joint_sampling)
STEP = ['simulation.joint_sampling="step"']
# the joints re-sampled at detection, their points and areas fixed between
DETECTION = ['simulation.joint_sampling="detection"']
# the joints clipped again (simulation.joint_sampling = "clip", the
# default's); with a travel of 1e-12 m, every pair at every step
CLIP = ['simulation.joint_sampling="clip"']
EVERY = CLIP + ["simulation.detection_travel=1e-12"]
# One numerical setting changed from the deck's: name -> (overrides, scaled).
ONE_CHANGED = {
    "safety factor 0.4": (["simulation.safety_factor=0.4"], None),
    "safety factor 0.2": (["simulation.safety_factor=0.2"], None),
    "margin x0.5": ([], ("margin", 0.5)),
    "margin x2": ([], ("margin", 2.0)),
    "split damping": (['simulation.damping_scheme="split"'], None),
    **{f"travel x{f:g}": ([], ("travel", f)) for f in (16.0, 8.0, 4.0, 2.0, 0.5, 0.25)},
}
SETTINGS = {
    "default": ([], None),
    **ONE_CHANGED,
    "re-sampled at detection": (DETECTION, None),
    **{f"re-sampled at detection, {name}": (DETECTION + o, scaled) for name, (o, scaled) in ONE_CHANGED.items()},
    "scene trigger": (SCENE, None),
    "scene trigger, safety factor 0.4": (SCENE + ["simulation.safety_factor=0.4"], None),
    "scene trigger, safety factor 0.2": (SCENE + ["simulation.safety_factor=0.2"], None),
    "scene trigger, margin x0.5": (SCENE, ("margin", 0.5)),
    "scene trigger, margin x2": (SCENE, ("margin", 2.0)),
    "scene trigger, travel x0.125": (SCENE, ("travel", 2.0)),
    "scene trigger, travel x0.25": (SCENE, ("travel", 4.0)),
    "scene trigger, travel x0.5": (SCENE, ("travel", 8.0)),
    "scene trigger, travel x2": (SCENE, ("travel", 32.0)),
    "scene trigger, split damping": (SCENE + ['simulation.damping_scheme="split"'], None),
    "scene trigger, travel half the margin": (SCENE + HALF, None),
    "scene trigger, safety factor 0.4, travel half the margin": (SCENE + ["simulation.safety_factor=0.4"] + HALF, None),
    "scene trigger, safety factor 0.2, travel half the margin": (SCENE + ["simulation.safety_factor=0.2"] + HALF, None),
    "scene trigger, margin x0.125, travel half the margin": (SCENE + HALF, ("margin", 0.125)),
    "scene trigger, margin x0.25, travel half the margin": (SCENE + HALF, ("margin", 0.25)),
    "scene trigger, margin x0.5, travel half the margin": (SCENE + HALF, ("margin", 0.5)),
    "scene trigger, margin x2, travel half the margin": (SCENE + HALF, ("margin", 2.0)),
    "scene trigger, split damping, travel half the margin": (SCENE + ['simulation.damping_scheme="split"'] + HALF,
                                                             None),
    "points following the blocks": (STEP, None),
    "points following the blocks, safety factor 0.4": (STEP + ["simulation.safety_factor=0.4"], None),
    "points following the blocks, margin x0.5": (STEP, ("margin", 0.5)),
    "points following the blocks, margin x2": (STEP, ("margin", 2.0)),
    "points following the blocks, travel x4": (STEP, ("travel", 4.0)),
    "points following the blocks, travel x16": (STEP, ("travel", 16.0)),
    "joints clipped every step": (EVERY, None),
    "joints clipped every step, safety factor 0.4": (EVERY + ["simulation.safety_factor=0.4"], None),
    "joints clipped every step, margin x0.5": (EVERY, ("margin", 0.5)),
    "joints clipped every step, margin x2": (EVERY, ("margin", 2.0)),
    "overlap model": (['simulation.joint_model="overlap"'], None),
    "overlap model, margin x0.5": (['simulation.joint_model="overlap"'], ("margin", 0.5)),
    "overlap model, margin x2": (['simulation.joint_model="overlap"'], ("margin", 2.0)),
    # the merged spire's automatic margin is 3.55 mm (its stones are larger):
    # the second row keeps the halves' 3.05 mm, to part the geometry from the margin
    "scene trigger, merged corner stones, travel half the margin": (
        SCENE + ['spire.corner_stones="merged"'] + HALF, None),
    "scene trigger, merged corner stones, margin 3.05 mm, travel half the margin": (
        SCENE + ['spire.corner_stones="merged"', "simulation.contact_margin=0.003046"] + HALF, None),
}

PULSE = "examples/spire/pulse.toml"
COLLAPSE = "examples/spire/constant_acceleration.toml"
# 3 halvings of [0.155, 0.205] g and the two ends: 5 trials, a bracket 0.00625 g wide
LAMBDA_ARGS = ["--direction", "90", "--method", "bisection", "--low", "0.155", "--high", "0.205",
               "--tolerance", "0.0063"]
# settings whose lambda lies below the bracket's low end start lower: 4
# halvings of [0.105, 0.205] g, 6 trials, the same 0.00625 g at the end
LAMBDA_LOW = {s: "0.105" for s in SETTINGS if "half the margin" not in s and "merged" not in s}
LAMBDA_LOW.update({s: "0.105" for s in ("scene trigger, margin x0.125, travel half the margin",
                                        "scene trigger, margin x0.25, travel half the margin")})


def pulse(a_g):
    return {"command": "run", "deck": [PULSE, "--set", f"ground_motion.acceleration_g={a_g}",
                                       "--set", "ground_motion.period=1.0"]}


# case name -> what is run; the order is the table's
CASES = {
    "main": {"command": "run", "deck": ["--default"]},
    "pulse25": pulse(0.25),
    "pulse35": pulse(0.35),
    "pulse50": pulse(0.5),
    "lambda": {"command": "collapse", "deck": [COLLAPSE] + LAMBDA_ARGS},
}


def command_text(case):
    return f"polydem {CASES[case]['command']} " + " ".join(CASES[case]["deck"])


# --- the quantities of each run ----------------------------------------------

def run_quantities(s):
    """(quantity, value, unit) of a `polydem run` summary.json."""
    a = s["assessment"]
    out = [("status", s["status"], ""), ("collapse mode", a["collapse_mode"] or "-", "")]
    if a.get("ground_acceleration_at_damage_g") is not None:
        out.append(("mechanism acceleration", f'{a["ground_acceleration_at_damage_g"]:.4f}', "g"))
    if a.get("collapse_time_s") is not None:
        out.append(("collapse time", f'{a["collapse_time_s"]:.3f}', "s"))
    out.append(("opened joints", str(a.get("opened_joints", 0)), ""))
    if a.get("opened_joints", 0) and a.get("crack_angle_deg") is not None:
        out += [("crack angle", f'{a["crack_angle_deg"]:.1f}', "deg"),
                ("crack lowest z", f'{a["crack_lowest_z_m"]:.2f}', "m"),
                ("crack highest z", f'{a["crack_highest_z_m"]:.2f}', "m")]
    out += [("dislodged", str(a["dislodged"]["count"]), "blocks"),
            ("fallen", str(a["dislodged"].get("fallen_count", 0)), "blocks"),
            ("simulated time", f'{s["end_time_s"]:.3f}', "s"),
            ("steps", str(s["steps"]), ""),
            ("time step", f'{s["time_step_s"]:.4g}', "s"),
            ("contact margin", f'{s["contact_margin_m"]:.4g}', "m"),
            ("detection travel", f'{s["detection_travel_m"]:.4g}', "m"),
            ("detections", str(s["contact_detections"]), ""),
            ("numerical energy of slip and damping", f'{100 * s["energy"]["numerical_of_dissipation"]:.3g}', "%")]
    if "pairs_resampled" in s:
        out.append(("pairs re-sampled", str(s["pairs_resampled"]), ""))
    return out


def collapse_quantities(c):
    """(quantity, value, unit) of a `polydem collapse` collapse.json (one
    direction, bisection): the bracket's midpoint, its ends, the trials and
    the crack of the last collapsing trial."""
    b = c["directions"][0]["bisection"]
    if "error" in b:
        raise RuntimeError(f"bisection: {b['error']}")
    lo, hi = b["bracket_g"]
    out = [("lambda", f'{b["collapse_acceleration_g"]:.4f}', "g"), ("lambda bracket low", f"{lo:.4f}", "g"),
           ("lambda bracket high", f"{hi:.4f}", "g"), ("trials", str(b["runs"]), "")]
    crack = b["crack"]
    out += [("collapse mode", crack["collapse_mode"] or "-", ""), ("opened joints", str(crack["opened_joints"]), "")]
    if crack["crack_angle_deg"] is not None:
        out += [("crack angle", f'{crack["crack_angle_deg"]:.1f}', "deg"),
                ("crack lowest z", f'{crack["crack_lowest_z_m"]:.2f}', "m"),
                ("crack highest z", f'{crack["crack_highest_z_m"]:.2f}', "m")]
    return out


# --- running -------------------------------------------------------------------

def polydem_cmd(polydem, case, overrides, out, setting=None):
    c = CASES[case]
    deck = list(c["deck"])
    if case == "lambda" and setting in LAMBDA_LOW:
        deck[deck.index("--low") + 1] = LAMBDA_LOW[setting]
    cmd = ["nice", "-n", "10", polydem, c["command"], *deck, "--threads", "1", "--quiet", "--out", out]
    for o in overrides:
        cmd += ["--set", o]
    return cmd


def automatic_distances(polydem, case, out):
    """The contact margin and detection travel the case's deck uses by
    default: a run of one step reports them."""
    c = CASES[case]
    deck = c["deck"] if c["command"] == "run" else [c["deck"][0]]
    d = os.path.join(out, "margin", case)
    cmd = ["nice", "-n", "10", polydem, "run", *deck, "--threads", "1", "--quiet", "--out", d,
           "--set", "simulation.end_time=1e-5"]
    subprocess.run(cmd, cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(d, "summary.json"), encoding="utf-8") as f:
        s = json.load(f)
    return {"margin": s["contact_margin_m"], "travel": s["detection_travel_m"]}


KEYS = {"margin": "simulation.contact_margin", "travel": "simulation.detection_travel"}


def run_one(polydem, case, setting, automatic, out):
    overrides, scaled = SETTINGS[setting]
    overrides = list(overrides)
    if scaled is not None:
        what, factor = scaled
        overrides.append(f"{KEYS[what]}={factor * automatic[what]:.6g}")
    d = os.path.join(out, case, setting.replace(" ", "_"))
    cmd = polydem_cmd(polydem, case, overrides, d, setting)
    start = time.monotonic()
    p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    wall = time.monotonic() - start
    if CASES[case]["command"] == "run":
        path = os.path.join(d, "summary.json")
        if not os.path.exists(path):
            raise RuntimeError(f"{' '.join(cmd)}: exit {p.returncode}\n{p.stderr[-2000:]}")
        with open(path, encoding="utf-8") as f:
            rows = run_quantities(json.load(f))
    else:
        path = os.path.join(d, "collapse.json")
        if not os.path.exists(path):
            raise RuntimeError(f"{' '.join(cmd)}: exit {p.returncode}\n{p.stderr[-2000:]}")
        with open(path, encoding="utf-8") as f:
            rows = collapse_quantities(json.load(f))
        if scaled is not None:
            rows.append((f"contact {what}" if what == "margin" else "detection travel",
                         f"{factor * automatic[what]:.4g}", "m"))
    rows.append(("wall time, 1 thread", f"{wall:.1f}", "s"))
    return rows


def solver_commit():
    """The commit the runs' program and decks come from, with "+" when they
    differ from it (the scripts, tests, benchmarks and docs do not count)."""
    head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True)
    dirty = subprocess.run(["git", "diff", "--quiet", "HEAD", "--", ".", ":!docs", ":!README.md", ":!benchmarks",
                            ":!scripts", ":!tests"], cwd=ROOT).returncode
    return head.stdout.strip() + ("+" if dirty else "")


def read_rows():
    if not os.path.exists(PATH):
        return []
    with open(PATH, encoding="utf-8") as f:
        return list(csv.DictReader(f))


def write_rows(rows):
    order_c, order_s = list(CASES), list(SETTINGS)
    rows = sorted(rows, key=lambda r: (order_c.index(r["case"]) if r["case"] in order_c else 99,
                                       order_s.index(r["setting"]) if r["setting"] in order_s else 99))
    os.makedirs(os.path.dirname(PATH), exist_ok=True)
    tmp = PATH + ".tmp"
    with open(tmp, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, COLUMNS)
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, PATH)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("polydem", help="the polydem binary")
    ap.add_argument("--case", action="append", choices=list(CASES), help="only these cases (repeatable)")
    ap.add_argument("--setting", action="append", choices=list(SETTINGS), help="only these settings (repeatable)")
    ap.add_argument("--jobs", type=int, default=2, help="polydem processes at a time (each 1 thread)")
    ap.add_argument("--force", action="store_true", help="run (case, setting) pairs already in the CSV again")
    ap.add_argument("--out", default="/tmp/polydem_convergence", help="where the runs write")
    args = ap.parse_args()
    polydem = os.path.abspath(args.polydem)
    cases = args.case or list(CASES)
    settings = args.setting or list(SETTINGS)
    done = {(r["case"], r["setting"]) for r in read_rows()}
    todo = [(c, s) for c in cases for s in settings if args.force or (c, s) not in done]
    # The main job first, then the other cases; their safety factor 0.2
    # runs (four times the steps) last, so that an interrupted benchmark has
    # every case's other settings.
    todo.sort(key=lambda cs: (cs[0] != "main" and cs[1].startswith("safety factor 0.2"), cases.index(cs[0])))
    if not todo:
        print("convergence: every (case, setting) is in the CSV (--force runs them again)")
        return 0
    stamp = {"machine": timings_csv.machine(), "cpu": timings_csv.cpu(), "commit": solver_commit(),
             "date": datetime.date.today().isoformat()}
    automatic = {}
    for c in sorted({c for c, s in todo if SETTINGS[s][1] is not None}, key=cases.index):
        automatic[c] = automatic_distances(polydem, c, args.out)
        print(f"convergence: {c}: automatic contact margin {automatic[c]['margin']:.4g} m, "
              f"detection travel {automatic[c]['travel']:.4g} m", flush=True)
    lock = threading.Lock()
    failed = []

    def work(c, s):
        print(f"convergence: start {c} / {s}", flush=True)
        rows = run_one(polydem, c, s, automatic.get(c), args.out)
        with lock:
            kept = [r for r in read_rows() if (r["case"], r["setting"]) != (c, s)]
            write_rows(kept + [{**stamp, "case": c, "setting": s, "quantity": q, "value": v, "unit": u}
                               for q, v, u in rows])
        summary = ", ".join(f"{q} {v}{(' ' + u) if u else ''}" for q, v, u in rows
                            if q in ("status", "collapse mode", "mechanism acceleration", "crack angle",
                                     "dislodged", "collapse time", "lambda", "wall time, 1 thread"))
        print(f"convergence: done  {c} / {s}: {summary}", flush=True)

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {pool.submit(work, c, s): (c, s) for c, s in todo}
        for f in concurrent.futures.as_completed(futures):
            if f.exception():
                failed.append(futures[f])
                print(f"convergence: FAILED {futures[f]}: {f.exception()}", file=sys.stderr, flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
