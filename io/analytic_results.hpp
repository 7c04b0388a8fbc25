// The results of `polydem analytic MODEL --json` as JSON values, one
// function per model (the keys carry their units: _m, _s, _g, _rad, _Hz),
// and the DEM frequency's signal as CSV. The command line prints them with
// kAnalyticDigits significant digits; the Python module reads them back at
// full precision, so both see the same keys.
#pragma once

#include "analytical/beam_modes.hpp"
#include "analytical/cracked_spire.hpp"
#include "analytical/rocking_cases.hpp"
#include "analytical/static_overturning.hpp"
#include "io/json.hpp"
#include "studies/dem_frequency.hpp"
#include "studies/limit_study.hpp"
#include "studies/spire_lambda.hpp"
#include "studies/standing.hpp"

#include <string>
#include <vector>

namespace polydem {

// The significant digits of every number `polydem analytic --json` prints.
inline constexpr int kAnalyticDigits = 12;

Json cone_overturning_json(const analytical::ConeOverturning& r);
Json spire_beam_json(const analytical::SpireBeamModes& r);
// The history is thinned to one sample every `every` seconds
// (analytical::samples_every).
Json rocking_json(const analytical::RockingCase& c, const analytical::RockingResponse& r, double every);
Json collapse_diagram_json(const analytical::CollapseDiagramCase& c, const analytical::CollapseDiagram& r);
Json cracked_spire_json(const analytical::CrackedSpireCurve& r);
Json spire_lambda_json(const SpireLambda& r);
// `scene` is the one measured (its deck, windows and joint damping are echoed).
Json dem_frequency_json(const SceneSpec& scene, const DemFrequencyOptions& options, const DemFrequencyResult& r);
Json limit_study_json(const LimitStudy& study);
Json thinnest_arch_json(const ThinnestArchOptions& options, const std::vector<ThinnestArch>& arches);

// The tip's displacement after the pulse: "t_s,u_m", 9 significant digits.
// Throws std::runtime_error("cannot write PATH").
void write_dem_frequency_csv(const std::string& path, const DemFrequencyResult& r);

}  // namespace polydem
