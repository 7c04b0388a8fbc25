"""Scenes: a deck file or text, or one built in Python with the deck's names.

A Scene built in Python is written as deck text (TOML) and read by the same
reader as a deck file, so it is validated the same way, its errors name the
same keys, it runs with the same bits as `polydem run` on that text, and
`scene.save(path)` gives a deck the command line runs."""
import copy
import json
import math
import os

import numpy as np

from . import _polydem
from .errors import DeckError

_SECTIONS = ("simulation", "joint", "equilibrium", "spire", "ground_motion", "output", "assessment")
_KEYS = None


def _known_keys():
    global _KEYS
    if _KEYS is None:
        _KEYS = {}
        for k in _polydem.deck_keys():
            section, _, key = k.partition(".")
            _KEYS.setdefault(section, set()).add(key)
    return _KEYS


def toml_value(value, key="value"):
    """A Python value as TOML text: floats in their shortest round-trip form
    (the deck reader reads back the same double), numpy arrays as arrays."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, (str, os.PathLike)):
        return json.dumps(os.fspath(value))  # a TOML basic string
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v, key) for v in value) + "]"
    raise DeckError(f"{_Builder.NAME}: key '{key}': cannot be written to a deck ({type(value).__name__})")


def overrides_list(overrides):
    """{key: value} (or "key=value" strings) as the deck reader's --set strings."""
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        return [f"{k}={toml_value(v, k)}" for k, v in overrides.items()]
    return [str(o) for o in overrides]


class _Builder:
    NAME = "<python scene>"


