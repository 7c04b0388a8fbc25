"""polydem from Python: scenes, runs, studies and the analytical models with
numpy (docs/python.md).

    import polydem
    scene = polydem.Scene.from_deck("examples/verification/rocking_onset.toml")
    run = polydem.run(scene, end_time=1.0, out="out/rocking")
    print(run.status, run.positions[run.block("pillar")])
    print(polydem.analytical.limit_lp(scene)["cases"][0]["inscribed"]["lambda"])

Built by scripts/build.sh into build/python; use it with
PYTHONPATH=build/python and Debian's /usr/bin/python3."""
from . import _polydem, analytical
from .errors import DeckError, GeometryError, InstabilityError, PolydemError, SceneError
from .run import Progress, Run, run
from .scene import Scene
from .studies import CollapseResult, EnsembleResult, IdaResult, SweepResult, collapse_search, ensemble, ida, sweep

__version__ = _polydem.version
deck_keys = _polydem.deck_keys

__all__ = ["analytical", "Scene", "Run", "run", "collapse_search", "sweep", "ensemble", "ida", "CollapseResult", "SweepResult",
           "EnsembleResult", "IdaResult", "Progress",
           "PolydemError", "DeckError", "SceneError", "GeometryError", "InstabilityError", "deck_keys"]
