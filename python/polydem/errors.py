"""The exceptions polydem raises (docs/python.md, "Errors").

Every message is the command line's: a deck error names the file (or the
scene's name), the line when the value came from the deck text, and the key:

    examples/x.toml:12: key 'block[2].density': must be > 0 (got -5)
    <python scene>: --set key 'joint.friction_angle': must be in [0, 90) (got 95)

and the exception carries them apart as `file`, `line` (0 when none) and
`key` ("" when the message names none)."""
import re

_LOCATION = re.compile(r"^(?:(?P<file>.*?)(?::(?P<line>\d+))?: )?(?:--set )?key '(?P<key>[^']*)'", re.S)


class PolydemError(Exception):
    """Base of every polydem error."""


class DeckError(PolydemError, ValueError):
    """A deck, a scene built in Python or an override that is not valid."""

    def __init__(self, message):
        super().__init__(message)
        m = _LOCATION.match(str(message))
        self.file = (m.group("file") or "") if m else ""
        self.line = int(m.group("line")) if m and m.group("line") else 0
        self.key = m.group("key") if m else ""


class SceneError(DeckError):
    """Input found bad only when the scene is set up: blocks overlapping at
    the start, a time step above the critical one, a check that does not fit
    the scene. Located in the deck like a DeckError."""


class GeometryError(PolydemError, ValueError):
    """A block's shape is not a valid convex polyhedron."""


class InstabilityError(PolydemError, ArithmeticError):
    """The guard stopped the run (a non-finite state, blocks passing through
    each other, energy from nowhere). The message names the cause, the step
    and the time; `run` is the Run, finished, with the last good state
    (`run.last_good_state()`) and its outputs written if it had a directory."""

    run = None
