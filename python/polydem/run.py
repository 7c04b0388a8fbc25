"""Runs: a scene stepped from Python, with callbacks between chunks of steps.

The steps run in C++ with the GIL released (other Python threads go on);
the callback, the progress bar and the stop test run between chunks of
`every` steps, with the GIL. A callback sees the state after a whole step,
exactly as the command line's run has it at that step: reading the state
never changes the result."""
import json
import math
import sys
import time as _time

from . import _polydem
from .errors import InstabilityError, PolydemError
from .scene import as_scene


class Progress:
    """A one-line progress bar on stderr: simulated time, steps per second,
    time left. At most five redraws a second."""

    def __init__(self, stream=None, width=30):
        self.stream = stream or sys.stderr
        self.width = width
        self.start = _time.monotonic()
        self.last = -1.0

    def __call__(self, run, final=False):
        now = _time.monotonic()
        if not final and now - self.last < 0.2:
            return
        self.last = now
        frac = min(1.0, run.time / run.end_time) if run.end_time > 0 else 1.0
        wall = now - self.start
        filled = int(round(self.width * frac))
        eta = wall * (1 - frac) / frac if frac > 0 else 0.0
        self.stream.write(f"\rt = {run.time:.4f} / {run.end_time:.4g} s [{'#' * filled}{'.' * (self.width - filled)}]"
                          f" {100 * frac:3.0f} %  {run.steps / max(wall, 1e-9):.0f} steps/s  ETA {eta:.0f} s ")
        if final:
            self.stream.write("\n")
        self.stream.flush()


def _progress(progress):
    if progress is None:
        progress = sys.stderr.isatty()
    if progress is True:
        return Progress()
    return progress or None


