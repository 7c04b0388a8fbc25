#!/usr/bin/env python3
"""The docs' generated tables: every block between

    <!-- table:NAME -->
    ...
    <!-- /table -->

in README.md and docs/*.md is written by this script, from the measured
figures in benchmarks/results/*.csv and from the source tree, never by hand.

    scripts/doc_tables.py                  rewrite the blocks
    scripts/doc_tables.py --check          exit 1, with a diff, where a block
                                           differs from what would be written
                                           (ctest's doc_tables)
    scripts/doc_tables.py --run-decks build/polydem
                                           run the verification decks and the
                                           main job, write checks.csv and
                                           outcomes.csv, then rewrite

The CSVs:
  checks.csv     every [[check]] of examples/verification/*.toml: measured,
                 expected, tolerance (deterministic: the same on any machine)
  outcomes.csv   the main job's verdict and figures, and what the README's
                 Python example prints (deterministic)
  timings.csv    wall times: machine, cpu, commit, date, command, quantity,
                 value, unit (benchmarks/spire_speed.py, benchmarks/build_time.sh
                 and by hand from .ci/run's log)
  error_vs_time.csv, throughput.csv, redetection_jump.csv
                 written by the benchmark programs
  convergence.csv  the spire's answers per numerical setting: machine, cpu,
                 commit, date, case, setting, quantity, value, unit
                 (benchmarks/convergence.py)
  distributions.csv  the ensembles' bands per safety factor, the same columns
                 (benchmarks/distributions.py)
  ledger.csv     the energy ledger's numerical line per run, the same
                 columns (benchmarks/ledger.py)
The tables show the commit each figure was measured at; the machine and the
date stay in the CSV.

The `generator_sections` block (docs/deck.md) is the reference each
generator section keeps in its io/*_section.cpp, in a `/* docs/deck.md */`
comment: a new generator's file brings its own documentation.

The `layout` table (docs/architecture.md) counts the source tree: C++ files
and lines per top-level folder. --check accepts its counts within 10 % (the
tree moves with every change; the folders must match exactly), and checks
that every repository path architecture.md names in backquotes exists.
"""
import argparse
import csv
import datetime
import difflib
import glob
import json
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
RESULTS = os.path.join(ROOT, "benchmarks", "results")
# The benchmarks' own lists of settings give the tables' column and row order.
sys.path.insert(0, os.path.join(ROOT, "benchmarks"))
import convergence  # noqa: E402
import distributions  # noqa: E402
BLOCK = re.compile(r"(<!-- table:([a-z0-9_]+) -->\n)(.*?)(<!-- /table -->)", re.S)


# --- reading the CSVs ------------------------------------------------------

