#!/usr/bin/python3
"""The structures gallery of docs/structures.md: docs/img/wall_gallery.png
(the bonds, leaves, openings, a corner and a gable),
docs/img/wall_corners.png (English and Flemish bond corners with their
closers) and docs/img/tower_gallery.png (a square and an octagonal tower and the bell
tower with its spire), each a grid of panels drawn by render_blocks.py from
the blocks of `polydem mesh`.

    scripts/render_structures_gallery.py [--polydem build/polydem] [--work out/gallery_structures]

Each panel is one plan window of one mesh (the walls of
examples/structures/wall_gallery.toml side by side, one window per wall).
"""

import argparse
import os
import subprocess
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import render_blocks  # noqa: E402

# (deck, panel title, window, view, colour)
WALLS = "examples/structures/wall_gallery.toml"
PANELS_WALLS = [
    (WALLS, "running bond, lintel", (0, 2.8, -0.3, 0.3), (-70, 20), "block_id"),
    (WALLS, "English bond", (3.6, 6.4, -0.3, 0.3), (-70, 20), "block_id"),
    (WALLS, "Flemish bond", (7.2, 10, -0.3, 0.3), (-70, 20), "block_id"),
    (WALLS, "3 leaves, through-stones", (0, 2.8, 2.1, 2.9), (-70, 20), "block_id"),
    (WALLS, "header bond, arched door", (3.6, 6.4, 2.1, 2.9), (-70, 20), "block_id"),
    (WALLS, "arched window", (7.2, 10, 2.1, 2.9), (-70, 20), "block_id"),
    (WALLS, "corner: quoins interlocking", (0, 3.2, 4.5, 6.8), (-20, 25), "block_id"),
    ("examples/structures/gable_wall.toml", "gable, English bond, lintel", (-0.5, 4.5, -0.5, 0.5), (-60, 15),
     "block_id"),
]
CORNERS = "examples/structures/wall_corners.toml"
PANELS_CORNERS = [
    (CORNERS, "English bond corner: quoin headers, queen closers", (1.2, 3.1, -0.5, 2.0), (-40, 18), "block_id"),
    (CORNERS, "Flemish bond corner: quoin headers, queen closers", (4.8, 6.7, -0.5, 2.0), (-40, 18), "block_id"),
]
TOWERS = "examples/structures/tower_gallery.toml"
PANELS_TOWERS = [
    (TOWERS, "square tower, lintels (faces 0, 3)", (-1.6, 1.6, -1.6, 1.6), (-25, 20), "block_id"),
    (TOWERS, "octagonal tower, arches (faces 0, 2, 4, 6)", (3, 7, -2, 2), (-25, 20), "block_id"),
    ("examples/structures/bell_tower.toml", "bell tower with its spire", (-2.5, 2.5, -2.5, 2.5), (-65, 15),
     "course"),
]


def mesh(polydem, deck, work):
    out = os.path.join(work, os.path.splitext(os.path.basename(deck))[0])
    subprocess.run([polydem, "mesh", os.path.join(ROOT, deck), "--out", out], check=True, stdout=subprocess.DEVNULL)
    return os.path.join(out, "blocks.vtu")


def grid(polydem, work, panels, cols, out, size):
    frames = []
    meshes = {}
    for i, (deck, title, window, view, color) in enumerate(panels):
        if deck not in meshes:
            meshes[deck] = mesh(polydem, deck, work)
        png = os.path.join(work, "panel_%s_%d.png" % (os.path.basename(out), i))
        render_blocks.main([meshes[deck], "--color", color, "--view", str(view[0]), str(view[1]), "--size", "5", "4",
                            "--zoom", "1.3", "--dpi", "80", "--window"] + [str(w) for w in window] +
                           ["--title", title, "--out", png])
        frames.append(png)
    rows = (len(frames) + cols - 1) // cols
    fig, axs = plt.subplots(rows, cols, figsize=size)
    for ax in axs.flat:
        ax.axis("off")
    for ax, png in zip(axs.flat, frames):
        ax.imshow(mpimg.imread(png))
    plt.tight_layout()
    plt.savefig(os.path.join(ROOT, out), dpi=75)
    print("wrote", out)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--polydem", default=os.path.join(ROOT, "build", "polydem"))
    ap.add_argument("--work", default=os.path.join(ROOT, "out", "gallery_structures"))
    args = ap.parse_args(argv)
    os.makedirs(args.work, exist_ok=True)
    grid(args.polydem, args.work, PANELS_WALLS, 4, "docs/img/wall_gallery.png", (18, 7.5))
    grid(args.polydem, args.work, PANELS_TOWERS, 3, "docs/img/tower_gallery.png", (15, 5.5))
    grid(args.polydem, args.work, PANELS_CORNERS, 2, "docs/img/wall_corners.png", (12, 5))


if __name__ == "__main__":
    main()
