"""The same scene from Python and from `polydem run` gives the same bits:
summary.json (timing fields aside) and every dataset of results.h5. The
Python runs read the state in a callback and stop and go on part way: none
of that may change a bit."""
import os

import numpy as np
import polydem
import pytest
from compare_outputs import differences
from conftest import deck, polydem_cli


def cli(tmp_path, name, deck_path, *sets, threads=2):
    out = tmp_path / f"cli_{name}"
    args = ["run", deck_path, "--out", out, "--threads", threads, "--quiet"]
    for s in sets:
        args += ["--set", s]
    p = polydem_cli(*args)
    assert p.returncode in (0, 1), p.stderr
    return out


def reader(every_seen):
    def look(run):  # reads everything a script would
        every_seen.append((run.positions.sum(), run.contact_forces.sum(), len(run.contacts()["force"]),
                           run.joint_openings()["opening"].sum(), run.energies()["balance"]))
    return look


# The spire on 1 and 2 threads (its parallel path: more than 2048
# subcontacts); a 2-thread Python process once differed from the command
# line, depending on its environment (docs/python.md, "Determinism").
@pytest.mark.parametrize("name,path,end_time,threads", [
    ("rocking", "examples/verification/rocking_onset.toml", 0.6, 2),
    ("spire", "examples/spire/earthquake.toml", 0.03, 1),  # record, tower filter, walking, histories
    ("spire2", "examples/spire/earthquake.toml", 0.03, 2),
])
def test_deck_from_python_and_command_line(tmp_path, name, path, end_time, threads):
    a = cli(tmp_path, name, deck(path), f"simulation.end_time={end_time!r}", threads=threads)
    seen = []
    scene = polydem.Scene.from_deck(deck(path))
    run = polydem.Run(scene.with_set({"simulation.end_time": end_time}), out=tmp_path / f"py_{name}",
                      threads=threads)
    run.run(until=end_time / 3, callback=reader(seen), every=97, progress=False)  # stop part way ...
    run.step(5)
    run.run(callback=reader(seen), every=101, progress=False)                       # ... and go on
    assert run.finished and len(seen) > 2
    assert differences(a, tmp_path / f"py_{name}") == []


def test_python_scene_from_python_and_command_line(tmp_path):
    v = np.array([[-0.25, -0.25, 2.0], [0.25, -0.25, 2.0], [0.25, 0.25, 2.0], [-0.25, 0.25, 2.0], [0.0, 0.1, 2.4]])
    scene = (polydem.Scene(end_time=0.4)
             .joint(friction_angle=35.0, damping=2.1e-5)
             .add_box("base", size=(2, 2, 0.5), center=(0, 0, -0.25), motion="fixed")
             .add_prism("pillar", polygon=[[-0.25, -0.25], [0.25, -0.25], [0.25, 0.25], [-0.25, 0.25]], z=(0, 2))
             .add_hull("cap", v, density=2400.0)
             .ground_motion(kind="sine_pulse", acceleration_g=0.35, period=0.3, direction=[1.0, 0.5, 0.0])
             .output(history_interval=0.01, histories=["cap.position", "pillar.rotation"]))
    path = scene.save(tmp_path / "scene.toml")
    a = cli(tmp_path, "scene", path)
    seen = []
    run = polydem.Run(polydem.Scene.from_deck(path), out=tmp_path / "py", threads=2)
    run.run(callback=reader(seen), every=333, progress=False)
    assert differences(a, tmp_path / "py") == []
    # The scene built in Python (not read back from the file) gives the same bits too.
    b = polydem.run(scene, threads=2, progress=False)
    assert np.array_equal(b.positions, run.positions) and b.summary["steps"] == run.summary["steps"]


# Verification 14 from the command line: the wall cut from one box and the
# same wall imported from imported_wall.obj write the same summary.json and
# results.h5, bit for bit, but for the deck's own path and text.
def test_imported_wall_writes_the_cut_walls_results(tmp_path):
    a = cli(tmp_path, "cut", deck("examples/verification/cut_wall.toml"), "simulation.end_time=0.05")
    b = cli(tmp_path, "imported", deck("examples/verification/imported_wall.toml"), "simulation.end_time=0.05")
    assert differences(a, b) == ["summary.json /deck: {!r} != {!r}".format(deck("examples/verification/cut_wall.toml"),
                                                                           deck("examples/verification/imported_wall.toml")),
                                 "results.h5 deck: differs", "results.h5 deck@path: differs"]