def read_csv(name):
    """Rows of benchmarks/results/NAME as dicts; lines starting with # are
    comments (the benchmark programs' header of machine and commit)."""
    path = os.path.join(RESULTS, name)
    with open(path, encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def csv_comment(name, key):
    """The value of a `# key: value` comment line of a benchmark CSV."""
    with open(os.path.join(RESULTS, name), encoding="utf-8") as f:
        for line in f:
            if line.startswith(f"# {key}:"):
                return line.split(":", 1)[1].strip().split(",")[0].strip()
    return "?"


def markdown(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(out) + "\n"


def timing_rows(table):
    return [r for r in read_csv("timings.csv") if r["table"] == table]


def timings(table):
    """quantity and value, and the command, commit and note: as columns
    where they differ between rows, else once under the table."""
    rows = timing_rows(table)
    if not rows:
        return "(not measured yet)\n"
    header, varying, common = ["quantity", "value"], [], []
    for key in ("command", "commit", "note"):
        values = {r[key] for r in rows}
        if len(values) > 1:
            varying.append(key)
        elif values != {""}:
            common.append(key)
    body = markdown(header + varying,
                    [[r["quantity"], f'{r["value"]} {r["unit"]}'.strip()] +
                     [f'`{r[k]}`' if k == "command" else r[k] for k in varying] for r in rows])
    said = {"command": lambda v: f"`{v}`", "commit": lambda v: f"at {v}", "note": lambda v: v}
    if common:
        body += "\n" + "; ".join(said[k](rows[0][k]) for k in common) + ".\n"
    return body


# --- the tables --------------------------------------------------------------

def table_checks():
    rows = read_csv("checks.csv")
    body = markdown(
        ["deck", "check", "what is measured", "measured", "expected", "tolerance", "passed"],
        [(f'`{r["deck"]}`', r["check"], r["quantity"], f'{r["measured"]} {r["unit"]}'.rstrip(" -"),
          r["expected"], r["tolerance"], r["passed"]) for r in rows])
    commits = sorted({r["commit"] for r in rows})
    return body + f"\nFrom `scripts/doc_tables.py --run-decks build/polydem` at {', '.join(commits)}.\n"


def outcome(quantity):
    for r in read_csv("outcomes.csv"):
        if r["quantity"] == quantity:
            return r
    raise KeyError(quantity)


def table_main_job_verdict():
    lines = [outcome(f"verdict line {i}")["value"] for i in (1, 2, 3)]
    return "```\n" + "\n".join(lines) + "\n```\n"


def table_main_job():
    rows = [r for r in read_csv("outcomes.csv") if not r["quantity"].startswith(("verdict", "python"))]
    body = markdown(["quantity", "value"], [(r["quantity"], f'{r["value"]} {r["unit"]}'.strip()) for r in rows])
    return body + f'\nFrom `{rows[0]["command"]}` at {rows[0]["commit"]}.\n'


def without_leading_comments(path, fence):
    with open(os.path.join(ROOT, path), encoding="utf-8") as f:
        lines = f.read().splitlines()
    while lines and (lines[0].startswith("#") or not lines[0].strip()):
        lines.pop(0)
    return f"```{fence}\n" + "\n".join(lines) + "\n```\n"


def table_deck_example():
    return without_leading_comments("examples/verification/rocking_onset.toml", "toml")


def table_python_example():
    return without_leading_comments("examples/python/ten_lines.py", "python")


def table_python_example_output():
    lines = [r["value"] for r in read_csv("outcomes.csv") if r["quantity"].startswith("python line")]
    return "```\n" + "\n".join(lines) + "\n```\n"


def table_error_vs_time():
    rows = read_csv("error_vs_time.csv")
    header = ["case", "check", "parameter", "value", "dt (s)", "steps", "wall (s)", "measured", "expected", "error"]
    return (markdown(header, [[r[h] for h in header] for r in rows]) +
            f'\nFrom `scripts/bench.sh error` at {csv_comment("error_vs_time.csv", "polydem")}, 1 thread.\n')


def table_throughput():
    rows = read_csv("throughput.csv")
    header = ["scene", "blocks (with base)", "threads", "parallel threshold", "steps", "subcontacts/step",
              "wall best (s)", "updates/s", "speed-up", "bitwise = 1 thread"]
    return (markdown(header, [[r[h] for h in header] for r in rows]) +
            f'\nFrom `scripts/bench.sh throughput` at {csv_comment("throughput.csv", "polydem")}, best of 5 runs.\n')


def table_redetection_jump():
    rows = read_csv("redetection_jump.csv")
    header = ["joint model", "scene", "seeds", "pairs", "worst jump"]
    return (markdown(header, [[r[h] for h in header] for r in rows]) +
            f'\nFrom `scripts/bench.sh jump` at {csv_comment("redetection_jump.csv", "polydem")}: the largest '
            'change of any pair\'s force or moment, relative to the largest before, that the seeds found (a '
            'lower bound on the model\'s worst).\n')


def table_wall_scaling():
    rows = read_csv("wall_scaling.csv")
    body = markdown(
        ["blocks", "leaves", "threads", "subcontacts", "µs per step", "ns per update", "peak memory (MiB)"],
        [(f'{int(r["blocks"]):,}', r["leaves"], r["threads"], f'{int(r["subcontacts"]):,}',
          f'{float(r["us_per_step"]):,.0f}', f'{float(r["ns_per_update"]):.1f}', f'{float(r["peak_rss_mib"]):,.0f}')
         for r in rows])
    return body + f'\nFrom `benchmarks/wall_scaling.py` at {csv_comment("wall_scaling.csv", "polydem")}, one run a case.\n'


def table_convergence():
    """benchmarks/convergence.py's runs: one row per numerical setting, the
    answers of each case as columns."""
    path = os.path.join(RESULTS, "convergence.csv")
    if not os.path.exists(path):
        return "(not measured yet)\n"
    rows = read_csv("convergence.csv")
    got = {}
    for r in rows:
        got.setdefault((r["case"], r["setting"]), {})[r["quantity"]] = r["value"]
    order = list(convergence.SETTINGS)
    settings = sorted({r["setting"] for r in rows}, key=lambda s: (order.index(s) if s in order else len(order), s))

    def crack(q):
        if "crack angle" not in q:
            return "none"
        low, high = (float(q[k]) + 0.0 for k in ("crack lowest z", "crack highest z"))  # + 0.0: no "-0.00"
        return f'{q["crack angle"]}°, z {low:.2f}–{high:.2f} m ({q["opened joints"]} joints)'

    def outcome(q):
        text = q["status"] + (f' {q["collapse mode"]}' if q["collapse mode"] != "-" else "")
        if "collapse time" in q:
            text += f' at {q["collapse time"]} s'
        return text + f', {lost(q)}'

    def lost(q):
        return f'{q["dislodged"]} lost' + (f' ({q["fallen"]} fell)' if "fallen" in q else "")

    def setting_name(s):
        name = s.replace(" x", " ×")
        main = got.get(("main", s), {})
        margin, travel = main.get("contact margin"), main.get("detection travel")
        if margin and "margin x" in s:
            with_margin = name.replace(", travel", f" ({1000 * float(margin):.2f} mm), travel")
            name = with_margin if with_margin != name else f"{name} ({1000 * float(margin):.2f} mm)"
        elif margin and "margin" not in s.replace("half the margin", "") and "corner" in s:
            # a geometry with its own automatic margin
            name = name.replace("merged corner stones", f"merged corner stones, margin {1000 * float(margin):.2f} mm")
        if travel and ("travel x" in s or s in ("default", "re-sampled at detection", "scene trigger")):
            name = f"{name} ({1000 * float(travel):.2g} mm)"
        return name

    def numerical(q):
        v = q.get("numerical energy of slip and damping")
        return f"{float(v):+.2f} %" if v not in (None, "", "-") else "-"

    def effort(q):
        wall = q.get("wall time, 1 thread")
        text = f"{float(wall):.0f} s" if wall else "-"
        if q.get("pairs re-sampled"):
            text += f' ({int(q["detections"]):,} detections, {int(q["pairs re-sampled"]):,} pairs re-sampled)'
        elif q.get("detections"):
            text += f' ({int(q["detections"]):,} detections)'
        return text

    header = ["setting", "time step (µs)", "mechanism (g)", "crack", "stones lost", "main job",
              "main job's run (1 thread)", "numerical (of slip + damping)", "pulse 0.25 g", "pulse 0.35 g", "pulse 0.5 g", "λ onto a window face (g, bracket)"]
    table = []
    for s in settings:
        m = got.get(("main", s))
        line = [setting_name(s)]
        if m:
            line += [f'{1e6 * float(m["time step"]):.2f}', m["mechanism acceleration"], crack(m),
                     lost(m), m["status"] + (f' {m["collapse mode"]}' if m["collapse mode"] != "-" else ""),
                     effort(m), numerical(m)]
        else:
            line += ["not run"] * 7
        for case in ("pulse25", "pulse35", "pulse50"):
            q = got.get((case, s))
            line.append(outcome(q) if q else "not run")
        q = got.get(("lambda", s))
        line.append(f'{q["lambda"]} ({q["lambda bracket low"]}–{q["lambda bracket high"]})' if q else "not run")
        table.append(line)
    commits = sorted({r["commit"] for r in rows})
    return (markdown(header, table) +
            f"\nFrom `benchmarks/convergence.py build/polydem` at {', '.join(commits)}, one run per cell on "
            "1 thread (the run column's wall times from runs two at a time on 2 cores beside other work: what a "
            "run costs, not a benchmark, which docs/benchmarks.md keeps); the default clips each joint again as its "
            "blocks move and re-samples it pair by pair, at its automatic travel; \"re-sampled at detection\": "
            "the joints' points and areas fixed from one pair-by-pair re-sampling to the next "
            "(`simulation.joint_sampling = \"detection\"`); \"joints clipped every step\": at a travel of "
            "1e-12 m; \"scene trigger\": the joints re-sampled scene-wide at detection "
            "(`simulation.detection_trigger = \"scene\"`), its travel factors of the scene-wide automatic "
            "travel (sixteen times the pair-by-pair one); \"travel half the margin\": the detection travel at its "
            "largest, half the contact margin (`simulation.detection_travel = 1`), where the margin also sets how "
            "often the joints are re-sampled (λ: five trials from [0.155, 0.205] g, six from [0.105, 0.205] g where "
            "λ lies lower, the bracket halved to 0.00625 g); the wall times, steps, margins and "
            "energy lines are in benchmarks/results/convergence.csv. The crack: the joints of the initial mesh "
            "whose faces moved apart, open or slid, by more than 2.5 mm (half the damage displacement), from "
            "the blocks' poses (run/crack.hpp).\n")


def band_mm(median, p16, p84):
    """An ensemble's median [16-84 %] of a length in metres, as mm."""
    v = [1e3 * float(x) for x in (median, p16, p84)]
    return f"{v[0]:.1f} [{v[1]:.1f}, {v[2]:.1f}]"


def table_distributions():
    """benchmarks/distributions.py's ensembles: one row per figure, one
    column per safety factor."""
    if not os.path.exists(os.path.join(RESULTS, "distributions.csv")):
        return "(not measured yet)\n"
    rows = read_csv("distributions.csv")
    got = {}
    for r in rows:
        got.setdefault((r["case"], r["setting"]), {})[r["quantity"]] = r["value"]
    order = list(distributions.SETTINGS)
    settings = sorted({r["setting"] for r in rows}, key=lambda s: (order.index(s) if s in order else len(order), s))

    def collapse(q):
        if "collapse 50 %" in q:
            return f'{float(q["collapse 50 %"]):.3f} [{float(q["collapse 16 %"]):.3f}, {float(q["collapse 84 %"]):.3f}]'
        if "collapse bracket below" in q and "collapse bracket above" in q:
            return f'{float(q["collapse bracket below"]):.2f}-{float(q["collapse bracket above"]):.2f} (a step)'
        return q.get("collapse status", "-")

    def mm(q, stem):
        if f"{stem} median" not in q:
            return "-"
        return band_mm(*(q[f"{stem} {p}"] for p in ("median", "p16", "p84")))

    def median_interval(q):
        if "residual_vertical_opening median 5 %" not in q:
            return "-"
        return (f'[{1e3 * float(q["residual_vertical_opening median 5 %"]):.1f}, '
                f'{1e3 * float(q["residual_vertical_opening median 95 %"]):.1f}]')

    lines = []
    for T in ("0.6", "1.0", "2.0"):
        lines.append((f"tip, T_p = {T} s: collapse a_p, 50 % [16-84 %] (g)", f"tip{T}", collapse))
    for label, stem in (("largest residual vertical opening", "residual_vertical_opening"),
                        ("largest residual bed opening", "residual_bed_opening"),
                        ("largest vertical opening during the run", "max_vertical_opening"),
                        ("top course: largest residual vertical opening", "top course residual vertical largest")):
        lines.append((f"spire, record ×4: {label}, median [16-84 %] (mm)", "walking4",
                      (lambda st: lambda q: mm(q, st))(stem)))
        if stem == "residual_vertical_opening":
            lines.append(("spire, record ×4: the median's 5-95 % interval, replicas resampled (mm)", "walking4",
                          median_interval))
    lines.append(("spire, record ×4: replicas", "walking4", lambda q: q.get("replicas", "-")))
    # One row per setting (pair by pair first, then scene-wide), one column per figure.
    table = []
    for s in settings:
        table.append([s.replace(" x", " ×")] + [
            show(got[(case, s)]) if (case, s) in got else
            "–" if case.startswith("tip") and s in distributions.WALKING_ONLY else "not run"
            for _, case, show in lines])
    commits = sorted({r["commit"] for r in rows})
    return (markdown(["setting"] + [label for label, _, _ in lines], table) +
            f"\nFrom `benchmarks/distributions.py build/polydem` at {', '.join(commits)}: the tip 20 replicas a "
            f"point (at the two safety factors only), the spire's replicas as the column says; the joints clipped as "
            "they move (the default), \"re-sampled at detection\" pair by pair (`simulation.joint_sampling = "
            "\"detection\"`) or, \"scene trigger\", scene-wide (`simulation.detection_trigger = "
            "\"scene\"`, its automatic travel 0.38 mm on the spire); \"travel half "
            "the margin\": the detection travel at half the contact margin (`simulation.detection_travel = 1`); "
            "\"a step\": every replica "
            "survives at the first amplitude and collapses at the second (0.01 g apart). Run times in "
            "benchmarks/results/distributions.csv.\n")


SOURCE_EXT = (".cpp", ".hpp", ".inc", ".h")
NOT_SOURCE = {"tests", "benchmarks", "fuzz", "examples", "docs", "scripts"}


def source_folders():
    """{folder: (files, lines, largest file, its lines)} for every top-level
    folder of C++ sources that is part of the product (python/ included)."""
    out = {}
    git = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True)
    tracked = git.stdout.split() if git.returncode == 0 else [
        os.path.relpath(os.path.join(d, f), ROOT) for d, _, files in os.walk(ROOT) for f in files]
    for path in tracked:
        parts = path.split("/")
        if len(parts) < 2 or parts[0] in NOT_SOURCE or not path.endswith(SOURCE_EXT):
            continue
        full = os.path.join(ROOT, path)
        if not os.path.exists(full):
            continue
        with open(full, encoding="utf-8", errors="replace") as f:
            n = sum(1 for _ in f)
        files, lines, big, big_n = out.get(parts[0], (0, 0, "", 0))
        if n > big_n:
            big, big_n = path, n
        out[parts[0]] = (files + 1, lines + n, big, big_n)
    return dict(sorted(out.items()))


def table_layout():
    rows = [(f"`{k}/`", f, f"{n:,}", f"`{big}` ({big_n:,})") for k, (f, n, big, big_n) in source_folders().items()]
    total_f = sum(v[0] for v in source_folders().values())
    total_n = sum(v[1] for v in source_folders().values())
    rows.append(("all", total_f, f"{total_n:,}", ""))
    return markdown(["folder", "C++ files", "lines", "largest file (lines)"], rows)


TWO_COMMANDS = [  # (command, what, table, quantity)
    ("`scripts/quickstart.sh`", "build the polydem program", "build",
     "build for scripts/quickstart.sh (the polydem target)"),
    ("", "run the main job", "spire_speed", "main job: wall time"),
    ("`scripts/test.sh`", "build everything", "build", "build for scripts/test.sh (everything)"),
    ("", "run the default test suite", "build", "default test suite (ctest -LE slow)"),
]


def table_two_commands():
    """What the README's two commands take, packages installed."""
    rows, commits = [], set()
    for command, what, table, quantity in TWO_COMMANDS:
        match = [r for r in timing_rows(table) if r["quantity"] == quantity]
        if match:
            rows.append((command, what, f'{match[0]["value"]} {match[0]["unit"]}'))
            commits.add(match[0]["commit"])
        else:
            rows.append((command, what, "not measured"))
    return (markdown(["command", "step", "wall time"], rows) +
            f"\nPackages installed; measured at {', '.join(sorted(commits))} (benchmarks/results/timings.csv "
            "has each figure's machine; docs/benchmarks.md).\n")


def table_generator_sections():
    """docs/deck.md's reference of the generator sections: the
    `/* docs/deck.md ... */` comment of each io/*_section.cpp, in the order
    the deck reader reads the sections (their `.order`)."""
    sections = []
    for path in glob.glob(os.path.join(ROOT, "io", "*_section.cpp")):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        doc = re.search(r"^/\* docs/deck\.md\n(.*?)\n\*/$", text, re.S | re.M)
        order = re.search(r"\.order = (\d+)", text)
        if doc and order:
            sections.append((int(order.group(1)), doc.group(1).rstrip("\n")))
    return "\n\n".join(doc for _, doc in sorted(sections)) + "\n"


def table_ledger():
    """benchmarks/ledger.py's runs: the energy ledger's numerical line per
    run, one row per (run, setting)."""
    if not os.path.exists(os.path.join(RESULTS, "ledger.csv")):
        return "(not measured yet)\n"
    rows = read_csv("ledger.csv")
    got, order = {}, []
    for r in rows:
        key = (r["case"], r["setting"])
        if key not in got:
            order.append(key)
        got.setdefault(key, {})[r["quantity"]] = r["value"]
    names = {"main": "main job (`polydem run --default`)",
             "pulse35": "spire pulse 0.35 g, T_p = 1 s, through the collapse",
             "pulse50": "spire pulse 0.5 g, T_p = 1 s, through the collapse",
             "pulse100": "spire pulse 1.0 g, T_p = 1 s, through the collapse",
             "earthquake": "earthquake deck (record ×4)"}

    def pct(v):
        return "-" if v in ("-", "") else f"{float(v):+.3g} %"

    table = []
    for case, setting in order:
        q = got[(case, setting)]
        name = names.get(case, f"`{case}.toml`")
        if setting != "default":
            name += f" ({setting})"
        table.append([name, q["status"], q["simulated time"], q["energy put in"], q["slip"], q["damping"],
                      q["numerical"], pct(q["numerical of the energy put in"]),
                      pct(q["numerical of slip and damping"]),
                      f'{float(q["largest numerical excursion of the energy put in"]):.2g} %',
                      q.get("numerical at detections", "not measured")])
    header = ["run", "status", "simulated (s)", "put in (J)", "slip (J)", "damping (J)", "numerical (J)",
              "numerical, of the energy put in", "numerical, of slip + damping", "largest numerical (magnitude) during the run",
              "of the numerical, at detections (J)"]
    commits = sorted({r["commit"] for r in rows})
    return (markdown(header, table) +
            f"\nFrom `benchmarks/ledger.py build/polydem` at {', '.join(commits)}, one run each on 1 thread "
            "(the wall times are in benchmarks/results/ledger.csv).\n")


def table_spire_walking(name="spire_walking"):
    """docs/spire.md's walking under the earthquake deck: one row per record
    scale from docs/data/<name>.csv (the ensembles.csv of `polydem sweep
    --replicas`; spire_walking: re-sampled scene-wide, spire_walking_pair:
    the default, the joints clipped as they move, pair by pair;
    spire_walking_detection: re-sampled pair by pair at detection), median
    [16-84 %] over the replicas in mm."""
    path = os.path.join(ROOT, "docs", "data", name + ".csv")
    with open(path, encoding="utf-8") as f:
        rows = list(csv.DictReader(f))

    def mm(r, stem):
        return band_mm(*(r[f"{stem}_{k}"] for k in ("median", "p16", "p84")))

    def outcome(r):
        counts = [(int(r[k]), k[2:].replace("_", " ")) for k in r if k.startswith("n_") and r[k] and int(r[k]) > 0]
        return ", ".join(f"{label} {n} of {r['replicas']}" for n, label in counts)

    header = ["record", "largest residual opening, vertical joints", "vertical, during the shaking",
              "largest residual opening, bed joints", "bed, during the shaking", "tip's peak", "outcome"]
    table = [[f"×{float(r['ground_motion.scale']):g}", mm(r, "residual_vertical_opening_m"),
              mm(r, "max_vertical_opening_m"), mm(r, "residual_bed_opening_m"), mm(r, "max_bed_opening_m"),
              mm(r, "peak_tip_displacement_m"), outcome(r)]
             for r in sorted(rows, key=lambda r: float(r["ground_motion.scale"]))]
    return markdown(header, table)


def table_spire_bands():
    """docs/analytical.md's whole spire under one-sine pulses as ensembles,
    re-sampled scene-wide, from docs/data/spire_bands_default.csv and its
    _points.csv (scripts/bands_refine.py merge of the sweeps' columns): per
    T_p the 50 % boundary of damage, stones lost and collapse (fitted: 50 %
    [16-84 %]; otherwise the bracket the replicas observed), then per point
    how the replicas ended."""
    base = os.path.join(ROOT, "docs", "data", "spire_bands_default")
    with open(base + ".csv", encoding="utf-8") as f:
        bands = list(csv.DictReader(f))
    with open(base + "_points.csv", encoding="utf-8") as f:
        points = list(csv.DictReader(f))
    axis, column = "ground_motion.acceleration_g", "ground_motion.period"

    def boundary(r):
        g = lambda k: float(r[f"{axis}_{k}"])  # noqa: E731
        status = r["status"]
        if status == "fitted":
            cell = f"{g(50):.3f} [{g(16):.3f}, {g(84):.3f}]"
        elif status == "not_identified":
            cell = f"{g('below'):g}-{g('above'):g} (a step between points)"
        elif status == "all_reached":
            cell = f"below {g('above'):g} (every point)"
        elif status == "none_reached":
            cell = f"above {g('below'):g} (no point)"
        else:
            cell = status.replace("_", " ")
        if r.get(f"{axis}_falls_back"):
            cell += f"; fewer again from {g('falls_back'):g}"
        return cell

    columns = sorted({float(r[column]) for r in bands})
    by = {(float(r[column]), r["outcome"]): r for r in bands}
    runs = {c: sum(int(p["replicas"]) for p in points if float(p[column]) == c) for c in columns}
    top = markdown(["T_p (s)", "damage (g)", "stones lost (g)", "collapse (g)", "runs"],
                   [[f"{c:g}"] + [boundary(by[(c, o)]) if (c, o) in by else "-"
                                  for o in ("damage", "stones_lost", "collapse")] + [runs[c]]
                    for c in columns])

    def outcomes(p):
        judged = int(p["judged"])
        collapsed = int(p.get("n_collapsed") or 0)
        lost = round(float(p["p_stones_lost"] or 0) * judged) - collapsed
        damaged = int(p.get("n_damaged") or 0) - lost
        modes = [f"{int(p[k])} Mode {k[7:]}" for k in ("n_mode_I", "n_mode_II") if int(p[k] or 0)]
        cells = [p.get("n_intact") or "0", str(damaged), str(lost),
                 f"{collapsed}" + (f" ({', '.join(modes)})" if modes else "")]
        other = int(p["replicas"]) - judged
        return cells + [str(other)]

    rows = [[f"{float(p[column]):g}", f"{float(p[axis]):g}"] + outcomes(p)
            for p in sorted(points, key=lambda p: (float(p[column]), float(p[axis])))]
    low = markdown(["T_p (s)", "a_p (g)", "intact", "damaged, no stone lost", "stones lost, standing", "collapsed",
                    "no verdict"], rows)
    return top + "\n" + low


TABLES = {
    "two_commands": table_two_commands,
    "checks": table_checks,
    "main_job": table_main_job,
    "main_job_verdict": table_main_job_verdict,
    "error_vs_time": table_error_vs_time,
    "throughput": table_throughput,
    "redetection_jump": table_redetection_jump,
    "layout": table_layout,
    "wall_scaling": table_wall_scaling,
    "convergence": table_convergence,
    "distributions": table_distributions,
    "spire_walking": table_spire_walking,
    "spire_walking_pair": lambda: table_spire_walking("spire_walking_pair"),
    "spire_walking_detection": lambda: table_spire_walking("spire_walking_detection"),
    "spire_bands": table_spire_bands,
    "ledger": table_ledger,
    "deck_example": table_deck_example,
    "python_example": table_python_example,
    "python_example_output": table_python_example_output,
    "generator_sections": table_generator_sections,
}
for _name in ("build", "spire_speed", "ci", "governor", "yade"):
    TABLES[f"timings_{_name}"] = (lambda n: lambda: timings(n))(_name)


# --- the checks --------------------------------------------------------------

def layout_within_tolerance(written):
    """The layout block as written against the tree: the same folders, each
    count within 10 %."""
    problems = []
    now = source_folders()
    seen = {}
    for line in written.splitlines():
        m = re.match(r"\| `([a-z_]+)/` \| (\d+) \| ([\d,]+) \|", line)
        if m:
            seen[m.group(1)] = (int(m.group(2)), int(m.group(3).replace(",", "")))
    if set(seen) != set(now):
        problems.append(f"folders {sorted(seen)} in the table, {sorted(now)} in the tree")
    for k in set(seen) & set(now):
        for what, a, b in (("files", seen[k][0], now[k][0]), ("lines", seen[k][1], now[k][1])):
            if abs(a - b) > 0.1 * b:
                problems.append(f"{k}/: {a} {what} in the table, {b} in the tree")
    return problems


def missing_paths(text):
    """Repository paths in backquotes (`run/setup.hpp`, `contact/joint_law.{hpp,cpp}`)
    that do not exist."""
    top = {p.split("/")[0] for p in os.listdir(ROOT)}
    out = []
    for span in re.findall(r"`([^`\s]+)`", text):
        path = span.split(" ")[0]
        if "/" not in path or path.split("/")[0] not in top or "*" in path:
            continue
        m = re.match(r"(.*)\{(.*)\}(.*)", path)
        variants = [m.group(1) + x + m.group(3) for x in m.group(2).split(",")] if m else [path]
        out += [v for v in variants if not os.path.exists(os.path.join(ROOT, v))]
    return sorted(set(out))


def doc_files():
    return [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))


