#!/usr/bin/env python3
"""Compares two run directories bit for bit: summary.json without the
wall-clock fields (wall_seconds, throughput, profile) and every dataset and
attribute of results.h5.

    compare_outputs.py DIR_A DIR_B     prints the differences, exits 1 if any

Used by the pytest suite (the same scene from Python and from `polydem run`)
and to check that a refactor left the command line's results unchanged."""
import json
import sys

import h5py
import numpy as np

# Wall-clock fields: measured, never computed, so never equal twice.
TIMING = ("wall_seconds", "subcontact_updates_per_second", "profile", "checkpoint_wall_seconds")


def strip_timing(value):
    if isinstance(value, dict):
        return {k: strip_timing(v) for k, v in value.items() if k not in TIMING}
    if isinstance(value, list):
        return [strip_timing(v) for v in value]
    return value


def summary_differences(a, b):
    with open(a, encoding="utf-8") as f:
        sa = strip_timing(json.load(f))
    with open(b, encoding="utf-8") as f:
        sb = strip_timing(json.load(f))
    out = []

    def walk(x, y, path):
        if isinstance(x, dict) and isinstance(y, dict):
            for k in sorted(set(x) | set(y)):
                if k not in x or k not in y:
                    out.append(f"summary.json {path}/{k}: only in {'b' if k not in x else 'a'}")
                else:
                    walk(x[k], y[k], f"{path}/{k}")
        elif isinstance(x, list) and isinstance(y, list) and len(x) == len(y):
            for i, (u, v) in enumerate(zip(x, y)):
                walk(u, v, f"{path}[{i}]")
        elif x != y or type(x) is not type(y):
            out.append(f"summary.json {path}: {x!r} != {y!r}")

    walk(sa, sb, "")
    return out


def h5_items(path):
    items = {}

    def visit(name, obj):
        for k, v in obj.attrs.items():
            items[f"{name}@{k}"] = v
        if isinstance(obj, h5py.Dataset):
            items[name] = obj[()]

    with h5py.File(path, "r") as f:
        for k, v in f.attrs.items():
            items[f"/@{k}"] = v
        f.visititems(visit)
    return items


def same(x, y):
    if isinstance(x, np.ndarray) or isinstance(y, np.ndarray):
        x, y = np.asarray(x), np.asarray(y)
        if x.shape != y.shape or x.dtype != y.dtype:
            return False
        if x.dtype.kind == "f":  # bitwise: NaN equals NaN, -0 differs from 0
            return x.tobytes() == y.tobytes()
        return bool(np.all(x == y))
    return x == y


def h5_differences(a, b):
    ia, ib = h5_items(a), h5_items(b)
    out = [f"results.h5 {k}: only in {'a' if k in ia else 'b'}" for k in sorted(set(ia) ^ set(ib))]
    out += [f"results.h5 {k}: differs" for k in sorted(set(ia) & set(ib)) if not same(ia[k], ib[k])]
    return out


def differences(dir_a, dir_b):
    return summary_differences(f"{dir_a}/summary.json", f"{dir_b}/summary.json") + h5_differences(
        f"{dir_a}/results.h5", f"{dir_b}/results.h5")


if __name__ == "__main__":
    diffs = differences(sys.argv[1], sys.argv[2])
    for d in diffs:
        print(d)
    print(f"{len(diffs)} difference(s)" if diffs else "identical (timing fields aside)")
    sys.exit(1 if diffs else 0)
