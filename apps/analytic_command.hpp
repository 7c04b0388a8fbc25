#pragma once
// `polydem analytic <model> [--key value ...] [--json]`: the paper's
// closed-form and ODE models (analytical/) and the limit analyses of the
// block model (studies/) from the command line, one CLI11 subcommand per
// model: lambda, beam, rocking, collapse-diagram, cracked-cone-p,
// refined-lambda, dem-frequency, limit-lp, arch-thickness, spectrum
// (apps/spectrum_command.hpp), fragility, synthetic.
// `polydem analytic --help` lists them, `polydem analytic MODEL --help`
// their options. --json prints io/analytic_results.hpp's JSON.

#include <string>
#include <vector>

// args: the words after `polydem` (a leading "analytic" is skipped if present).
// Prints to stdout; errors to stderr. Returns 0 on success, 2 on bad input
// (dem-frequency: 1 when the run went unstable).
int run_analytic_command(const std::vector<std::string>& args);
