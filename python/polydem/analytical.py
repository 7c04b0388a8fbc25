"""The models of `polydem analytic` from Python: the paper's closed-form and
ODE models and the limit analyses and DEM frequency of the block model.

Each function is the command line's model of the same name ('-' as '_';
`lambda` is `static_lambda`), takes its options as keyword arguments with
the same names, units and defaults, and returns the dict that `--json`
prints, with every number at full precision (the command line prints 12
significant digits). NaN is None. rocking() adds the history as an (n, 4)
array (columns history_columns), dem_frequency() the tip's signal t, u.

The block models take `scene`: None (the default [spire]), a deck path or
a polydem.Scene; no_windows=True removes the spire's windows (the override
spire.window_faces=[]).

fragility() and synthetic_suite() are `polydem analytic fragility` and
`polydem analytic synthetic` (docs/fragility.md): out=DIR writes the
command line's files (fragility() draws no PNG: scripts/plot_fragility.py
DIR does)."""
import functools
import json
import os

import numpy as np

from . import _polydem
from .scene import as_scene


def _dict(f):
    @functools.wraps(f)
    def call(*args, **kwargs):
        return json.loads(f(*args, **kwargs))
    return call


def _parsed(scene, no_windows):
    if scene is None or isinstance(scene, (str, os.PathLike)):
        return _polydem.analytic_scene("" if scene is None else os.fspath(scene), bool(no_windows))
    scene = as_scene(scene)
    if no_windows:
        scene = scene.with_set({"spire.window_faces": []})
    return scene.parsed()


static_lambda = _dict(_polydem.static_lambda)
beam = _dict(_polydem.beam)
collapse_diagram = _dict(_polydem.collapse_diagram)
cracked_cone_p = _dict(_polydem.cracked_cone_p)
arch_thickness = _dict(_polydem.arch_thickness)


@functools.wraps(_polydem.rocking)
def rocking(*args, **kwargs):
    r = json.loads(_polydem.rocking(*args, **kwargs))
    r["history"] = np.array(r["history"], dtype=float).reshape(-1, 4)
    return r


def refined_lambda(scene=None, no_windows=False, **options):
    """The refined static collapse multiplier of the scene's [spire]
    (`polydem analytic refined-lambda`); options: g."""
    return json.loads(_polydem.refined_lambda(_parsed(scene, no_windows), **options))


def dem_frequency(scene=None, no_windows=False, **options):
    """The first natural frequency of the scene's [spire] by a DEM free
    vibration (`polydem analytic dem-frequency`); options: duration,
    settle, pulse_g, pulse_period, interval, keep_damping, threads."""
    text, t, u = _polydem.dem_frequency(_parsed(scene, no_windows), **options)
    r = json.loads(text)
    r["t"], r["u"] = np.array(t), np.array(u)
    return r


def limit_lp(scene=None, no_windows=False, **options):
    """The limit-analysis LP of the scene (`polydem analytic limit-lp`);
    options: phi and direction (degrees, a number or a list; phi by default
    the deck's joint.friction_angle, direction 0), sides, pyramid, method,
    lp_file."""
    for key in ("phi", "direction"):
        if key in options:
            options[key] = [float(v) for v in np.atleast_1d(options[key])]
    return json.loads(_polydem.limit_lp(_parsed(scene, no_windows), **options))


__all__ = ["static_lambda", "beam", "rocking", "collapse_diagram", "cracked_cone_p", "refined_lambda",
           "dem_frequency", "limit_lp", "arch_thickness"]


# Records and response spectra (docs/records.md): accelerations in m/s², the
# spectra's psa in m/s², psv in m/s, sd in m, periods in s.
read_record = _polydem.read_record
record_suite = _polydem.record_suite
response_spectrum = _polydem.response_spectrum
spectra = _polydem.spectra


def fragility(csv=None, im=None, state=None, record=None, **options):
    """Lognormal fragility curves fitted to runs (`polydem analytic
    fragility`): a runs CSV, or im and state (and record, for IDA) as
    sequences; options method ('auto', 'ida', 'stripes'), bootstrap, seed,
    confidence, points, out. The curves ('im', and per state 'probability',
    'low', 'high') as numpy arrays."""
    r = json.loads(_polydem.fragility(
        "" if csv is None else os.fspath(csv),
        [] if im is None else [float(x) for x in im],
        [] if state is None else [str(s) for s in state],
        [] if record is None else [str(s) for s in record],
        **{k: (os.fspath(v) if k == "out" else v) for k, v in options.items()}))
    r["im"] = np.array(r["im"], dtype=float)
    for s in r["states"]:
        for k in ("probability", "low", "high"):
            s[k] = np.array([np.nan if x is None else x for x in s[k]], dtype=float)
    return r


def synthetic_suite(magnitude, distance, vs30, **options):
    """A suite of synthetic records (`polydem analytic synthetic`); options
    count, seed, fault, dt, high_pass, prefix, out. Each record's
    'acceleration_m_s2' is a numpy array sampled every 'dt' from t = 0."""
    if "out" in options:
        options["out"] = os.fspath(options["out"])
    r = json.loads(_polydem.synthetic_suite(magnitude, distance, vs30, **options))
    for rec in r["records"]:
        rec["acceleration_m_s2"] = np.array(rec["acceleration_m_s2"], dtype=float)
    return r
