# The README's Python in ten lines: run the rocking-onset deck until the
# pillar has moved 5 mm. From the repository: PYTHONPATH=build/python /usr/bin/python3 examples/python/ten_lines.py
import polydem

scene = polydem.Scene.from_deck("examples/verification/rocking_onset.toml")
run = polydem.Run(scene, out="out/python_rocking", threads=1)
pillar = run.block("pillar")
upright = lambda r: abs(r.displacements[pillar, 0]) < 0.005   # go on until the pillar has moved 5 mm
run.run(callback=upright, every=100, progress=False)
print(f"stopped at t = {run.time:.3f} s, a_g = {run.ground_acceleration()[0] / 9.81:.4f} g")
print("pillar centroid (m):", run.positions[pillar].round(4))
print(run.finish()["checks"][0]["name"], run.checks[0]["measured"], run.checks[0]["passed"])
