// The text reports of `polydem analytic MODEL` (without --json): each echoes
// its inputs with their units, then a table. The numbers are the results'
// (io/analytic_results.hpp holds the same as JSON).
#pragma once

#include "io/analytic_results.hpp"

#include <ostream>

namespace polydem {

// h_c_given: eq. 2 at the crack height asked for is reported too.
void report_cone_overturning(std::ostream& out, const analytical::ConeOverturning& r, bool h_c_given);
void report_spire_beam(std::ostream& out, const analytical::SpireBeamModes& r);
// The history one sample every `every` seconds.
void report_rocking(std::ostream& out, const analytical::RockingCase& c, const analytical::RockingResponse& r,
                    double every);
void report_collapse_diagram(std::ostream& out, const analytical::CollapseDiagramCase& c,
                             const analytical::CollapseDiagram& r);
void report_cracked_spire(std::ostream& out, const analytical::CrackedSpireCurve& r);
void report_spire_lambda(std::ostream& out, const SpireLambda& r);
void report_dem_frequency(std::ostream& out, const SceneSpec& scene, const DemFrequencyOptions& options,
                          const DemFrequencyResult& r);
// interfaces: list every interface that opens or slides, case by case.
void report_limit_study(std::ostream& out, const LimitStudy& study, bool interfaces);
// The heading, then one line per arch as each is found.
void report_thinnest_arch_heading(std::ostream& out, const ThinnestArchOptions& options);
void report_thinnest_arch(std::ostream& out, const ThinnestArch& arch);

}  // namespace polydem
