// Which code path the step's hot loops take: the AVX2 lanes (the joint law,
// contact/joint_law_lanes.hpp; the gather, contact/gather_lanes.hpp; the
// blocks' update, integrators/block_update_lanes.hpp) or the portable loops
// every machine runs. Both give the same bits (each lane repeats the portable arithmetic
// in its order), so the choice changes speed only; tests run both and
// compare.
//
// `automatic` takes the lanes where this build has them (x86-64) and the
// CPU has AVX2, unless the environment sets POLYDEM_CODE_PATH=portable (for
// timing one against the other). Where the CPU also has AVX-512VL, the
// joint law's kernel is the copy compiled for it (contact/
// joint_law_lanes_avx512.cpp: the same lanes and bits, 32 registers);
// POLYDEM_CODE_PATH=avx2 keeps the AVX2 copy.
#pragma once

namespace polydem {

// lanes_avx2: the lanes, with the joint law's AVX2 kernel even where the
// CPU has AVX-512VL (tests compare the two kernels).
enum class CodePath { automatic, portable, lanes, lanes_avx2 };

// True when this build has the AVX2 lanes (x86-64, its own code compiled for
// baseline x86-64) and this CPU can run them.
bool lanes_available();

// True when lanes_available() and the CPU (and its OS) also run AVX-512F
// and AVX-512VL.
bool wide_lanes_available();

// Whether `path` runs the lanes: automatic as above; `lanes` and
// `lanes_avx2` where lanes_available(), the portable loops elsewhere.
bool use_lanes(CodePath path);

// Whether the joint law's lanes take the AVX-512VL kernel: `lanes` where
// wide_lanes_available(), `automatic` there too unless
// POLYDEM_CODE_PATH=avx2; never on the other paths.
bool use_wide_lanes(CodePath path);

}  // namespace polydem
