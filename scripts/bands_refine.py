#!/usr/bin/python3
"""Refine the bands of a `polydem sweep --replicas N --band-axis KEY` grid
where its boundaries are sharper than the grid, and merge the refined
columns into one pair of tables (docs/ensembles.md, "Bands along an
intensity axis").

    scripts/bands_refine.py grid out/tip_bands [--step 0.01] [--outcomes damage,collapse]
    scripts/bands_refine.py merge out/tip_bands/T* --out docs/data/tip_bands

`grid DIR` reads DIR/bands.csv and prints, for each column (one --vary key
beside the band axis), a line `VALUE LIST`: the column's value and the band
axis values to run it at, the grid's own plus every multiple of --step
strictly inside the bracket (below, above) of each outcome that has no fit
(status not_identified: the step from none to all lies within one grid
interval). A `polydem sweep` of one column with `--vary KEY=LIST` in the
same DIR reuses the grid's runs and adds the new ones.

`merge DIR...` concatenates the bands.csv of several such sweeps (one column
each) into PREFIX.csv, and their ensembles.csv into PREFIX_points.csv with
the columns a diagram needs: the varied values, replicas, the count of each
status (0 where a sweep saw none), n_mode_I, n_mode_II, judged, p_damage,
p_stones_lost, p_collapse. Rows in increasing order of the varied values.
A DIR ending in .csv is a pair X.csv, X_points.csv merged before (columns
kept from an earlier merge are merged again with new ones).

Uses only the Python standard library.
"""

import argparse
import csv
import os
import sys


def read_rows(path):
    with open(path) as f:
        reader = csv.DictReader(f)
        return reader.fieldnames, list(reader)


def text(x):
    """The value to 12 significant digits: the same double polydem reads back."""
    return "%.12g" % x


def refine(args):
    fields, rows = read_rows(os.path.join(args.dir, "bands.csv"))
    column = fields[0]
    axis = next(f[: -len("_below")] for f in fields if f.endswith("_below"))
    wanted = set(args.outcomes.split(","))
    points = {}
    _, ensembles = read_rows(os.path.join(args.dir, "ensembles.csv"))
    for r in ensembles:
        points.setdefault(r[column], set()).add(float(r[axis]))
    for r in rows:
        values = points.setdefault(r[column], set())
        if r["outcome"] not in wanted or r["status"] != "not_identified":
            continue
        if not r[axis + "_below"] or not r[axis + "_above"]:
            continue
        lo, hi = float(r[axis + "_below"]), float(r[axis + "_above"])
        k = int(round(lo / args.step)) + 1
        while k * args.step < hi - 0.5 * args.step:
            values.add(round(k * args.step, 12))
            k += 1
    for c in sorted(points, key=float):
        print(c, ",".join(text(v) for v in sorted(points[c])))


POINT_COLUMNS = ["replicas", "n_mode_I", "n_mode_II", "judged", "p_damage", "p_stones_lost", "p_collapse"]


def merge(args):
    bands_header, bands = None, []
    keys, points, statuses = None, [], set()
    for d in args.dirs:
        # A sweep's directory, or a pair X.csv, X_points.csv merged before.
        merged = d.endswith(".csv")
        bands_csv = d if merged else os.path.join(d, "bands.csv")
        points_csv = os.path.splitext(d)[0] + "_points.csv" if merged else os.path.join(d, "ensembles.csv")
        header, rows = read_rows(bands_csv)
        if bands_header is None:
            bands_header = header
        elif header != bands_header:
            sys.exit(f"{bands_csv}: its columns differ from the first one's")
        bands += rows
        header, rows = read_rows(points_csv)
        these = header[: header.index("replicas")]
        if keys is None:
            keys = these
        elif these != keys:
            sys.exit(f"{points_csv}: its varied keys differ from the first one's")
        statuses |= {h for h in header if h.startswith("n_") and not h.startswith("n_mode")}
        points += rows
    order = lambda r, names: [float(r[k]) for k in names]  # noqa: E731
    column_keys = bands_header[: bands_header.index("outcome")]
    outcome_order = {"damage": 0, "stones_lost": 1, "collapse": 2}
    bands.sort(key=lambda r: (order(r, column_keys), outcome_order.get(r["outcome"], 3)))
    points.sort(key=lambda r: order(r, keys))
    with open(args.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, bands_header, lineterminator="\n")
        w.writeheader()
        w.writerows(bands)
    point_header = keys + ["replicas"] + sorted(statuses) + POINT_COLUMNS[1:]
    with open(args.out + "_points.csv", "w", newline="") as f:
        w = csv.DictWriter(f, point_header, extrasaction="ignore", lineterminator="\n")
        w.writeheader()
        for r in points:
            w.writerow({k: r.get(k, "0") for k in point_header})
    print(args.out + ".csv", args.out + "_points.csv")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="command", required=True)
    g = sub.add_parser("grid", help="the band axis values to run each column at")
    g.add_argument("dir")
    g.add_argument("--step", type=float, default=0.01)
    g.add_argument("--outcomes", default="damage,collapse")
    m = sub.add_parser("merge", help="one pair of tables from several one-column sweeps")
    m.add_argument("dirs", nargs="+")
    m.add_argument("--out", required=True)
    args = ap.parse_args()
    refine(args) if args.command == "grid" else merge(args)


if __name__ == "__main__":
    main()
