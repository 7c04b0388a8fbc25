#!/usr/bin/python3
"""A picture strip: one run's snapshots at chosen instants side by side, as
the paper's Figure 6 (the spire under a 1.0 g, 1.0 s one-sine pulse).

    scripts/picture_strip.py out/pulse/vtk/blocks.pvd --times 0.3,0.6,0.9,1.2,1.6,2.4 \\
        --view -90 8 --window -6 6 -3 3 --out docs/img/figure6_strip.png

Each frame is drawn by render_blocks.py (its shading and colours: the
displacement magnitude, each frame on its own scale) with the same axes
(the plan window and the first frame's height), and the frames are laid
side by side with their times.
"""

import argparse
import os
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_blocks  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("pvd", help="the run's vtk/blocks.pvd")
    ap.add_argument("--times", required=True, help="comma-separated instants [s] (the nearest snapshots)")
    ap.add_argument("--view", nargs=2, type=float, default=(-90.0, 8.0), metavar=("AZIMUTH", "ELEVATION"))
    ap.add_argument("--window", nargs=4, type=float, metavar=("XMIN", "XMAX", "YMIN", "YMAX"))
    ap.add_argument("--color", default="displacement", choices=["displacement", "course", "block_id"])
    ap.add_argument("--title", default="")
    ap.add_argument("--dpi", type=int, default=90)
    ap.add_argument("--out", required=True)
    args = ap.parse_args(argv)
    times = [float(t) for t in args.times.split(",")]
    frames = []
    zlim = None
    with tempfile.TemporaryDirectory() as tmp:
        for k, t in enumerate(times):
            vtu, t_snap = render_blocks.pick_snapshot(args.pvd, t, False)
            points, cell_faces, data = render_blocks.read_vtu(vtu)
            if zlim is None:
                zlim = (points[:, 2].min(), points[:, 2].max())
            png = os.path.join(tmp, f"frame{k}.png")
            render_blocks.render(points, cell_faces, data, args.color, tuple(args.view), f"t = {t_snap:.2f} s", png,
                                 args.dpi, (4.0, 5.0), 1.15, args.window, zlim)
            frames.append(mpimg.imread(png))
    fig, axes = plt.subplots(1, len(frames), figsize=(3.2 * len(frames), 4.2), dpi=args.dpi)
    for ax, im in zip(axes if len(frames) > 1 else [axes], frames):
        ax.imshow(im)
        ax.axis("off")
    if args.title:
        fig.suptitle(args.title, fontsize=12)
    fig.tight_layout()
    fig.savefig(args.out, dpi=args.dpi)
    print(f"wrote {args.out} ({len(frames)} frames)")


if __name__ == "__main__":
    main()
