"""Studies: the collapse search, sweeps, ensembles and IDA, as numpy
structured arrays.

The runs go on in C++ with the GIL released, one after the other in this
process (each on `threads` OpenMP threads); `progress` is called after each
run with its row as a dict (True: a line on stderr per run; False: nothing;
None: a line per run when stderr is a terminal)."""
import sys

import numpy as np

from . import _polydem
from .scene import as_scene, overrides_list


def structured(rows, columns=None):
    """A list of dicts as a numpy structured array, one field per key
    (floats f8, ints i8, bools ?, strings U)."""
    if columns is None:
        columns = list(rows[0].keys()) if rows else []
    fields = []
    for c in columns:
        values = [r[c] for r in rows]
        if all(isinstance(v, bool) for v in values) and values:
            fields.append((c, "?"))
        elif all(isinstance(v, int) and not isinstance(v, bool) for v in values) and values:
            fields.append((c, "i8"))
        elif all(isinstance(v, str) for v in values) and values:
            fields.append((c, f"U{max(1, max(len(v) for v in values))}"))
        else:
            fields.append((c, "f8"))
    out = np.zeros(len(rows), dtype=fields)
    for i, r in enumerate(rows):
        out[i] = tuple(r[c] for c in columns)
    return out


def _printer(progress, line):
    if progress is None:
        progress = sys.stderr.isatty()
    if progress is True:
        return lambda row: print(line(row), file=sys.stderr, flush=True)
    return progress or None


class CollapseResult:
    """directions: one row per direction (direction_deg, bisection_g, low_g,
    high_g, bisection_runs, bisection_error, ramp_g, crack_angle_deg,
    collapse_mode); trials: one row per run (method: "constant" for a
    bisection trial, "ramp"; direction_deg,
    acceleration_g, collapsed, status, collapse_mode, crack_angle_deg,
    steps, wall_seconds); lowest_g: the lowest collapse acceleration over
    the directions (NaN: none)."""

    def __init__(self, directions, trials, lowest_g):
        self.directions, self.trials, self.lowest_g = directions, trials, lowest_g

    def __repr__(self):
        return f"<polydem.CollapseResult {len(self.directions)} direction(s), {len(self.trials)} runs, lowest {self.lowest_g:.4f} g>"


def collapse_search(scene, directions=(0.0,), method="bisection", *, low_g=0.05, high_g=0.5, tolerance_g=0.005,
                    rise_time=0.5, hold_time=2.5, ramp_rate_g=0.1, threads=0, out=None, progress=None, set=None):
    """The collapse acceleration of the scene per direction (degrees from
    x), as `polydem collapse`: method "bisection" (constant accelerations,
    the bracket halved to tolerance_g), "ramp" (one run under a ramp of
    ramp_rate_g g/s; the acceleration at which the mechanism forms) or
    "both". out: a directory for collapse.json (as the command line's).
    Returns a CollapseResult."""
    scene = as_scene(scene)
    if set:
        scene = scene.with_set(set)
    o = _polydem.CollapseSearchOptions()
    o.low_g, o.high_g, o.tolerance_g = float(low_g), float(high_g), float(tolerance_g)
    o.rise_time, o.hold_time, o.ramp_rate_g, o.threads = float(rise_time), float(hold_time), float(ramp_rate_g), int(threads)
    report = _printer(progress, lambda t: (
        f"  direction {t['direction_deg']:6.1f} deg  {t['method']:<9} a = {t['acceleration_g']:.4f} g  "
        f"{t['status']:<9} {t['steps']} steps  {t['wall_seconds']:.1f} s"))
    rows, trials, lowest = _polydem.collapse_search(scene.parsed(), [float(d) for d in directions], method, o,
                                                    "" if out is None else str(out), report)
    return CollapseResult(structured(rows), structured(trials, [
        "method", "direction_deg", "acceleration_g", "collapsed", "status", "collapse_mode", "crack_angle_deg",
        "steps", "wall_seconds"]), lowest)


