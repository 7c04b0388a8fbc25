#!/usr/bin/python3
"""Render polydem's blocks as shaded 3D polyhedra (a PNG for reports and the README).

    scripts/render_blocks.py out/main/vtk/blocks.pvd --last --out wall.png
    scripts/render_blocks.py out/main/vtk/blocks.pvd --time 3.0 --view -60 20
    scripts/render_blocks.py out/spire_mesh/blocks.vtu --color course

Input: one VTK XML UnstructuredGrid written by polydem (`vtk/blocks_NNNNN.vtu`
from `polydem run` with `output.snapshot_interval`, or `blocks.vtu` from
`polydem mesh`), or the `.pvd` series that lists the snapshots with their times
(`--time T` takes the snapshot nearest T, `--last` or nothing the last one).
Only ASCII files with VTK_POLYHEDRON (42) or VTK_POLYGON (7) cells are read;
the XML is parsed with xml.etree, no VTK module is needed.

Each face is drawn as one polygon of a Poly3DCollection with its colour (by
displacement magnitude in mm, in um when every block moved less than 0.01 mm,
course or block id) shaded by a light that sits
above-left of the camera: ambient + diffuse * max(0, n.l) with n the outward
face normal (Newell's method; polydem writes the faces counter-clockwise seen
from outside). Faces turned away from the camera are hidden by their own block
and are dropped before drawing (back-face culling), which halves the polygon
count; matplotlib's painter's algorithm orders the rest by mean depth, and
faces much larger than a stone (the base slab) are cut into stone-sized tiles
so that they do not sort in front of the stones standing on them. The
projection is orthographic with equal scaling of x, y and z.

Uses only Debian's python3-numpy and python3-matplotlib (Agg backend).
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import cm, colors  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

VTK_POLYGON = 7
VTK_POLYHEDRON = 42


# ---------------------------------------------------------------------------
# Reading
# ---------------------------------------------------------------------------

def read_pvd(path):
    """Return [(time, absolute .vtu path), ...] of a ParaView collection, in file order."""
    root = ET.parse(path).getroot()
    base = os.path.dirname(os.path.abspath(path))
    series = []
    for ds in root.iter("DataSet"):
        series.append((float(ds.get("timestep", "nan")), os.path.join(base, ds.get("file"))))
    if not series:
        raise SystemExit(f"{path}: no DataSet entries")
    return series


def _array(element, dtype):
    if element.get("format", "ascii") != "ascii":
        raise SystemExit(f"DataArray '{element.get('Name')}': only format=\"ascii\" is supported")
    text = element.text or ""
    return np.array(text.split(), dtype=dtype)


def read_vtu(path):
    """Points, the faces of each cell (lists of point-id arrays) and the cell data of a .vtu."""
    root = ET.parse(path).getroot()
    piece = root.find("UnstructuredGrid/Piece")
    if piece is None:
        raise SystemExit(f"{path}: not a VTK UnstructuredGrid")
    points = _array(piece.find("Points/DataArray"), float).reshape(-1, 3)
    cells = {a.get("Name"): a for a in piece.findall("Cells/DataArray")}
    conn = _array(cells["connectivity"], np.int64)
    offsets = _array(cells["offsets"], np.int64)
    types = _array(cells["types"], np.int64)
    faces_stream = _array(cells["faces"], np.int64) if "faces" in cells else None
    face_offsets = _array(cells["faceoffsets"], np.int64) if "faceoffsets" in cells else None

    cell_faces = []
    start = 0
    for c, (end, kind) in enumerate(zip(offsets, types)):
        if kind == VTK_POLYHEDRON:
            if faces_stream is None:
                raise SystemExit(f"{path}: polyhedral cells without a 'faces' array")
            f_end = face_offsets[c]
            f_start = face_offsets[c - 1] if c > 0 else 0
            stream = faces_stream[f_start:f_end]
            nfaces, i, faces = stream[0], 1, []
            for _ in range(nfaces):
                n = stream[i]
                faces.append(stream[i + 1:i + 1 + n])
                i += 1 + n
            cell_faces.append(faces)
        elif kind == VTK_POLYGON:
            cell_faces.append([conn[start:end]])
        else:
            cell_faces.append([])  # lines, vertices: nothing to shade
        start = end

    data = {}
    for a in piece.findall("CellData/DataArray"):
        ncomp = int(a.get("NumberOfComponents", "1"))
        values = _array(a, float)
        data[a.get("Name")] = values.reshape(-1, ncomp) if ncomp > 1 else values
    return points, cell_faces, data


def pick_snapshot(path, time, last):
    """(vtu path, time or None) for a .vtu or a .pvd and the --time/--last choice."""
    if path.endswith(".pvd"):
        series = read_pvd(path)
        if time is None or last:
            t, f = series[-1]
        else:
            t, f = min(series, key=lambda s: abs(s[0] - time))
        return f, t
    # A bare .vtu: look its time up in a .pvd beside it, if there is one.
    folder = os.path.dirname(os.path.abspath(path))
    for name in sorted(os.listdir(folder)):
        if name.endswith(".pvd"):
            for t, f in read_pvd(os.path.join(folder, name)):
                if os.path.exists(f) and os.path.samefile(f, path):
                    return path, t
    return path, None


# ---------------------------------------------------------------------------
# Drawing
# ---------------------------------------------------------------------------

def view_vectors(azim_deg, elev_deg):
    """Unit vectors towards the camera, and the camera's right and up, in world coordinates."""
    a, e = np.radians(azim_deg), np.radians(elev_deg)
    eye = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    right = np.array([-np.sin(a), np.cos(a), 0.0])
    up = np.cross(eye, right)
    return eye, right, up


