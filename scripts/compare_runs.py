# Compares two run directories: summary.json (timing keys aside) and every
# dataset of results.h5 present in the first, bit for bit.
import json, sys, h5py, numpy as np
a, b = sys.argv[1], sys.argv[2]
TIMING = {"wall_seconds", "profile", "subcontact_updates_per_second", "polydem_version", "deck", "threads"}
sa = json.load(open(a + "/summary.json")); sb = json.load(open(b + "/summary.json"))
bad = 0
for k in sa:
    if k in TIMING: continue
    if k not in sb: print("missing in new:", k); bad += 1; continue
    va, vb = sa[k], sb[k]
    if k == "equilibrium" and isinstance(va, dict):
        va = {x: y for x, y in va.items() if x != "wall_seconds"}; vb = {x: y for x, y in vb.items() if x != "wall_seconds"}
    if va != vb: print("summary differs:", k, va, vb); bad += 1
print("summary keys only in new:", sorted(set(sb) - set(sa)))
fa, fb = h5py.File(a + "/results.h5"), h5py.File(b + "/results.h5")
n = 0
def visit(name, obj):
    global bad, n
    if not isinstance(obj, h5py.Dataset): return
    if name not in fb: print("dataset missing in new:", name); bad += 1; return
    x, y = obj[()], fb[name][()]
    if isinstance(x, np.ndarray) and x.dtype.kind == 'f':
        same = x.shape == y.shape and np.array_equal(x.view(np.uint64), y.view(np.uint64))
    else:
        same = np.array_equal(np.asarray(x), np.asarray(y)) if not isinstance(x, bytes) else x == y
    n += 1
    if not same: print("dataset differs:", name); bad += 1
fa.visititems(visit)
new_only = []
fb.visititems(lambda name, o: new_only.append(name) if isinstance(o, h5py.Dataset) and name not in fa else None)
print(f"{n} datasets compared bit for bit; new datasets: {new_only}; differences: {bad}")
sys.exit(1 if bad else 0)