class SweepResult:
    """points: one row per run (the varied keys, status, collapse_mode,
    peak_tip_displacement, peak_displacement, residual_displacement,
    collapse_time, dislodged, steps, wall_seconds, exit_code, message); columns (a
    boundary search only): one row per column of the outer grid with
    damage_threshold, stones_lost_threshold, collapse_threshold, collapse_mode, runs."""

    def __init__(self, points, columns):
        self.points, self.columns = points, columns

    def __repr__(self):
        return f"<polydem.SweepResult {len(self.points)} runs, {len(self.columns)} columns>"


def sweep(scene, vary=None, search=None, resolution=None, threads=1, progress=None, set=None):
    """Runs the scene over a grid of deck keys, as `polydem sweep`:
    vary = {key: values} (the first key varies slowest). search =
    "KEY=START:STOP:N" (or (key, start, stop, n)) with `resolution` adds a
    boundary search along KEY for each point of the grid: the damage and
    collapse thresholds with far fewer runs than the full grid
    (docs/sweep.md). Returns a SweepResult."""
    scene = as_scene(scene)
    if set:
        scene = scene.with_set(set)
    axes = [(str(k), [float(v) for v in vs]) for k, vs in (vary or {}).items()]
    if isinstance(search, (tuple, list)):
        key, start, stop, n = search
        search = f"{key}={start!r}:{stop!r}:{int(n)}"
    if search and resolution is None:
        raise ValueError("a search needs a resolution")
    if not axes and not search:
        raise ValueError("give vary={key: values} or a search")
    report = _printer(progress, lambda p: (
        "  " + " ".join(f"{k.rsplit('.', 1)[-1]}={p[k]:g}" for k in p if "." in k) +
        f": {p['status']}{' (Mode ' + p['collapse_mode'] + ')' if p['collapse_mode'] else ''}  ({p['wall_seconds']:.1f} s)"))
    rows, columns = _polydem.sweep(scene.parsed(), axes, search or "", float(resolution or 0), int(threads), report)
    keys = [k for k, _ in axes] + ([search.split("=", 1)[0]] if search else [])
    fields = keys + ["status", "collapse_mode", "peak_tip_displacement", "peak_displacement", "residual_displacement",
                     "collapse_time", "dislodged", "steps", "wall_seconds", "exit_code", "message"]
    cols = structured(columns, [k for k, _ in axes] + ["damage_threshold", "stones_lost_threshold", "collapse_threshold", "collapse_mode",
                                                     "runs", "wall_seconds"]) if columns else structured([])
    return SweepResult(structured(rows, fields) if rows else structured([]), cols)


class EnsembleResult:
    """replicas: one row per replica (replica, seed, what was drawn:
    friction_angle_shift_deg, normal_stiffness_factor,
    shear_stiffness_factor, time_shift_s, largest_initial_speed_m_s; the
    outcome: status, collapse_mode, ground_acceleration_at_damage_g,
    peak_tip_displacement_m, residual_displacement_m and the walking
    openings (NaN: not measured), dislodged_blocks, steps, wall_seconds,
    exit_code, message); summary: a dict with replicas, seed, status_counts
    {status: n}, collapse_modes {"I": n, "II": n}, distributions {outcome:
    {"n", "p16", "median", "p84"}}, as ensemble.json's "outcome", and
    courses (with output.walking; empty otherwise): per course from the
    bottom, a dict with level_m, bed_joints, vertical_joints and each
    figure of courses.csv as {"n", "p16", "median", "p84"}
    (docs/ensembles.md)."""

    def __init__(self, replicas, summary):
        self.replicas, self.summary = replicas, summary

    def __repr__(self):
        counts = ", ".join(f"{k} {v}" for k, v in self.summary["status_counts"].items())
        return f"<polydem.EnsembleResult {len(self.replicas)} replicas: {counts}>"


