// The tables of an incremental dynamic analysis or a multiple-stripe
// analysis (layout in docs/ida.md):
//   DIR/ida.csv         one row per run: record, im, scale, state, and the
//                       response (peak and residual tip displacement, the
//                       largest displacement and joint openings, dislodged
//                       stones, the damage and collapse times);
//                       `polydem analytic fragility` reads it as it is
//   DIR/capacities.csv  one row per record: its IM, the lowest IM that
//                       reached each state, the collapse bracket, its runs
// Neither holds a run time, so an analysis gives the same files bit for bit
// on any number of workers; both are written atomically.
#pragma once

#include "io/json.hpp"
#include "studies/ida.hpp"

#include <string>

namespace polydem {

std::string ida_csv(const IdaReport& report);
std::string capacities_csv(const IdaReport& report);

// Writes both into DIR (creating it).
void write_ida_tables(const std::string& dir, const IdaReport& report);

// Per record: name, record_im, damage_im, stones_lost_im, collapse_im,
// below_collapse_im, runs, undetermined (null for NaN).
Json capacities_json(const IdaReport& report);

}  // namespace polydem
