// The step's kernels and the lane type they are written over.
//
// The hot loops of the step (the joint law, contact/joint_law_kernels.hpp; the
// gather, contact/gather_lanes.hpp; the blocks' update,
// integrators/block_update_lanes.hpp) work four subcontacts or four blocks
// at a time. Each is written once, in a .inc file, over a lane type: `V`,
// four doubles, and free functions on it (add, mul, comparisons that give
// lane masks, pick, masked loads and stores of a group of up to four
// entries, ...). Two lane types implement that interface: plain doubles
// (core/lanes_portable.hpp), which every machine runs, and AVX2 registers
// (core/lanes_avx2.hpp). Each kernel's .inc is compiled once per lane type
// (and the joint law's once more for AVX-512VL, the same 256-bit lanes in 32
// registers) under its own name; the code path picks one at run time. Each
// lane function performs one IEEE operation per lane (or a fixed sequence
// of them) and the kernels fix every association, with no fused
// multiply-add (-ffp-contract=off), so every lane type gives the same bits:
// the choice changes speed only. Tests run the kernels on every lane type
// the machine has and compare them with the Eigen expressions they stand
// for.
//
// `automatic` takes the AVX2 lanes where this build has them (x86-64) and
// the CPU has AVX2, unless the environment sets POLYDEM_CODE_PATH=portable
// (for timing one against the other). Where the CPU also has AVX-512VL, the
// joint law's kernel is the copy compiled for it;
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