def rewrite(text, path, check, problems):
    def replace(m):
        name, old = m.group(2), m.group(3)
        if name not in TABLES:
            problems.append(f"{os.path.relpath(path, ROOT)}: unknown table '{name}'")
            return m.group(0)
        new = "\n" + TABLES[name]() + "\n"
        if check and old != new:
            if name == "layout":
                problems.extend(f"{os.path.relpath(path, ROOT)}: layout: {p}" for p in layout_within_tolerance(old))
                return m.group(0)
            diff = "".join(difflib.unified_diff(old.splitlines(True), new.splitlines(True),
                                                f"{path} (written)", f"{path} (generated)"))
            problems.append(f"{os.path.relpath(path, ROOT)}: table '{name}' differs:\n{diff}")
        return m.group(1) + new + m.group(4)
    return BLOCK.sub(replace, text)


# --- running the decks -------------------------------------------------------

def git_commit():
    head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True)
    dirty = subprocess.run(["git", "diff", "--quiet", "HEAD", "--", ".", ":!docs", ":!README.md",
                            ":!benchmarks/results"], cwd=ROOT).returncode
    return head.stdout.strip() + ("+" if dirty else "")


def fmt(x):
    return f"{x:.10g}" if isinstance(x, float) else str(x)


def run_decks(polydem, out):
    commit, date = git_commit(), datetime.date.today().isoformat()
    checks = []
    decks = sorted(glob.glob(os.path.join(ROOT, "examples", "verification", "*.toml")))
    env = dict(os.environ, OMP_NUM_THREADS=os.environ.get("OMP_NUM_THREADS", "2"))
    for deck in decks:
        rel = os.path.relpath(deck, ROOT)
        d = os.path.join(out, os.path.basename(deck)[:-5])
        print(f"doc_tables: {rel}", file=sys.stderr)
        subprocess.run([polydem, "run", deck, "--quiet", "--out", d], env=env, check=False)
        with open(os.path.join(d, "summary.json"), encoding="utf-8") as f:
            s = json.load(f)
        for c in s["checks"]:
            checks.append({"commit": commit, "date": date, "deck": os.path.basename(deck), "check": c["name"],
                           "quantity": c["note"].replace("|", "/"), "measured": fmt(c["measured"]),
                           "expected": fmt(c["expected"]), "tolerance": fmt(c["tolerance"]),
                           "unit": c["unit"], "passed": "yes" if c["passed"] else "NO"})
    with open(os.path.join(RESULTS, "checks.csv"), "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, list(checks[0]))
        w.writeheader()
        w.writerows(checks)

    print("doc_tables: polydem run --default", file=sys.stderr)
    d = os.path.join(out, "main")
    p = subprocess.run([polydem, "run", "--default", "--out", d], env=env, capture_output=True, text=True)
    verdict = p.stdout.splitlines()[-3:]
    with open(os.path.join(d, "summary.json"), encoding="utf-8") as f:
        s = json.load(f)
    a = s["assessment"]
    command = "polydem run --default"
    rows = [(f"verdict line {i + 1}", line, "") for i, line in enumerate(verdict)] + [
        ("status", s["status"], ""),
        ("collapse mode", a["collapse_mode"], ""),
        ("ground acceleration when the mechanism formed", f'{a["ground_acceleration_at_damage_g"]:.4f}', "g"),
        ("time the mechanism formed", f'{a["damage_time_s"]:.3f}', "s"),
        ("time of collapse", f'{a["collapse_time_s"]:.3f}', "s"),
        ("stones lost (ending more than 0.1 m from their place)", f'{a["dislodged"]["count"]} of {s["free_blocks"]}', ""),
        ("their fraction of the free mass", f'{100 * a["dislodged"]["mass_fraction"]:.1f}', "%"),
        ("of them fallen (ending 0.1 m below their place)", f'{a["dislodged"]["fallen_count"]}', ""),
        ("energy put in", f'{s["energy"]["put_in_J"]:.4g}', "J"),
        ("numerical energy (made > 0, lost < 0)", f'{s["energy"]["numerical_J"]:.3g}', "J"),
        ("numerical, of the slip and damping dissipation", f'{100 * s["energy"]["numerical_of_dissipation"]:.2g}', "%"),
        ("largest numerical excursion over the energy put in", f'{s["energy_balance_error"]:.2g}', ""),
        ("steps", f'{s["steps"]:,}', ""),
        ("time step", f'{s["time_step_s"]:.3g}', "s"),
        ("simulated time", f'{s["end_time_s"]:.3g}', "s"),
    ]
    print("doc_tables: examples/python/ten_lines.py", file=sys.stderr)
    python = "PYTHONPATH=build/python /usr/bin/python3 examples/python/ten_lines.py"
    p = subprocess.run(["/usr/bin/python3", "examples/python/ten_lines.py"], cwd=ROOT, capture_output=True, text=True,
                       env=dict(env, PYTHONPATH=os.path.join(os.path.dirname(polydem), "python")), check=True)
    with open(os.path.join(RESULTS, "outcomes.csv"), "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["commit", "date", "command", "quantity", "value", "unit"])
        for q, v, u in rows:
            w.writerow([commit, date, command, q, v, u])
        for i, line in enumerate(p.stdout.splitlines()):
            w.writerow([commit, date, python, f"python line {i + 1}", line, ""])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true", help="compare only; exit 1 where a block differs")
    ap.add_argument("--run-decks", metavar="POLYDEM", help="run the decks with this binary first")
    ap.add_argument("--out", default="/tmp/polydem_doc_tables", help="where --run-decks writes its runs")
    args = ap.parse_args()
    if args.run_decks:
        run_decks(os.path.abspath(args.run_decks), args.out)
    problems = []
    for path in doc_files():
        with open(path, encoding="utf-8") as f:
            text = f.read()
        new = rewrite(text, path, args.check, problems)
        if os.path.basename(path) == "architecture.md":
            problems += [f"docs/architecture.md names `{p}`, which does not exist" for p in missing_paths(text)]
        if not args.check and new != text:
            with open(path, "w", encoding="utf-8") as f:
                f.write(new)
            print(f"doc_tables: wrote {os.path.relpath(path, ROOT)}")
    for p in problems:
        print(p)
    if problems:
        print("doc_tables: run scripts/doc_tables.py to rewrite the generated tables", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
