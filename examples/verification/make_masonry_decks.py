#!/usr/bin/env python3
"""Writes the masonry verification decks (verification 8): a stack of ten
stones and a dry-stone wall of 5 courses in running bond (55 stones).
Run from this folder: python3 make_masonry_decks.py"""

HEADER = """[simulation]
end_time = 10.0

[joint]
normal_stiffness = 98e9
friction_angle = 30.0
damping = 2.1e-5
"""


def box(name, size, center, motion="free"):
    s = f'[[block]]\nname = "{name}"\nshape = "box"\n'
    s += f"size = [{size[0]:.6g}, {size[1]:.6g}, {size[2]:.6g}]\n"
    s += f"center = [{center[0]:.6g}, {center[1]:.6g}, {center[2]:.6g}]\n"
    s += f'motion = "{motion}"\n' if motion != "free" else "density = 2600.0\n"
    return s + "\n"


def stack():
    out = ["# Verification 8a: a stack of ten stones settles under gravity and stays put for 10 s.\n"
           "# Stones 0.5 x 0.4 x 0.3 m on a fixed base; the top stone must not move more than 0.1 mm.\n\n",
           HEADER, "\n", box("base", (2, 2, 0.5), (0, 0, -0.25), "fixed")]
    for k in range(10):
        out.append(box(f"stone{k + 1}", (0.5, 0.4, 0.3), (0, 0, 0.15 + 0.3 * k)))
    out.append('[output]\nhistory_interval = 0.05\nhistories = ["stone10.position"]\n\n')
    out.append('[[check]]\nkind = "no_drift"\nblock = "stone10"\ntolerance = 1e-4\n\n')
    out.append('[[check]]\nkind = "energy_no_growth"\ntolerance = 1e-3\n')
    open("stack_of_ten.toml", "w").write("".join(out))


def wall():
    length, unit, height, depth, courses = 3.0, 0.3, 0.2, 0.3, 5
    out = ["# Verification 8b: a dry-stone wall of 5 courses in running bond settles and stays put for 10 s.\n"
           "# Stones 0.3 x 0.3 x 0.2 m, alternate courses offset by half a stone (half stones at the ends).\n"
           "# The stones at the top corners must not move more than 0.1 mm.\n\n",
           HEADER, "\n", box("base", (4, 1, 0.5), (0, 0, -0.25), "fixed")]
    n = 0
    names = []
    for c in range(courses):
        z = height * (c + 0.5)
        x = -length / 2
        pieces = [unit] * 10 if c % 2 == 0 else [unit / 2] + [unit] * 9 + [unit / 2]
        for w in pieces:
            n += 1
            name = f"c{c + 1}s{n}"
            out.append(box(name, (w, depth, height), (x + w / 2, 0, z)))
            names.append(name)
            x += w
    out.append(f'[output]\nhistory_interval = 0.05\nhistories = ["{names[-1]}.position"]\n\n')
    out.append(f'[[check]]\nkind = "no_drift"\nblock = "{names[-1]}"\ntolerance = 1e-4\n\n')
    out.append(f'[[check]]\nkind = "no_drift"\nblock = "{names[-10]}"\ntolerance = 1e-4\n\n')
    out.append('[[check]]\nkind = "energy_no_growth"\ntolerance = 1e-3\n')
    open("dry_stone_wall.toml", "w").write("".join(out))
    return n


if __name__ == "__main__":
    stack()
    print("wall stones:", wall())