def cell_values(data, color):
    """Per-cell scalar, colour map, norm and colour-bar label for --color."""
    n = len(next(iter(data.values()))) if data else 0
    if color == "displacement":
        d = data["displacement"]
        values = 1000.0 * np.linalg.norm(d, axis=1)
        unit = "mm"
        if values.size and 0 < values.max() < 0.01:  # a structure that stays put: micrometres
            values, unit = 1000.0 * values, "\u00b5m"
        top = values.max() if values.size and values.max() > 0 else 1.0
        return values, plt.get_cmap("viridis"), colors.Normalize(0.0, top), f"displacement [{unit}]"
    values = np.asarray(data[color], dtype=float).reshape(n)
    if color == "course":
        lo, hi = int(values.min()), int(values.max())
        cmap = plt.get_cmap("tab20", max(hi - lo + 1, 2))
        return values, cmap, colors.Normalize(lo - 0.5, hi + 0.5), "course"
    cmap = plt.get_cmap("tab20")
    return np.mod(values, 20), cmap, colors.Normalize(-0.5, 19.5), "block id (mod 20)"


def clip(poly, axis, limit, keep_below):
    """Part of a convex polygon (k x 3) on one side of the plane p.axis = limit."""
    d = poly @ axis - limit
    if not keep_below:
        d = -d
    out = []
    for i in range(len(poly)):
        j = (i + 1) % len(poly)
        if d[i] <= 0.0:
            out.append(poly[i])
        if (d[i] < 0.0) != (d[j] < 0.0) and d[i] != d[j]:
            out.append(poly[i] + (poly[j] - poly[i]) * (d[i] / (d[i] - d[j])))
    return np.array(out) if len(out) >= 3 else None


