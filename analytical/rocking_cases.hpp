#pragma once
// A rocking body and a ground motion given by a few numbers, as `polydem
// analytic rocking` and `collapse-diagram` (and Python) describe them, and
// the two computations on them: the response to one ground motion
// (rocking_response.hpp) and the collapse diagram under one-sine pulses
// (collapse_diagram.hpp).

#include <optional>
#include <string>
#include <vector>

#include "analytical/collapse_diagram.hpp"
#include "analytical/cracked_spire.hpp"
#include "analytical/ground_motion.hpp"
#include "analytical/rocking_body.hpp"
#include "analytical/rocking_response.hpp"

namespace polydem::analytical {

enum class BodyShape { block, shell, cone, cracked };
const char* to_string(BodyShape s);
std::optional<BodyShape> body_shape_named(const std::string& name);  // "block", ...; none for another

// Only the fields of the shape are read; the defaults of the cone's are the
// paper's spire (SpireGeometry's).
struct BodySpec {
  BodyShape shape = BodyShape::shell;
  double b = 0.2, h = 1.0;                            // block: half-width, half-height [m]
  double r_b = SpireGeometry{}.r_b;                   // shell (eq. 8), solid cone, cracked: base radius [m]
  double H = SpireGeometry{}.H;                       // shell, solid cone, cracked: height [m]
  double tip = SpireGeometry{}.tip_height;            // cracked: the solid tip [m]
  double thickness = SpireGeometry{}.wall_thickness;  // cracked: the wall below the tip [m]
  double density = SpireGeometry{}.density;           // cracked [kg/m³]
  std::optional<double> H_bar;                        // cracked: the cracked height [m]; default tip
};

// The body of unit mass (shell, cone, block) or of its own mass (cracked).
RockingBody rocking_body(const BodySpec& spec, double g);

enum class LoadKind { pulse, constant, record };
const char* to_string(LoadKind k);
std::optional<LoadKind> load_kind_named(const std::string& name);  // "pulse", ...; none for another

// Accelerations in units of g.
struct LoadSpec {
  LoadKind kind = LoadKind::pulse;
  double a_p = 1.0, T_p = 1.0;     // pulse: a_p sin(2π t / T_p) for 0 ≤ t ≤ T_p [g, s]
  double a = 0.2;                  // constant [g]
  double record_dt = 0.0;          // record: the samples' step [s], from t = 0
  std::vector<double> record;      // record: samples [g]
  std::string record_name;         // record: where the samples came from (echoed in results)
  bool record_shifted = false;     // record: its first sample was not at t = 0 (echoed in reports)
};

GroundMotion ground_motion(const LoadSpec& load, double g);

struct RockingCase {
  BodySpec body;
  LoadSpec load;
  RockingOptions options;  // options.g scales the load and makes the body
};

struct RockingResponse {
  RockingBody body;
  RockingResult result;  // with the history of every step
};

RockingResponse rocking_response(const RockingCase& c);

// The history thinned to about one sample every `every` seconds: a sample
// is kept once `every` has passed since the last one kept; the first and
// the last are always kept.
std::vector<RockingSample> samples_every(const std::vector<RockingSample>& history, double every);

struct CollapseDiagramCase {
  BodySpec body;
  double T_p_min = 0.2, T_p_max = 3.0;  // [s]
  int T_p_count = 15;                   // evenly spaced; 1: T_p_min alone
  // scan.g makes the body too. Amplitudes to 5 g, transitions to 1e-3 g.
  CollapseScanOptions scan = [] {
    CollapseScanOptions s;
    s.a_max_g = 5.0;
    s.tolerance_g = 1e-3;
    return s;
  }();
};

struct CollapseDiagram {
  RockingBody body;
  std::vector<CollapseColumn> columns;  // one per T_p
};

CollapseDiagram pulse_collapse_diagram(const CollapseDiagramCase& c);

}  // namespace polydem::analytical
