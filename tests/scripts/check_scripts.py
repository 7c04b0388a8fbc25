#!/usr/bin/python3
"""End-to-end check of the plotting scripts in scripts/ (run by CTest, label `scripts`).

    /usr/bin/python3 tests/scripts/check_scripts.py POLYDEM_BINARY SOURCE_DIR

Runs polydem on small cases into a temporary folder (free rocking for 0.3 s with
snapshots, the rocking-onset block under its ramp for 1 s, a constant-acceleration
collapse search on the rocking-onset block in two directions, the 402-block spire
mesh), then every script on the results (with the options the README's gallery
uses: several runs with their difference, --x ground.acceleration, --vline,
--length-unit, several collapse.json with --hline, --zoom), and
checks that each PNG exists, is larger than 10 kB and is not a blank image (the
standard deviation of its pixels). A small polydem sweep boundary search on the
spire's tip feeds plot_pulse_figures.py and plot_collapse_diagram.py, and a
sweep of its ensembles with bands the latter's --bands panels; a sweep of the
column of drums' ensembles with walking feeds plot_walking.py. The spire rendering must take under 20 s.
No pytest: a failure prints what failed and exits 1.
"""

import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402

PYTHON = "/usr/bin/python3"
failures = []


def run(cmd, ok_codes=(0,)):
    t0 = time.monotonic()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seconds = time.monotonic() - t0
    print(f"$ {' '.join(cmd)}  [{seconds:.1f} s, exit {proc.returncode}]")
    if proc.returncode not in ok_codes:
        print(proc.stdout)
        raise SystemExit(f"FAILED: exit code {proc.returncode} (expected {ok_codes})")
    return seconds


def check_png(path):
    if not os.path.exists(path):
        failures.append(f"{path}: not written")
        return
    size = os.path.getsize(path)
    pixels = mpimg.imread(path)[..., :3]
    spread = float(np.std(pixels))
    print(f"  {os.path.basename(path)}: {size / 1024:.0f} kB, {pixels.shape[1]}x{pixels.shape[0]}, "
          f"pixel std {spread:.3f}")
    if size <= 10 * 1024:
        failures.append(f"{path}: only {size} bytes")
    if spread < 0.05:
        failures.append(f"{path}: nearly uniform image (pixel std {spread:.4f})")