def ensemble(scene, replicas, seed=None, threads=1, progress=None, set=None):
    """Runs `replicas` replicas of the scene with seeded perturbations, as
    `polydem ensemble` (docs/ensembles.md): replica 0 is the scene as given,
    replica k > 0 the scene with [ensemble] replica = k; seed: the
    perturbations' seed (None: the scene's ensemble.seed, 1). The replicas
    run one after the other in this process. Returns an EnsembleResult."""
    scene = as_scene(scene)
    if set:
        scene = scene.with_set(set)
    if seed is not None:
        if int(seed) != seed or seed < 0:
            raise ValueError(f"seed must be an integer >= 0 (got {seed!r})")
        scene = scene.with_set({"ensemble.seed": int(seed)})
    if int(replicas) != replicas or not 1 <= replicas <= 1000000:
        raise ValueError(f"replicas must be an integer in [1, 1000000] (got {replicas!r})")
    report = _printer(progress, lambda r: (
        f"  replica {r['replica']}: {r['status']}{' (Mode ' + r['collapse_mode'] + ')' if r['collapse_mode'] else ''}"
        f"  ({r['wall_seconds']:.1f} s)"))
    rows, summary = _polydem.ensemble(scene.parsed(), int(replicas), int(threads), report)
    return EnsembleResult(structured(rows), summary)


class IdaResult:
    """runs: one row per run (record, im, scale, state, status,
    collapse_mode, peak_tip_displacement, residual_displacement,
    peak_displacement, max_bed_opening, max_vertical_opening (NaN unless
    output.walking), dislodged, damage_time, collapse_time (-1: none), steps,
    wall_seconds, exit_code, message), by record then IM; records: one row
    per record (record, record_im, damage_im, stones_lost_im, collapse_im
    (NaN: not reached), below_collapse_im, collapse_scale, runs,
    undetermined), as capacities.csv (docs/ida.md)."""

    def __init__(self, runs, records):
        self.runs, self.records = runs, records

    def __repr__(self):
        return f"<polydem.IdaResult {len(self.records)} record(s), {len(self.runs)} runs>"


def ida(scene, suite, im="pga", period=None, damping=0.05, *, stripes=None, scales=None, hunt=(0.05, 0.05, 0.05),
        tolerance=0.01, max_runs=12, threads=1, out=None, progress=None, set=None):
    """Incremental dynamic analysis of the scene under the records of a
    suite file, as `polydem ida` (docs/ida.md): im "pga" or "sa" (with
    period T1 in s and damping), in g. By default hunt-and-fill on each
    record: hunt = (first, step, growth) IMs up to the first collapse, the
    bracket bisected to `tolerance`, the gaps below filled, at most
    max_runs runs per record. stripes = [IM, ...]: a multiple-stripe
    analysis instead; scales = [factor, ...]: every record at those scale
    factors. The runs go one after the other in this process. out: a
    directory for ida.csv and capacities.csv (`polydem analytic fragility`
    reads ida.csv). Returns an IdaResult."""
    scene = as_scene(scene)
    if set:
        scene = scene.with_set(set)
    if stripes is not None and scales is not None:
        raise ValueError("give stripes or scales, not both")
    if im not in ("pga", "sa"):
        raise ValueError(f"im must be 'pga' or 'sa' (got {im!r})")
    if im == "pga" and period is not None:
        raise ValueError("period goes with im='sa'")
    h = _polydem.HuntAndFill()
    h.first, h.step, h.growth = (float(x) for x in hunt)
    h.tolerance, h.max_runs = float(tolerance), int(max_runs)
    mode = "stripes" if stripes is not None else "scales" if scales is not None else "hunt"
    levels = [float(x) for x in (stripes if stripes is not None else scales if scales is not None else [])]
    report = _printer(progress, lambda r: (
        f"  {r['record']} im={r['im']:g}: {r['status']}"
        f"{' (Mode ' + r['collapse_mode'] + ')' if r['collapse_mode'] else ''}  ({r['wall_seconds']:.1f} s)"))
    rows, records = _polydem.ida(scene.parsed(), str(suite), im, float(period or 0), float(damping), mode, levels, h,
                                 int(threads), "" if out is None else str(out), report)
    fields = ["record", "im", "scale", "state", "status", "collapse_mode", "peak_tip_displacement",
              "residual_displacement", "peak_displacement", "max_bed_opening", "max_vertical_opening", "dislodged",
              "damage_time", "collapse_time", "steps", "wall_seconds", "exit_code", "message"]
    return IdaResult(structured(rows, fields) if rows else structured([]),
                     structured(records, ["record", "record_im", "damage_im", "stones_lost_im", "collapse_im",
                                          "below_collapse_im", "collapse_scale", "runs", "undetermined"]))
