// Which code path the step's hot loops take: the AVX2 lanes (the joint law,
// contact/joint_law_lanes.hpp; the gather, contact/gather_lanes.hpp; the
// blocks' update, integrators/block_update_lanes.hpp) or the portable loops
// every machine runs. Both give the same bits (each lane repeats the portable arithmetic
// in its order), so the choice changes speed only; tests run both and
// compare.
//
// `automatic` takes the lanes where this build has them (x86-64) and the
// CPU has AVX2, unless the environment sets POLYDEM_CODE_PATH=portable (for
// timing one against the other).
#pragma once

namespace polydem {

enum class CodePath { automatic, portable, lanes };

// True when this build has the AVX2 lanes (x86-64, its own code compiled for
// baseline x86-64) and this CPU can run them.
bool lanes_available();

// Whether `path` runs the lanes: automatic as above; `lanes` where
// lanes_available(), the portable loops elsewhere.
bool use_lanes(CodePath path);

}  // namespace polydem
