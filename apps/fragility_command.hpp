// `polydem analytic fragility INPUT.csv --out DIR`: lognormal fragility
// curves with bootstrap bands from IDA or multiple-stripe runs
// (analytical/fragility.hpp, docs/fragility.md).
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace polydem {

// Adds the subcommand to `polydem analytic`; the returned function runs it
// once the words are parsed (it throws on bad input, before writing).
std::function<int()> add_fragility_command(CLI::App& analytic);

}  // namespace polydem
