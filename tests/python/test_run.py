"""Runs from Python: stepping, callbacks, numpy views, loads, instability, outputs."""
import json
import os
import threading

import numpy as np
import polydem
import pytest


def pillar(end_time=0.2, friction_angle=30.0):
    """A 0.5 x 0.5 x 2 m pillar on a fixed base (examples/verification/rocking_onset.toml's blocks)."""
    return (polydem.Scene(end_time=end_time)
            .joint(normal_stiffness=98e9, friction_angle=friction_angle, damping=2.1e-5)
            .add_box("base", size=(2, 2, 0.5), center=(0, 0, -0.25), motion="fixed")
            .add_box("pillar", size=(0.5, 0.5, 2), center=(0, 0, 1), density=2600.0))


def test_step_and_views():
    run = polydem.Run(pillar())
    pos = run.positions
    assert pos.shape == (2, 3) and not pos.flags.writeable
    before = pos.copy()
    assert run.step(100) == 100 and run.steps == 100
    assert run.time == pytest.approx(100 * run.dt, rel=1e-12)
    # A view: the same memory, changed in place by the steps.
    assert np.shares_memory(pos, run.positions)
    assert pos[1, 2] != before[1, 2]
    q = run.orientations
    assert q.shape == (2, 4) and np.allclose(np.linalg.norm(q, axis=1), 1.0)
    R = run.rotations[1]
    x, y, z, w = q[1]
    assert R[0, 1] == pytest.approx(2 * (x * y - z * w), abs=1e-14)  # column-major read right
    assert run.velocities.shape == run.contact_forces.shape == (2, 3)
    c = run.contacts()
    assert len(c["normal_force"]) == 4 and c["point"].shape == (4, 3)  # the pillar's four corners
    j = run.joint_openings()
    assert list(j["block_a"]) == [0] and list(j["block_b"]) == [1] and j["bed"][0]
    assert abs(j["opening"][0]) < 1e-5


def test_settled_weight_and_finish(tmp_path):
    run = polydem.run(pillar(end_time=0.05), out=tmp_path / "out", threads=1, progress=False)
    assert run.finished and run.status == "intact"
    m = run.masses[run.block("pillar")]
    assert run.contact_forces[1, 2] == pytest.approx(m * 9.81, rel=1e-3)
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["steps"] == run.steps == run.summary["steps"]
    assert os.path.exists(tmp_path / "out" / "results.h5")
    assert set(run.energy_histories) >= {"time", "kinetic", "numerical"}


def test_callback_reads_state_and_stops_the_run():
    seen = []

    def stop_when_tilted(r):
        seen.append(r.time)
        return r.time < 0.02  # a custom stopping rule

    run = polydem.Run(pillar(end_time=1.0))
    run.run(callback=stop_when_tilted, every=50, progress=False)
    assert run.stopped_by_callback and not run.finished
    assert 0.02 <= run.time < 0.02 + 51 * run.dt
    assert len(seen) >= 2 and all(b > a for a, b in zip(seen, seen[1:]))
    s = run.finish()
    assert s["end_time_s"] == run.time and s["steps"] == run.steps


def test_vertical_ground_acceleration_table_halves_the_weight():
    # The ground accelerating downwards at g/2: the pillar weighs half.
    g = 9.81
    t = np.array([0.0, 10.0])
    a = np.array([[0.0, 0.0, -g / 2], [0.0, 0.0, -g / 2]])
    run = polydem.run(pillar(end_time=0.05), ground_acceleration=a, ground_acceleration_time=t, progress=False)
    m = run.masses[1]
    assert run.contact_forces[1, 2] == pytest.approx(m * g / 2, rel=2e-3)
    assert run.ground_acceleration() == pytest.approx([0, 0, -g / 2])


def test_no_settling_before_the_callers_ground_acceleration_is_final():
    # A pillar at rest under a horizontal table rising to 0.1 g over 0.3 s
    # (b/h = 0.25: it stands; the table is zero after its last sample) is
    # nearly still long before the table ends: it may settle only after the
    # last sample plus settle_time, as with the deck's loads.
    scene = pillar(end_time=1.0).with_set({"simulation.settle_velocity": 1e-3, "simulation.settle_time": 0.02})
    t = np.array([0.0, 0.3])
    a = np.array([[0.0, 0.0, 0.0], [0.981, 0.0, 0.0]])
    run = polydem.run(scene, ground_acceleration=a, ground_acceleration_time=t, progress=False)
    assert run._r.settled
    assert 0.32 <= run.time < 0.5
    # A function of time may change at any moment: the run goes to its end.
    run = polydem.run(scene.with_set({"simulation.end_time": 0.1}), ground_acceleration=lambda t: (0.0, 0.0, 0.0),
                      progress=False)
    assert not run._r.settled and run.time == pytest.approx(0.1, abs=2 * run.dt)


