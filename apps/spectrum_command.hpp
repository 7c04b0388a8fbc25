#pragma once
// `polydem analytic spectrum RECORD... | --suite FILE [--damping 0.05]
// [--periods T,T,...] [--mark-period NAME=T ...] --out DIR`: the elastic
// response spectra of records or a record suite (docs/records.md, "Response
// spectra"), written as DIR/spectra.csv, DIR/marks.csv and DIR/spectrum.png.
// A subcommand of `polydem analytic` (apps/analytic_command.cpp adds it).

#include <functional>

namespace CLI {
class App;
}

struct AnalyticModel {
  CLI::App* command = nullptr;  // parsed() once the words named it
  std::function<int()> run;     // 0 done, 1 the plot failed (the CSVs are written), 2 bad input
};

// Adds the `spectrum` subcommand to `app`; its options live as long as the
// returned model.
AnalyticModel add_spectrum_model(CLI::App& app);
