#pragma once
// `polydem analytic <model> [--key value ...] [--json]`: the paper's
// closed-form and ODE models (analytical/) from the command line.
// Models: lambda, beam, rocking, collapse-diagram, cracked-cone-p;
// `polydem analytic --help` lists their options.

#include <string>
#include <vector>

// args: the words after `polydem` (a leading "analytic" is skipped if present).
// Prints to stdout; errors to stderr. Returns 0 on success, 2 on bad input.
int run_analytic_command(const std::vector<std::string>& args);
