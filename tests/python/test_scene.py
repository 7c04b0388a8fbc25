"""Scenes: decks, overrides, scenes built in Python, and the errors that name the key."""
import random
import struct

import numpy as np
import polydem
import pytest
from conftest import deck


def test_deck_with_overrides():
    s = polydem.Scene.from_deck(deck("examples/verification/rocking_onset.toml"), set={"simulation.end_time": 0.25})
    assert s.end_time == 0.25
    assert s.block_names == ["base", "pillar"]
    assert s.with_set({"simulation.end_time": 0.5}).end_time == 0.5
    assert s.end_time == 0.25  # with_set made a copy


def test_deck_error_names_file_line_and_key(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text('[simulation]\nend_time = 1\n\n[[block]]\nshape = "box"\nsize = [1, 1, 1]\ndensity = -5\n')
    with pytest.raises(polydem.DeckError) as e:
        polydem.Scene.from_deck(path)
    assert (e.value.file, e.value.line, e.value.key) == (str(path), 7, "block[1].density")
    assert "must be > 0" in str(e.value)


def test_override_error_names_the_override():
    with pytest.raises(polydem.DeckError) as e:
        polydem.Scene.from_deck(deck("examples/verification/rocking_onset.toml"), set={"joint.friction_angle": 95})
    assert e.value.key == "joint.friction_angle" and "--set" in str(e.value) and e.value.line == 0


def test_builder_unknown_key_raises_at_once():
    with pytest.raises(polydem.DeckError) as e:
        polydem.Scene().joint(frction_angle=30)
    assert e.value.key == "joint.frction_angle"
    with pytest.raises(polydem.DeckError) as e:
        polydem.Scene().add_box("a", size=(1, 1, 1), colour="red")
    assert e.value.key == "block[1].colour"


def test_builder_bad_value_names_the_block_key():
    s = polydem.Scene(end_time=0.1).add_box("base", (2, 2, 0.5), (0, 0, -0.25), motion="fixed")
    s.add_box("stone", (1, 1, 1), (0, 0, 0.5), density=-1.0)
    with pytest.raises(polydem.DeckError) as e:
        s.parsed()
    assert e.value.key == "block[2].density" and e.value.file == "<python scene>"


def test_floats_round_trip_through_the_deck_text():
    rng = random.Random(14)
    base = polydem.Scene().add_box("b", (1, 1, 1), motion="fixed")
    for _ in range(200):
        x = struct.unpack("d", struct.pack("Q", rng.getrandbits(62)))[0]  # positive, any exponent
        if not (x > 0) or x == float("inf"):
            continue
        assert base.with_set({"simulation.end_time": x}).end_time == x  # the override's text
        v = rng.uniform(-10, 10)
        assert polydem.Scene(end_time=x).add_box("b", (1, 1, 1), (v, 0, 0), motion="fixed").end_time == x


def test_python_scene_shapes_and_spire():
    v = np.array([[-0.5, -0.5, 1.0], [0.5, -0.5, 1.0], [0.5, 0.5, 1.0], [-0.5, 0.5, 1.0], [0.0, 0.0, 1.6]])
    s = (polydem.Scene(end_time=0.01)
         .add_box("base", size=(3, 3, 0.5), center=(0, 0, -0.25), motion="fixed")
         .add_prism("stone", polygon=[[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]], z=(0, 1))
         .add_hull("cap", vertices=v, density=2400.0))
    assert s.block_names == ["base", "stone", "cap"]
    assert "[[block]]" in s.deck_text
    spire = polydem.Scene(end_time=0.01).spire(stones_per_face=1, window_faces=[])
    names = spire.block_names
    assert names[0] == "base" and names[-1] == "tip" and len(names) > 40


def test_hull_needs_n_by_3():
    with pytest.raises(polydem.DeckError) as e:
        polydem.Scene().add_hull("x", np.zeros((4, 2)))
    assert e.value.key == "block[1].vertices"


def test_overlapping_blocks_are_a_scene_error():
    s = (polydem.Scene(end_time=0.01).add_box("a", (1, 1, 1), (0, 0, 0), motion="fixed")
         .add_box("b", (1, 1, 1), (0, 0, 0.5)))
    with pytest.raises(polydem.SceneError) as e:
        polydem.Run(s)
    assert e.value.key == "block"


def test_saved_scene_reads_back_the_same(tmp_path):
    s = polydem.Scene(end_time=0.5).joint(friction_angle=35.0).add_box("b", (1, 2, 3), motion="fixed")
    path = s.save(tmp_path / "scene.toml")
    assert polydem.Scene.from_deck(path).deck_text == s.deck_text


def test_cut_and_import_from_python(tmp_path):
    # A pier cut into three drums, then the same drums from an OBJ file.
    s = (polydem.Scene(end_time=0.01)
         .add_box("base", (2, 2, 0.5), (0, 0, -0.25), motion="fixed")
         .add_box("pier", (0.5, 0.5, 1.5), (0, 0, 0.75))
         .add_cut(0, origin=(0, 0, 0.5), spacing=0.5, count=2))
    assert s.block_names == ["base", "pier_cut1", "pier_cut2", "pier_cut3"]
    with pytest.raises(polydem.DeckError) as e:
        polydem.Scene().add_cut(0, spacingg=1)
    assert e.value.key == "cut[1].spacingg"
    obj = tmp_path / "drums.obj"
    lines, first = [], 1
    for k in range(3):
        lines.append(f"o drum{k}")
        for z in (0.5 * k, 0.5 * (k + 1)):
            for x, y in ((-0.25, -0.25), (0.25, -0.25), (0.25, 0.25), (-0.25, 0.25)):
                lines.append(f"v {x} {y} {z}")
        for f in ((3, 2, 1, 0), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)):
            lines.append("f " + " ".join(str(first + i) for i in f))
        first += 8
    obj.write_text("\n".join(lines) + "\n")
    imported = polydem.Scene(end_time=0.01).add_import(obj, density=2000.0)
    assert imported.block_names == ["drum0", "drum1", "drum2"]