def tiles(poly, normal, cell):
    """Split a large planar convex polygon into tiles of about cell x cell.

    matplotlib orders polygons by the depth of their centroids, so a big face (the
    base slab's top) sorts in front of the small stones standing on it; tiles
    small as a stone sort correctly."""
    u = np.cross(normal, [1.0, 0.0, 0.0] if abs(normal[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    su, sv = poly @ u, poly @ v
    nu = int(np.ceil((su.max() - su.min()) / cell))
    nv = int(np.ceil((sv.max() - sv.min()) / cell))
    if nu <= 1 and nv <= 1:
        return [poly]
    eu = np.linspace(su.min(), su.max(), nu + 1)
    ev = np.linspace(sv.min(), sv.max(), nv + 1)
    out = []
    for a in range(nu):
        strip = poly
        if a > 0:
            strip = clip(strip, u, eu[a], keep_below=False)
        if strip is not None and a < nu - 1:
            strip = clip(strip, u, eu[a + 1], keep_below=True)
        if strip is None:
            continue
        for b in range(nv):
            piece = strip
            if b > 0:
                piece = clip(piece, v, ev[b], keep_below=False)
            if piece is not None and b < nv - 1:
                piece = clip(piece, v, ev[b + 1], keep_below=True)
            if piece is not None:
                out.append(piece)
    return out


def clip_to_window(poly, window):
    """Part of a convex polygon inside the plan window (xmin, xmax, ymin, ymax), or None."""
    x, y = np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])
    for axis, limit, keep_below in ((x, window[0], False), (x, window[1], True),
                                    (y, window[2], False), (y, window[3], True)):
        poly = clip(poly, axis, limit, keep_below)
        if poly is None:
            return None
    return poly


def render(points, cell_faces, data, color, view, title, out, dpi, size, zoom=1.15, window=None, zlim=None):
    eye, right, up = view_vectors(*view)
    light = 0.55 * eye + 0.65 * np.array([0.0, 0.0, 1.0]) - 0.5 * right
    light /= np.linalg.norm(light)

    values, cmap, norm, label = cell_values(data, color)
    # Tile size: the lower quartile of the blocks' middle extent (a stone's width).
    extents = [np.sort(np.ptp(points[np.unique(np.concatenate(f))], axis=0))[1]
               for f in cell_faces if f]
    cell = max(np.percentile(extents, 25), 1e-3 * np.ptp(points, axis=0).max())
    polys, face_rgb, edge_rgb = [], [], []
    whole, whole_rgb = [], []  # the tiled faces in one piece, drawn beneath everything
    for c, faces in enumerate(cell_faces):
        base = np.array(cmap(norm(values[c]))[:3])
        for f in faces:
            p = points[f]
            if window is not None:
                p = clip_to_window(p, window)  # a wide base drawn only where the blocks are
                if p is None:
                    continue
            # Newell's normal: robust for any planar polygon, orientation from the vertex order.
            q = np.roll(p, -1, axis=0)
            n = np.array([np.sum((p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2])),
                          np.sum((p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0])),
                          np.sum((p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1]))])
            length = np.linalg.norm(n)
            if length == 0.0:
                continue
            n /= length
            facing = n @ eye
            if len(faces) > 1 and facing < -1e-9:
                continue  # back face of a closed block
            lit = 0.35 + 0.65 * max(0.0, (n if facing >= 0 else -n) @ light)
            rgb = np.clip(base * lit, 0.0, 1.0)
            pieces = tiles(p, n, cell) if np.ptp(p, axis=0).max() > 2.0 * cell else [p]
            polys.extend(pieces)
            face_rgb.extend([rgb] * len(pieces))
            # Tiles take the face colour as edge colour; the whole face beneath them
            # fills the antialiasing seams between tiles and carries the outline.
            edge_rgb.extend([rgb * 0.45 if len(pieces) == 1 else rgb] * len(pieces))
            if len(pieces) > 1:
                whole.append(p)
                whole_rgb.append(rgb)
    if not polys:
        raise SystemExit("no faces to draw")

    fig = plt.figure(figsize=size, dpi=dpi)
    ax = fig.add_axes([0.0, 0.05, 0.82, 0.88], projection="3d", proj_type="ortho")  # room below for the x, y labels
    cax = fig.add_axes([0.83, 0.22, 0.022, 0.52])
    ax.computed_zorder = False  # draw the collections in the order added
    if whole:
        ax.add_collection3d(Poly3DCollection(whole, facecolors=whole_rgb, edgecolors=np.array(whole_rgb) * 0.45,
                                             linewidths=0.35, zorder=1))
    ax.add_collection3d(Poly3DCollection(polys, facecolors=face_rgb, edgecolors=edge_rgb, linewidths=0.35,
                                         zorder=2))

    lo, hi = points.min(axis=0), points.max(axis=0)
    if window is not None:
        lo[:2] = np.maximum(lo[:2], [window[0], window[2]])
        hi[:2] = np.minimum(hi[:2], [window[1], window[3]])
    if zlim is not None:
        lo[2], hi[2] = zlim
    span = np.maximum(hi - lo, 1e-3 * max(hi - lo))
    ax.set_xlim(lo[0], lo[0] + span[0])
    ax.set_ylim(lo[1], lo[1] + span[1])
    ax.set_zlim(lo[2], lo[2] + span[2])
    ax.set_box_aspect(span, zoom=zoom)
    ax.view_init(elev=view[1], azim=view[0])
    ax.set_xlabel("x [m]", fontsize=8)
    ax.set_ylabel("y [m]", fontsize=8)
    ax.set_zlabel("z [m]", fontsize=8)
    ax.tick_params(labelsize=7)
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.pane.set_facecolor((0.96, 0.96, 0.96, 1.0))
        axis.pane.set_edgecolor((0.8, 0.8, 0.8, 1.0))
    ax.grid(False)

    mappable = cm.ScalarMappable(norm=norm, cmap=cmap)
    bar = fig.colorbar(mappable, cax=cax)
    bar.set_label(label, fontsize=9)
    bar.ax.tick_params(labelsize=8)
    if color == "course":
        lo, hi = int(round(norm.vmin + 0.5)), int(round(norm.vmax - 0.5))  # the first and the last course
        bar.set_ticks(np.arange(lo, hi + 1, max(1, (hi - lo + 1) // 10)))
    fig.suptitle(title, fontsize=11, y=0.97)
    # mplot3d leaves its axis labels out of the tight box: add them, or they are cut off.
    fig.savefig(out, dpi=dpi, bbox_inches="tight",
                bbox_extra_artists=fig.get_default_bbox_extra_artists()
                + [ax.xaxis.label, ax.yaxis.label, ax.zaxis.label])
    plt.close(fig)
    return len(polys)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("input", help="a .vtu file or a .pvd series")
    when = ap.add_mutually_exclusive_group()
    when.add_argument("--time", type=float, help="snapshot nearest this time [s] (with a .pvd)")
    when.add_argument("--last", action="store_true", help="the last snapshot (the default for a .pvd)")
    ap.add_argument("--out", help="PNG to write (default: beside the input, .png)")
    ap.add_argument("--color", choices=["displacement", "course", "block_id"], default="displacement",
                    help="what the colour shows (default displacement magnitude, mm; um below 0.01 mm)")
    ap.add_argument("--view", nargs=2, type=float, metavar=("AZIMUTH", "ELEVATION"), default=(-60.0, 20.0),
                    help="camera azimuth and elevation in degrees (default -60 20)")
    ap.add_argument("--title", help="title, followed by the time when known (default: the file name)")
    ap.add_argument("--zoom", type=float, default=1.15,
                    help="size of the drawing in its axes (default 1.15; lower it when tick labels are cut off)")
    ap.add_argument("--dpi", type=int, default=110)
    ap.add_argument("--size", nargs=2, type=float, metavar=("W", "H"), default=(7.0, 5.5),
                    help="figure size in inches (default 7 5.5)")
    ap.add_argument("--window", nargs=4, type=float, metavar=("XMIN", "XMAX", "YMIN", "YMAX"),
                    help="draw only this plan window [m] (faces clipped to it: a wide base)")
    args = ap.parse_args(argv)

    vtu, t = pick_snapshot(args.input, args.time, args.last)
    points, cell_faces, data = read_vtu(vtu)
    color = args.color
    if color not in data:
        fallback = next((c for c in ("course", "block_id") if c in data), None)
        if fallback is None:
            raise SystemExit(f"{vtu}: no cell data '{color}' and nothing to fall back to")
        print(f"render_blocks: {os.path.basename(vtu)} has no '{color}'; colouring by {fallback}", file=sys.stderr)
        color = fallback
    title = args.title if args.title is not None else os.path.basename(vtu)
    if t is not None:
        title += f"   t = {t:.3f} s"
    out = args.out or os.path.splitext(vtu)[0] + ".png"
    n = render(points, cell_faces, data, color, tuple(args.view), title, out, args.dpi, tuple(args.size), args.zoom,
               args.window)
    print(f"wrote {out} ({len(cell_faces)} blocks, {n} faces drawn)")


if __name__ == "__main__":
    main()