class Scene:
    """A scene to run: a deck file (`Scene.from_deck`), deck text
    (`Scene.from_text`), the built-in default deck (`Scene.default`), or
    built here: `Scene(end_time=2.0).joint(friction_angle=35).add_box(...)`.

    Keyword arguments of the builder methods are the deck's keys of that
    section, in the deck's units (docs/deck.md); a key the deck does not
    have raises DeckError at once, a bad value when the scene is read
    (`parsed()`, or when it runs)."""

    def __init__(self, **simulation):
        self._tables = {}   # section -> {key: value}, single tables
        self._blocks = []   # [[block]] tables
        self._checks = []   # [[check]] tables
        self._imports = []  # [[import]] tables
        self._cuts = []     # [[cut]] tables
        self._text = None   # deck text (from_deck / from_text)
        self._name = _Builder.NAME
        self._from_file = False
        self._overrides = []
        self._parsed = None
        if simulation:
            self.simulation(**simulation)

    # ----------------------------------------------------------- from decks
    @classmethod
    def from_deck(cls, path, set=None):
        """The deck file at `path`, with overrides `set` ({key: value}, as
        `--set key=value`). Relative record paths are relative to the deck."""
        s = cls()
        s._name = os.fspath(path)
        s._from_file = True
        s._overrides = overrides_list(set)
        s._parsed = _polydem.read_deck(s._name, s._overrides)
        s._text = s._parsed.deck_text
        return s

    @classmethod
    def from_text(cls, text, name="<deck text>", set=None):
        """Deck text; `name` names it in messages (relative record paths are
        relative to its directory, the current one by default)."""
        s = cls()
        s._text = text
        s._name = name
        s._overrides = overrides_list(set)
        s.parsed()
        return s

    @classmethod
    def default(cls, set=None):
        """The built-in default deck (`polydem run --default`): the spire
        under a ground acceleration rising at 0.1 g/s."""
        return cls.from_text(_polydem.default_deck_text(), _polydem.default_deck_name, set)

    def with_set(self, overrides):
        """A copy with more overrides ({key: value}), applied after the
        earlier ones, as further `--set`s."""
        s = copy.copy(self)
        s._tables = copy.deepcopy(self._tables)
        s._blocks = copy.deepcopy(self._blocks)
        s._checks = copy.deepcopy(self._checks)
        s._imports = copy.deepcopy(self._imports)
        s._cuts = copy.deepcopy(self._cuts)
        s._overrides = self._overrides + overrides_list(overrides)
        s._parsed = None
        if self._from_file:  # keep read_deck's deck_path and record directory
            s._parsed = _polydem.read_deck(s._name, s._overrides)
        return s

    # ------------------------------------------------------------- building
    def _table(self, section, kwargs):
        self._edit()
        known = _known_keys().get(section, set())
        for k in kwargs:
            if k not in known:
                raise DeckError(f"{self._name}: key '{section}.{k}': unknown key "
                                f"({section} accepts: {', '.join(sorted(known))})")
        table = self._tables.setdefault(section, {})
        table.update(kwargs)
        return self

    def _edit(self):
        if self._text is not None:
            raise DeckError(f"{self._name}: a scene read from a deck is changed with with_set(), not built on")
        self._parsed = None

    def simulation(self, **kw):
        """[simulation]: end_time, time_step, gravity, contact_margin, ..."""
        return self._table("simulation", kw)

    def joint(self, **kw):
        """[joint]: normal_stiffness, shear_stiffness, friction_angle (deg), cohesion, ..."""
        return self._table("joint", kw)

    def equilibrium(self, **kw):
        """[equilibrium]: brings the scene to rest under its weight first."""
        return self._table("equilibrium", kw)

    def spire(self, **kw):
        """[spire]: the octagonal masonry spire, generated stone by stone."""
        return self._table("spire", kw)

    def ground_motion(self, **kw):
        """[ground_motion]: kind, applied_as, direction, acceleration(_g), rate(_g),
        period, record, scale, tower_frequency, ... A relative `record` path is
        taken from the current directory."""
        if "record" in kw:
            kw = dict(kw, record=os.path.abspath(os.fspath(kw["record"])))
        return self._table("ground_motion", kw)

    def output(self, **kw):
        """[output]: history_interval, histories, energies, walking, snapshot_interval, ..."""
        return self._table("output", kw)

    def assessment(self, **kw):
        """[assessment]: damage_displacement, collapse_displacement, stop_on_collapse, ..."""
        return self._table("assessment", kw)

    def add_block(self, name=None, **kw):
        """A [[block]] with any of its keys (shape = "box" | "prism" | "hull")."""
        self._edit()
        known = _known_keys()["block"]
        index = len(self._blocks) + 1
        for k in kw:
            if k not in known:
                raise DeckError(f"{self._name}: key 'block[{index}].{k}': unknown key "
                                f"(block accepts: {', '.join(sorted(known))})")
        table = {"name": name} if name is not None else {}
        table.update(kw)
        self._blocks.append(table)
        return self

    def add_box(self, name, size, center=(0.0, 0.0, 0.0), **kw):
        """A box of full edge lengths `size` (m) centred at `center`."""
        return self.add_block(name, shape="box", size=size, center=center, **kw)

    def add_prism(self, name, polygon, z, **kw):
        """A right prism: a convex polygon (n×2, m) in the xy-plane from z[0] to z[1]."""
        return self.add_block(name, shape="prism", polygon=polygon, z=z, **kw)

    def add_hull(self, name, vertices, **kw):
        """The convex hull of `vertices` (n×3 array, m): every point must be
        a corner of the hull (as the deck's shape = "hull")."""
        v = np.asarray(vertices, dtype=float)
        if v.ndim != 2 or v.shape[1] != 3:
            raise DeckError(f"{self._name}: key 'block[{len(self._blocks) + 1}].vertices': "
                            f"must be an array of shape (n, 3) (got {v.shape})")
        return self.add_block(name, shape="hull", vertices=v, **kw)

    def _array_table(self, section, tables, kw):
        self._edit()
        known = _known_keys()[section]
        for k in kw:
            if k not in known:
                raise DeckError(f"{self._name}: key '{section}[{len(tables) + 1}].{k}': unknown key "
                                f"({section} accepts: {', '.join(sorted(known))})")
        tables.append(dict(kw))
        return self

    def add_import(self, file, **kw):
        """An [[import]]: blocks from an .obj, .ply or .vtu file (scale,
        rotation, offset, density, motion, fixed_below, fixed, group,
        name_prefix). A relative `file` is taken from the current directory."""
        return self._array_table("import", self._imports, dict(kw, file=os.path.abspath(os.fspath(file))))

    def add_cut(self, dip, **kw):
        """A [[cut]]: a joint set (dip, dip_direction, origin, spacing, count)
        cutting the blocks selected by `blocks` and/or `groups` (every free
        block by default), after every block is made, in the order added."""
        return self._array_table("cut", self._cuts, dict(kw, dip=dip))

    def check(self, kind, **kw):
        """A [[check]]: a verification check evaluated after the run."""
        self._edit()
        self._checks.append(dict(kind=kind, **kw))
        return self

    # -------------------------------------------------------------- reading
    @property
    def name(self):
        return self._name

    @property
    def overrides(self):
        return list(self._overrides)

    @property
    def deck_text(self):
        """The deck text: the file's or the one written from the builder."""
        if self._text is not None:
            return self._text
        lines = [f"# written by polydem's Python module ({_Builder.NAME})"]

        def table(header, entries):
            lines.append("")
            lines.append(header)
            for k, v in entries.items():
                lines.append(f"{k} = {toml_value(v, k)}")

        for section in ("simulation", "joint", "equilibrium"):
            if section in self._tables:
                table(f"[{section}]", self._tables[section])
        for b in self._blocks:
            table("[[block]]", b)
        for t in self._imports:
            table("[[import]]", t)
        for t in self._cuts:
            table("[[cut]]", t)
        for section in ("spire", "ground_motion", "output", "assessment"):
            if section in self._tables:
                table(f"[{section}]", self._tables[section])
        for c in self._checks:
            table("[[check]]", c)
        return "\n".join(lines) + "\n"

    def parsed(self):
        """The scene read and validated (raises DeckError naming the key)."""
        if self._parsed is None:
            self._parsed = _polydem.parse_deck(self.deck_text, self._name, self._overrides)
        return self._parsed

    def validate(self):
        """Reads the scene now; returns it (raises DeckError or GeometryError)."""
        self.parsed()
        return self

    @property
    def block_names(self):
        return self.parsed().block_names

    @property
    def end_time(self):
        return self.parsed().end_time

    @property
    def warnings(self):
        return self.parsed().warnings

    def save(self, path):
        """Writes the deck text to `path` (`polydem run PATH` runs it; give
        the overrides as --set)."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.deck_text)
        return path

    def __repr__(self):
        n = len(self._parsed.block_names) if self._parsed is not None else "?"
        return f"<polydem.Scene {self._name!r}, {n} blocks>"


def as_scene(scene):
    """A Scene, or a deck path made into one."""
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, (str, os.PathLike)):
        return Scene.from_deck(scene)
    raise TypeError(f"expected a polydem.Scene or a deck path, got {type(scene).__name__}")
