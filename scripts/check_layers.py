#!/usr/bin/env python3
"""Checks the layering of ../shared/DESIGN.md and docs/architecture.md: a
folder includes only itself and the folders below it.

    geometry <- core <- contact <- integrators <- run <- studies <- io <- apps
    structures (the masonry generators) stands on geometry alone; analytical
    and the layers from run up may use it, core and the step never do
    analytical stands alone (it may use geometry, structures and core/units.hpp)
    python is a top layer beside apps: it may use everything but apps

Prints every include that breaks the rule (file:line: include) and exits 1
if there is one. Run by CTest (tests/scripts)."""
import os
import re
import sys

ORDER = ["geometry", "core", "contact", "integrators", "run", "studies", "io", "apps"]
SIDE = {"analytical", "structures"}  # beside the pipeline, usable from run up
ALLOWED = {folder: set(ORDER[: i + 1]) | (SIDE if i >= ORDER.index("run") else set())
           for i, folder in enumerate(ORDER)}
ALLOWED["structures"] = {"structures", "geometry"}
ALLOWED["analytical"] = {"analytical", "structures", "geometry"}
ALLOWED["python"] = set(ORDER[: ORDER.index("io") + 1]) | SIDE | {"python"}
EXCEPTIONS = {("analytical", "core/units.hpp")}  # the one g

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
include = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/([^"]+)"')
bad = 0
for folder in ALLOWED:
    for dirpath, _, files in os.walk(os.path.join(root, folder)):
        for name in sorted(files):
            if not name.endswith((".hpp", ".cpp", ".in")):
                continue
            path = os.path.join(dirpath, name)
            with open(path, encoding="utf-8") as f:
                for n, line in enumerate(f, 1):
                    m = include.match(line)
                    if not m or m.group(1) not in ALLOWED:
                        continue
                    target = m.group(1)
                    if target in ALLOWED[folder] or (folder, f"{target}/{m.group(2)}") in EXCEPTIONS:
                        continue
                    print(f"{os.path.relpath(path, root)}:{n}: {folder}/ includes {target}/{m.group(2)}")
                    bad += 1
print(f"layers: {bad} upward include(s)" if bad else "layers: every include points down")
sys.exit(1 if bad else 0)
