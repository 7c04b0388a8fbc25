"""The AVX2 / AVX-512VL kernels' objects run nothing before main().

A vector constant at namespace scope in one of them (`const __m256i k =
_mm256_setr_epi64x(...)`) is built by a static initialiser in AVX
instructions, listed in the object's .init_array and run at start-up on
every CPU: a machine without AVX would stop with SIGILL before the portable
path could be chosen (core/lanes_avx2.hpp). Usage:
    check_lanes_objects.py BUILD_DIR
Fails if no kernel object is found (the check would mean nothing), or if
any has an .init_array, .ctors or .preinit_array section.
"""
import pathlib
import subprocess
import sys

build = pathlib.Path(sys.argv[1])
objects = sorted(p for p in build.rglob("*_avx*.cpp.o") if "CMakeFiles" in p.parts)
if len(objects) < 4:
    sys.exit(f"expected the four lanes objects under {build}, found {len(objects)}: {[str(p) for p in objects]}")
bad = []
for o in objects:
    sections = subprocess.run(["readelf", "-S", "-W", str(o)], check=True, capture_output=True, text=True).stdout
    for name in (".init_array", ".ctors", ".preinit_array"):
        if name in sections:
            bad.append(f"{o}: {name}")
if bad:
    sys.exit("static initialisers in a lanes object (run before main() on every CPU):\n  " + "\n  ".join(bad))
print(f"{len(objects)} lanes objects, no static initialisers:", ", ".join(o.name for o in objects))