def main():
    polydem, source = sys.argv[1], sys.argv[2]
    scripts = os.path.join(source, "scripts")
    verification = os.path.join(source, "examples", "verification")
    with tempfile.TemporaryDirectory(prefix="polydem_scripts_") as tmp:
        rock = os.path.join(tmp, "rock")
        # Exit 1 is expected: 0.3 s ends before the first impact the deck's checks measure.
        run([polydem, "run", os.path.join(verification, "free_rocking.toml"), "--out", rock, "--quiet",
             "--set", "simulation.end_time=0.3", "--set", "output.snapshot_interval=0.1"], ok_codes=(0, 1))
        col = os.path.join(tmp, "collapse")
        run([polydem, "collapse", os.path.join(verification, "rocking_onset.toml"), "--out", col, "--quiet",
             "--direction", "0", "--direction", "90", "--low", "0.1", "--high", "0.5", "--tolerance", "0.05",
             "--hold-time", "1.0", "--ramp-rate", "0.3"])
        onset = os.path.join(tmp, "onset")
        # Exit 1 is expected: 1 s of the ramp ends before the block starts to rock.
        run([polydem, "run", os.path.join(verification, "rocking_onset.toml"), "--out", onset, "--quiet",
             "--set", "simulation.end_time=1.0"], ok_codes=(0, 1))
        mesh = os.path.join(tmp, "spire")
        run([polydem, "mesh", os.path.join(source, "examples", "spire", "spire_geometry.toml"), "--out", mesh])

        png = lambda name: os.path.join(tmp, name)  # noqa: E731
        h5 = os.path.join(rock, "results.h5")
        run([PYTHON, os.path.join(scripts, "plot_histories.py"), h5, "--out", png("histories.png")])
        check_png(png("histories.png"))
        run([PYTHON, os.path.join(scripts, "plot_histories.py"), h5, "--columns", "pillar.rotation.y",
             "pillar.angular_velocity.*", "--relative", "--out", png("histories_some.png")])
        check_png(png("histories_some.png"))
        onset_h5 = os.path.join(onset, "results.h5")
        run([PYTHON, os.path.join(scripts, "plot_histories.py"), onset_h5, "--columns", "pillar.rotation.*",
             "--x", "ground.acceleration", "--vline", "0.05", "a line", "--out", png("histories_x.png")])
        check_png(png("histories_x.png"))
        run([PYTHON, os.path.join(scripts, "plot_histories.py"), h5, onset_h5, "--labels", "free", "onset",
             "--columns", "pillar.rotation.y", "--difference", "--out", png("histories_two.png")])
        check_png(png("histories_two.png"))
        run([PYTHON, os.path.join(scripts, "plot_histories.py"), onset_h5, "--columns", "pillar.rotation.y",
             "ground.*", "--relative", "pillar.*", "--length-unit", "um", "--out", png("histories_rel.png")])
        check_png(png("histories_rel.png"))
        run([PYTHON, os.path.join(scripts, "plot_energy.py"), h5, "--out", png("energy.png")])
        check_png(png("energy.png"))
        run([PYTHON, os.path.join(scripts, "render_blocks.py"), os.path.join(rock, "vtk", "blocks.pvd"), "--last",
             "--out", png("blocks_last.png")])
        check_png(png("blocks_last.png"))
        run([PYTHON, os.path.join(scripts, "render_blocks.py"), os.path.join(rock, "vtk", "blocks.pvd"),
             "--time", "0.1", "--color", "block_id", "--view", "-30", "25", "--out", png("blocks_t.png")])
        check_png(png("blocks_t.png"))
        run([PYTHON, os.path.join(scripts, "picture_strip.py"), os.path.join(rock, "vtk", "blocks.pvd"),
             "--times", "0,0.1,0.2", "--window", "-1", "1", "-1", "1", "--dpi", "40", "--out", png("strip.png")])
        check_png(png("strip.png"))
        seconds = run([PYTHON, os.path.join(scripts, "render_blocks.py"), os.path.join(mesh, "blocks.vtu"),
                       "--color", "course", "--out", png("spire.png")])
        check_png(png("spire.png"))
        run([PYTHON, os.path.join(scripts, "render_blocks.py"), os.path.join(mesh, "blocks.vtu"),
             "--view", "-65", "15", "--size", "6", "6.5", "--zoom", "1.0", "--out", png("spire_zoom.png")])
        check_png(png("spire_zoom.png"))
        if seconds > 20.0:
            failures.append(f"rendering the 402-block spire took {seconds:.1f} s (limit 20 s)")
        collapse_json = os.path.join(col, "collapse.json")
        run([PYTHON, os.path.join(scripts, "plot_collapse.py"), collapse_json, "--out", png("collapse_bar.png")])
        check_png(png("collapse_bar.png"))
        run([PYTHON, os.path.join(scripts, "plot_collapse.py"), collapse_json, "--kind", "polar",
             "--out", png("collapse_polar.png")])
        check_png(png("collapse_polar.png"))
        run([PYTHON, os.path.join(scripts, "plot_collapse.py"), collapse_json, collapse_json, "--kind", "bar",
             "--hline", "0.25", "b/h", "--out", png("collapse_merged.png")])
        check_png(png("collapse_merged.png"))

        # polydem sweep's boundaries.csv: a small boundary search on the tip
        # (two periods, 0.1 g), drawn as Figures 5/7(b) and as a collapse diagram.
        sweep = os.path.join(tmp, "sweep")
        run([polydem, "sweep", os.path.join(source, "examples", "spire", "tip_pulse.toml"), "--out", sweep,
             "--quiet", "--jobs", "2", "--vary", "ground_motion.period=0.75,1.5",
             "--search", "ground_motion.acceleration_g=0.3:2.1:4", "--resolution", "0.1"])
        run([PYTHON, os.path.join(scripts, "plot_pulse_figures.py"), "--spire", sweep, "--tip", sweep,
             "--polydem", polydem, "--out", png("pulse_figures.png")])
        check_png(png("pulse_figures.png"))
        run([PYTHON, os.path.join(scripts, "plot_collapse_diagram.py"), sweep, "--polydem", polydem,
             "--body", "cone", "--r_b", "0.4301", "--H", "3.4", "--a_max", "2.5", "--out", png("sweep_diagram.png")])
        check_png(png("sweep_diagram.png"))
        # The same tip as ensembles with bands along a_p (2 replicas a point),
        # drawn with the analytical curves of both overturning conventions.
        bands = os.path.join(tmp, "bands")
        run([polydem, "sweep", os.path.join(source, "examples", "spire", "tip_pulse.toml"), "--out", bands,
             "--quiet", "--jobs", "2", "--vary", "ground_motion.period=0.75,1.5",
             "--vary", "ground_motion.acceleration_g=0.4,0.8,1.2", "--replicas", "2",
             "--band-axis", "ground_motion.acceleration_g"])
        run([PYTHON, os.path.join(scripts, "plot_collapse_diagram.py"), "--polydem", polydem, "--body", "cone",
             "--r_b", "0.4301", "--H", "3.4", "--a_max", "2.5", "--no-return", "--bands", bands, "deck",
             "--bands", bands, "again", "--dpi", "50", "--out", png("bands_diagram.png")])
        check_png(png("bands_diagram.png"))
        # Walking per course from ensembles: the column of drums with walking
        # on at two amplitudes, 3 replicas each, one table compared with itself.
        walk = os.path.join(tmp, "walk")
        run([polydem, "sweep", os.path.join(source, "examples", "verification", "column_rocking.toml"), "--out", walk,
             "--quiet", "--jobs", "2", "--set", "output.walking=true",
             "--vary", "ground_motion.acceleration_g=0.35,0.4", "--replicas", "3"])
        courses = os.path.join(walk, "courses.csv")
        run([PYTHON, os.path.join(scripts, "plot_walking.py"), courses, "--key", "ground_motion.acceleration_g",
             "--label", "{} g", "--compare", courses, "again {} g", "--dpi", "50", "--out", png("walking.png")])
        check_png(png("walking.png"))
        run([PYTHON, os.path.join(scripts, "plot_walking.py"), courses, "--key", "ground_motion.acceleration_g",
             "--figure", "peak", "--dpi", "50", "--out", png("walking_peak.png")])
        check_png(png("walking_peak.png"))

        # The spire's λ sensitivity (docs/data, measured by polydem collapse) as a tornado chart.
        run([PYTHON, os.path.join(scripts, "plot_sensitivity.py"),
             os.path.join(source, "docs", "data", "spire_lambda_sensitivity.csv"), "--dpi", "40",
             "--out", png("sensitivity.png")])
        check_png(png("sensitivity.png"))

    # The damping lever's stability table (docs/benchmarks.md): on a few
    # networks the explicit scheme must stop at its formula (within the
    # 0.02 grid and the networks' spread) and the block-implicit one must
    # reach the springs' limit, 2.
    proc = subprocess.run([PYTHON, os.path.join(scripts, "damping_stability.py"), "--trials", "4"],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(proc.stdout)
    rows = [line.split() for line in proc.stdout.splitlines()[1:] if line.strip()]
    if proc.returncode != 0 or len(rows) != 4:
        failures.append(f"damping_stability.py: exit {proc.returncode}, {len(rows)} rows")
    for r in rows:
        formula, explicit, block = float(r[1]), float(r[2]), float(r[3])
        if not (formula - 0.1 <= explicit <= formula + 0.02):
            failures.append(f"damping_stability.py: explicit limit {explicit} against the formula {formula}")
        if block < 1.98:
            failures.append(f"damping_stability.py: block-implicit limit {block} below the springs' 2")

    # The split scheme at the engine's step on a few networks, proportional
    # damping and not: stable just below it, and none stable only far below.
    proc = subprocess.run([PYTHON, os.path.join(scripts, "damping_stability.py"), "--split", "--trials", "4"],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(proc.stdout)
    rows = [line.split() for line in proc.stdout.splitlines()[1:] if line.strip()]
    if proc.returncode != 0 or len(rows) != 12:
        failures.append(f"damping_stability.py --split: exit {proc.returncode}, {len(rows)} rows")
    for r in rows:
        radius, ratio = float(r[-2]), float(r[-1])
        if radius > 1 + 1e-6 or ratio < 0.999:
            failures.append(f"damping_stability.py --split: {' '.join(r)}: unstable below the engine's step")

    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("all plotting scripts wrote non-trivial PNGs")


if __name__ == "__main__":
    main()