def test_ground_acceleration_function_and_instability():
    # A load that becomes NaN: the guard stops the run, names the cause, keeps the last good state.
    def load(t):
        return (0.0, 0.0, float("nan") if t > 0.01 else 0.0)

    run = polydem.Run(pillar(end_time=0.1), ground_acceleration=load)
    with pytest.raises(polydem.InstabilityError) as e:
        run.run(progress=False)
    assert "non-finite" in str(e.value) or "NaN" in str(e.value) or "nan" in str(e.value)
    assert e.value.run is run and run.finished and run.status == "unstable"
    good = run.last_good_state()
    assert good["time"] <= 0.01 + run.dt and np.all(np.isfinite(good["positions"]))


def test_gil_released_during_a_run():
    count = [0]
    done = threading.Event()

    def spin():
        while not done.is_set():
            count[0] += 1

    run = polydem.Run(pillar(end_time=1.0))
    t = threading.Thread(target=spin)
    t.start()
    try:
        before = count[0]
        run.run(every=10 ** 9, progress=False)  # one chunk: no return to Python until the end
        during = count[0] - before
    finally:
        done.set()
        t.join()
    # Had advance() kept the GIL, the spinning thread would not have run.
    assert run.finished and during > 10000


def test_energies_are_the_whole_ledger():
    """Every ledger line is there and they sum to the balance (to round-off)."""
    run = polydem.Run(pillar(end_time=0.05), threads=1)
    run.run(progress=False)
    e = run.energies()
    terms = ("kinetic", "gravitational", "strain", "slip", "damping")
    total = sum(e[k] for k in terms) - e["load_work"]
    assert total == pytest.approx(e["balance"], abs=1e-9 * (1.0 + sum(abs(e[k]) for k in terms)))


def test_split_damping_contacts_hold_the_whole_joint_force():
    # Under simulation.damping_scheme = "split" the blocks feel the law's
    # forces and the rest of the dashpots; each subcontact's recorded force
    # is both, so the pillar's subcontacts sum to its contact force. A stiff
    # dashpot and an impact make the rest a large part of it.
    scene = (polydem.Scene(end_time=0.05, damping_scheme="split")
             .joint(normal_stiffness=98e9, friction_angle=30.0, damping=1e-4)
             .add_box("base", size=(2, 2, 0.5), center=(0, 0, -0.25), motion="fixed")
             .add_box("pillar", size=(0.5, 0.5, 2), center=(0, 0, 1), density=2600.0, velocity=(0, 0, -0.05)))
    run = polydem.Run(scene)
    p = run.block("pillar")
    weight = run.masses[p] * 9.81
    while run.steps < 100 and run.contact_forces[p, 2] < 5 * weight:  # into the impact
        run.step(1)
    c = run.contacts()
    total = np.zeros(3)
    for k in range(len(c["normal_force"])):
        if c["incident_block"][k] == p:
            total += c["force"][k]
        elif c["reference_block"][k] == p:
            total -= c["force"][k]
    assert run.contact_forces[p, 2] > 5 * weight  # the impact: the dashpots at work
    assert np.allclose(total, run.contact_forces[p], rtol=1e-9, atol=1e-9 * weight)


def test_numerical_at_detections_is_the_shear_a_detection_drops():
    """A stone sliding past its base's edge on soft shear springs: as its
    joint is clipped smaller, the area lost takes its shear strain with it.
    That is nearly the whole numerical line, and energies() and
    summary.json say so alike."""
    scene = (polydem.Scene(end_time=1.0)
             .joint(normal_stiffness=1e9, shear_stiffness=2.5e5, friction_angle=30.0)
             .add_box("base", size=(2, 2, 0.5), center=(-0.5, 0, -0.25), motion="fixed")
             .add_box("stone", size=(1, 1, 0.5), center=(0, 0, 0.25), density=2600.0, velocity=(1.5, 0, 0)))
    run = polydem.Run(scene, threads=1)
    start = run.energies()["balance"]
    run.run(progress=False)
    e = run.energies()
    numerical = e["balance"] - start
    assert e["numerical_at_detections"] < -20.0  # J: the premise, shear dropped
    assert abs(numerical - e["numerical_at_detections"]) < 0.02 * abs(numerical)
    summary = run.finish()
    assert summary["energy"]["numerical_at_detections_J"] == e["numerical_at_detections"]