class Run:
    """One run of a scene (a Scene or a deck path).

    out: a directory for the outputs, the same as `polydem run --out`:
        snapshots during the run (when the deck asks), results.h5 and
        summary.json when it finishes. None: nothing is written.
    threads: OpenMP threads (0 or None: OMP_NUM_THREADS or every core);
        results do not depend on it.
    ground_acceleration: a load the deck cannot describe, added to the
        deck's ground motion as a body force −m·a(t) on every free block
        (its work is load work in the energy ledger): either an (n, 3)
        array of accelerations (m/s², world) at the times
        `ground_acceleration_time` (s, increasing; linear between samples,
        zero outside them), or a function of t returning 3 values, called
        once per step (with the GIL: slower).

    State arrays (positions, velocities, ...) are read-only numpy views of
    the run's own arrays: no copy, and they change in place as the run
    steps; they stay valid as long as the Run (they keep it alive). Take
    `.copy()` to keep a value."""

    def __init__(self, scene, out=None, threads=None, ground_acceleration=None, ground_acceleration_time=None):
        self.scene = as_scene(scene)
        self.stopped_by_callback = False
        self._r = _polydem.Run(self.scene.parsed(), "" if out is None else str(out), int(threads or 0),
                               ground_acceleration, ground_acceleration_time)

    # --------------------------------------------------------------- stepping
    def step(self, n=1):
        """Takes up to n steps (fewer at the end of the run); returns the
        number taken. Raises InstabilityError if the guard stops the run."""
        taken = self._r.advance(int(n))
        self._after_steps()
        return taken

    def run(self, until=None, callback=None, every=1000, progress=None):
        """Steps to the scene's end time, or to `until` (s) when given
        (then run() or step() may go on later). Every `every` steps
        callback(run) is called; returning False (any false value but None)
        stops the run there (it is
        not finished: call finish(), or run() again to go on). At the end
        time, or when the run collapses (assessment.stop_on_collapse) or
        settles, the run is finished (finish()). progress: True for a bar on
        stderr, False for none, None for a bar when stderr is a terminal, or
        a function of the run called every chunk. Returns self."""
        bar = _progress(progress)
        limit = math.inf if until is None else float(until)
        every = max(1, int(every))
        self.stopped_by_callback = False
        while not self._r.over and self._r.time < limit - 0.5 * self._r.dt:
            self._r.advance(every, limit)
            self._after_steps()
            if bar:
                bar(self)
            if callback is not None:
                go_on = callback(self)
                if go_on is not None and not go_on:  # False, or numpy's False_
                    self.stopped_by_callback = True
                    break
        if self._r.over:
            self.finish()
        if isinstance(bar, Progress):
            bar(self, final=True)
        return self

    def _after_steps(self):
        if self._r.unstable:
            self.finish()
            err = InstabilityError(self._r.instability)
            err.run = self
            raise err

    def finish(self):
        """Ends the run where it is: the report, and results.h5 and
        summary.json in `out`. Returns the summary (a dict, as summary.json)."""
        self._r.finish()
        return self.summary

    # ------------------------------------------------------------------ state
    over = property(lambda self: self._r.over, doc="at the end time, collapsed, settled or unstable")
    finished = property(lambda self: self._r.finished)
    time = property(lambda self: self._r.time, doc="simulated time (s)")
    end_time = property(lambda self: self._r.end_time)
    steps = property(lambda self: self._r.steps)
    dt = property(lambda self: self._r.dt, doc="the time step (s)")
    out = property(lambda self: self._r.out or None)
    threads = property(lambda self: self._r.threads)
    block_names = property(lambda self: self._r.block_names)
    masses = property(lambda self: self._r.masses, doc="kg, per block")
    free = property(lambda self: self._r.free, doc="True for the blocks the step integrates")
    positions = property(lambda self: self._r.positions, doc="(n, 3) centroids at t, m (view)")
    initial_positions = property(lambda self: self._r.initial_positions, doc="(n, 3) at t = 0 (view)")
    orientations = property(lambda self: self._r.orientations,
                            doc="(n, 4) unit quaternions body -> world at t, scalar last (x, y, z, w) (view)")
    rotations = property(lambda self: self._r.rotations, doc="(n, 3, 3) rotation matrices at t (view)")
    velocities = property(lambda self: self._r.velocities, doc="(n, 3) m/s at t - dt/2 (leapfrog; view)")
    angular_velocities = property(lambda self: self._r.angular_velocities, doc="(n, 3) rad/s at t - dt/2 (view)")
    contact_forces = property(lambda self: self._r.contact_forces, doc="(n, 3) sum of joint forces, N (view)")
    contact_torques = property(lambda self: self._r.contact_torques, doc="(n, 3) about the centroid, N m (view)")
    last_good_time = property(lambda self: self._r.last_good_time)

    @property
    def displacements(self):
        """(n, 3) positions minus the initial ones, m (a copy)."""
        return self._r.positions - self._r.initial_positions

    def block(self, name):
        """The index of the block called `name`."""
        try:
            return self._r.block_names.index(name)
        except ValueError:
            raise PolydemError(f"no block named {name!r}") from None

    def last_good_state(self):
        """The state at the guard's last passed check (every 256 steps):
        time, step, positions, orientations, velocities, angular_velocities (copies)."""
        return self._r.last_good_state()

    def energies(self):
        """The energy ledger now (J): kinetic, gravitational, strain, slip, damping, load_work, balance."""
        return self._r.energies()

    def ground_acceleration(self):
        """The ground acceleration applied now (m/s², world): the deck's and the caller's."""
        return self._r.ground_acceleration()

    def joint_openings(self):
        """The joints of the initial mesh (every pair touching at t = 0) and
        their opening now, m (> 0 open; a closed joint reads minus its
        overlap): dict of arrays block_a, block_b, bed, opening."""
        return self._r.joint_openings()

    def contacts(self):
        """Every subcontact now (copies: the contact arrays are rebuilt at
        each detection): reference_block, incident_block, point (n, 3),
        force on the incident block (n, 3), shear_force (n, 3), normal_force,
        overlap (m, > 0 closed), area (m²)."""
        return self._r.contacts()

    # ---------------------------------------------------------------- results
    @property
    def summary(self):
        """summary.json's content as a dict (the run must be finished)."""
        return json.loads(self._r.summary_text())

    @property
    def status(self):
        return self.summary["status"]

    @property
    def assessment(self):
        return self.summary["assessment"]

    @property
    def checks(self):
        return self.summary["checks"]

    @property
    def histories(self):
        """The deck's histories, {column: array} (column "time" first; units
        in history_units), as results.h5 holds them."""
        return self._r.histories()[0]

    @property
    def history_units(self):
        return self._r.histories()[1]

    @property
    def energy_histories(self):
        return self._r.energy_histories()[0]

    def __repr__(self):
        return (f"<polydem.Run {self.scene.name!r} t = {self.time:.6g} s, {self.steps} steps"
                f"{', finished' if self.finished else ''}>")


def run(scene, end_time=None, out=None, threads=None, callback=None, every=1000, progress=None, set=None,
        ground_acceleration=None, ground_acceleration_time=None):
    """Runs a scene (a Scene or a deck path) to its end and returns the
    finished Run. end_time and set ({key: value}) are overrides of the deck,
    as `polydem run --set simulation.end_time=...`. The other arguments are
    Run's and Run.run's."""
    scene = as_scene(scene)
    extra = dict(set or {})
    if end_time is not None:
        extra["simulation.end_time"] = float(end_time)
    if extra:
        scene = scene.with_set(extra)
    r = Run(scene, out=out, threads=threads, ground_acceleration=ground_acceleration,
            ground_acceleration_time=ground_acceleration_time)
    r.run(callback=callback, every=every, progress=progress)
    if not r.finished:
        r.finish()
    return r
