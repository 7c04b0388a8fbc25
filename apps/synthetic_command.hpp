// `polydem analytic synthetic --magnitude M --distance R --vs30 V --count N
// --seed S --out DIR`: a suite of synthetic records for an earthquake
// scenario (analytical/synthetic_ground_motion.hpp, docs/fragility.md).
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace polydem {

// Adds the subcommand to `polydem analytic`; the returned function runs it
// once the words are parsed (it throws on bad input, before writing).
std::function<int()> add_synthetic_command(CLI::App& analytic);

}  // namespace polydem
