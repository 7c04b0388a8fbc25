#include "apps/analytic_command.hpp"
#include "apps/spectrum_command.hpp"

#include "apps/fragility_command.hpp"
#include "apps/option_number.hpp"
#include "apps/synthetic_command.hpp"

#include "core/number_text.hpp"
#include "io/analytic_inputs.hpp"
#include "io/analytic_report.hpp"
#include "structures/generator_specs.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace pa = polydem::analytical;

namespace {

struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// ------------------------------------------------------------------ options
//
// Every option is accepted with '-' or '_' between words (--r_b, --r-b).
// Numbers are read by read_option_number (apps/option_number.hpp).

std::string spellings(const std::string& name) {
  std::string other = name;
  for (char& c : other) c = c == '_' ? '-' : c == '-' ? '_' : c;
  return other == name ? "--" + name : "--" + name + ",--" + other;
}

enum class Sign { any, positive };

// An option of one value, read by `read` once the words are parsed; a
// missing value and a second occurrence are errors naming the option.
// `shown`: its type and default in the help (CLI11 would take a default
// string for the missing value).
CLI::Option* valued(CLI::App* cmd, const std::string& name, std::function<void(const std::string&)> read,
                    const std::string& help, const std::string& shown) {
  CLI::callback_t take = [name, read](const CLI::results_t& values) {
    if (values.size() > 1) throw BadInput("--" + name + " given twice");
    if (values.empty() || values[0].empty()) throw BadInput("--" + name + " needs a value");
    read(values[0]);
    return true;
  };
  return cmd->add_option(spellings(name), take, help)
      ->expected(0, 1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->option_text(shown);
}

CLI::Option* number(CLI::App* cmd, const std::string& name, double& value, const std::string& help,
                    Sign sign = Sign::any) {
  auto read = [&value, name, sign](const std::string& text) {
    value = polydem::read_option_number(name, text);
    if (sign == Sign::positive && !(value > 0.0)) throw BadInput("--" + name + " must be > 0");
  };
  return valued(cmd, name, read, help, "NUMBER=" + polydem::shortest_text(value));
}

CLI::Option* positive(CLI::App* cmd, const std::string& name, double& value, const std::string& help) {
  return number(cmd, name, value, help, Sign::positive);
}

// An integer given as a number (read as one, so "2.5" is out of range).
int whole(const std::string& name, double v, int lo, int hi) {
  if (v < lo || v > hi || v != std::floor(v))
    throw BadInput("--" + name + " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(v);
}

// Comma-separated numbers ("20,25,30").
CLI::Option* number_list(CLI::App* cmd, const std::string& name, std::vector<double>& values, const std::string& help,
                         const std::string& shown = "N[,N...]") {
  auto read = [&values, name](const std::string& text) {
    values.clear();
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t comma = std::min(text.find(',', start), text.size());
      try {
        values.push_back(polydem::read_option_number(name, text.substr(start, comma - start)));
      } catch (const std::invalid_argument&) {
        throw BadInput("--" + name + " expects numbers separated by commas, got '" + text + "'");
      }
      start = comma + 1;
    }
  };
  return valued(cmd, name, read, help, shown);
}

CLI::Option* file(CLI::App* cmd, const std::string& name, std::string& value, const std::string& help) {
  return valued(cmd, name, [&value](const std::string& text) { value = text; }, help, "FILE");
}

// One of `choices`; the message lists them.
CLI::Option* choice(CLI::App* cmd, const std::string& name, std::string& value, const std::vector<std::string>& choices,
                    const std::string& help) {
  std::string listed, braced;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    listed += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
    braced += (i == 0 ? "" : ",") + choices[i];
  }
  auto read = [&value, name, choices, listed](const std::string& text) {
    if (std::find(choices.begin(), choices.end(), text) == choices.end())
      throw BadInput("--" + name + " must be " + listed);
    value = text;
  };
  return valued(cmd, name, read, help, "{" + braced + "}=" + value);
}

CLI::Option* flag(CLI::App* cmd, const std::string& name, bool& value, const std::string& help) {
  return cmd->add_flag(spellings(name), value, help);
}

// The first word CLI11 left over is an error (the models allow extras so
// that the message names the first, as given).
void reject_extras(const CLI::App* cmd) {
  const std::vector<std::string> left = cmd->remaining();
  if (left.empty()) return;
  const std::string& w = left.front();
  const bool option = w.size() > 1 && w[0] == '-' && !std::isdigit(static_cast<unsigned char>(w[1])) && w[1] != '.';
  throw BadInput(option ? "unknown option " + w : "unexpected argument '" + w + "'");
}

void print_json(const polydem::Json& j) { std::cout << j.dump(0, polydem::kAnalyticDigits) << "\n"; }

// ------------------------------------------------------------ lambda, beam

struct LambdaArgs {
  double r_b = 1.06, H = 9.4, h_c = 0.0;
  CLI::Option* h_c_given = nullptr;
  bool json = false;
};

CLI::App* add_lambda(CLI::App& app, LambdaArgs& a) {
  auto* c = app.add_subcommand("lambda", "Static overturning of a conical shell, eq. 1-2");
  positive(c, "r_b", a.r_b, "Base radius, m");
  positive(c, "H", a.H, "Height, m");
  a.h_c_given = number(c, "h_c", a.h_c, "Crack height for eq. 2, m (default: H)")->option_text("NUMBER");
  flag(c, "json", a.json, "One JSON object");
  return c;
}

int run_lambda(LambdaArgs& a) {
  const bool at = a.h_c_given->count() > 0;
  if (!at) a.h_c = a.H;
  if (a.h_c < 0.0 || a.h_c > a.H) throw BadInput("--h_c must be in [0, H]");
  const pa::ConeOverturning r = pa::cone_overturning(a.r_b, a.H, a.h_c);
  if (a.json) print_json(polydem::cone_overturning_json(r));
  else polydem::report_cone_overturning(std::cout, r, at);
  return 0;
}

struct BeamArgs {
  pa::SpireBeam beam;
  std::string section = "circle";
  double modes = 3;
  bool json = false;
};

CLI::App* add_beam(CLI::App& app, BeamArgs& a) {
  auto* c = app.add_subcommand("beam", "Tapered-cantilever modes of the spire, eq. 3-6");
  positive(c, "H", a.beam.H, "Height, m");
  positive(c, "r_b", a.beam.r_b, "Base outer radius (circle) or outer apothem (octagon), m");
  positive(c, "thickness", a.beam.thickness, "Wall thickness, m");
  positive(c, "E", a.beam.E, "Young's modulus, Pa");
  positive(c, "density", a.beam.density, "Density, kg/m3");
  choice(c, "section", a.section, {"circle", "octagon"}, "Base section");
  number(c, "modes", a.modes, "Modes, 1 to 20");
  flag(c, "json", a.json, "One JSON object");
  return c;
}

int run_beam(BeamArgs& a) {
  a.beam.modes = whole("modes", a.modes, 1, 20);
  a.beam.section = a.section == "octagon" ? pa::SectionShape::octagon : pa::SectionShape::circle;
  const pa::SpireBeamModes r = pa::spire_beam_modes(a.beam);
  if (a.json) print_json(polydem::spire_beam_json(r));
  else polydem::report_spire_beam(std::cout, r);
  return 0;
}

// ------------------------------------------------- rocking, collapse diagram

// --body and the options of each shape.
struct BodyArgs {
  pa::BodySpec spec;
  std::string shape = "shell";
  double H_bar = 0.0;
  std::vector<std::pair<CLI::Option*, std::vector<pa::BodyShape>>> options;  // and the shapes they apply to
  CLI::Option* H_bar_given = nullptr;
};

void add_body(CLI::App* c, BodyArgs& a) {
  using S = pa::BodyShape;
  choice(c, "body", a.shape, {"block", "shell", "cone", "cracked"},
         "Rocking body: a rectangular block, a conical shell (eq. 8), a solid cone, the cracked spire");
  a.options = {
      {positive(c, "b", a.spec.b, "block: half-width, m"), {S::block}},
      {positive(c, "h", a.spec.h, "block: half-height, m"), {S::block}},
      {positive(c, "r_b", a.spec.r_b, "shell, cone, cracked: base radius, m"), {S::shell, S::cone, S::cracked}},
      {positive(c, "H", a.spec.H, "shell, cone, cracked: height, m"), {S::shell, S::cone, S::cracked}},
      {positive(c, "tip", a.spec.tip, "cracked: height of the solid tip, m"), {S::cracked}},
      {positive(c, "thickness", a.spec.thickness, "cracked: wall thickness below the tip, m"), {S::cracked}},
      {positive(c, "density", a.spec.density, "cracked: density, kg/m3"), {S::cracked}},
  };
  a.H_bar_given = positive(c, "H_bar", a.H_bar, "cracked: cracked height, apex to pivot, m (default: --tip)")
                      ->option_text("NUMBER");
  a.options.push_back({a.H_bar_given, {S::cracked}});
}

// The body spec of the options; an option of another shape is an error.
void read_body(BodyArgs& a) {
  const pa::BodyShape shape = *pa::body_shape_named(a.shape);
  for (const auto& [option, shapes] : a.options)
    if (option->count() > 0 && std::find(shapes.begin(), shapes.end(), shape) == shapes.end())
      throw BadInput(option->get_name() + " does not apply to --body " + a.shape);
  a.spec.shape = shape;
  if (a.H_bar_given->count() > 0) a.spec.H_bar = a.H_bar;
}

struct RockingArgs {
  pa::RockingCase c;
  BodyArgs body;
  std::string load = "pulse", file;
  double restitution = 0.0, every = 0.1;
  bool linear = false, json = false;
  CLI::Option *a_p = nullptr, *T_p = nullptr, *a = nullptr, *file_given = nullptr, *restitution_given = nullptr;
};

CLI::App* add_rocking(CLI::App& app, RockingArgs& a) {
  auto* c = app.add_subcommand("rocking", "Rocking response on a rigid base, eq. 7-10");
  add_body(c, a.body);
  pa::LoadSpec& l = a.c.load;
  choice(c, "load", a.load, {"pulse", "constant", "record"}, "Ground acceleration");
  a.a_p = number(c, "a_p", l.a_p, "pulse: amplitude, g");
  a.T_p = positive(c, "T_p", l.T_p, "pulse: period, s");
  a.a = number(c, "a", l.a, "constant: acceleration, g");
  a.file_given = file(c, "file", a.file, "record: a record file (.AT2, .ASC, .csv with its unit; docs/records.md) at a uniform step");
  positive(c, "g", a.c.options.g, "Gravity, m/s2");
  positive(c, "dt", a.c.options.dt, "RK4 step, s");
  positive(c, "t_end", a.c.options.t_end, "End time, s");
  flag(c, "linear", a.linear, "The small-angle form, eq. 9");
  a.restitution_given =
      number(c, "restitution", a.restitution, "Coefficient of restitution (default: eq. 10)")->option_text("NUMBER");
  positive(c, "print_every", a.every, "Interval of the printed history, s");
  flag(c, "json", a.json, "One JSON object");
  return c;
}

int run_rocking(RockingArgs& a) {
  read_body(a.body);
  a.c.body = a.body.spec;
  pa::LoadSpec& l = a.c.load;
  const std::vector<std::pair<CLI::Option*, std::string>> load_options = {
      {a.a_p, "pulse"}, {a.T_p, "pulse"}, {a.a, "constant"}, {a.file_given, "record"}};
  for (const auto& [option, load] : load_options)
    if (option->count() > 0 && load != a.load) throw BadInput(option->get_name() + " does not apply to --load " + a.load);
  l.kind = *pa::load_kind_named(a.load);
  if (l.kind == pa::LoadKind::record) {
    if (a.file.empty()) throw BadInput("--load record needs --file");
    l = polydem::record_load(a.file);
  }
  pa::RockingOptions& ro = a.c.options;
  if (a.linear) ro.form = pa::RockingForm::linearised;
  if (a.restitution_given->count() > 0) ro.restitution = a.restitution;
  const pa::RockingResponse r = pa::rocking_response(a.c);
  if (a.json) print_json(polydem::rocking_json(a.c, r, a.every));
  else polydem::report_rocking(std::cout, a.c, r, a.every);
  return 0;
}

struct CollapseArgs {
  pa::CollapseDiagramCase c;
  BodyArgs body;
  double count = 15, points = 80, restitution = 0.0;
  bool linear = false, json = false, no_return = false;
  CLI::Option* restitution_given = nullptr;
};

CLI::App* add_collapse(CLI::App& app, CollapseArgs& a) {
  auto* c = app.add_subcommand("collapse-diagram", "One-sine pulse collapse curve (Zhang & Makris 2001)");
  add_body(c, a.body);
  pa::CollapseScanOptions& s = a.c.scan;
  positive(c, "Tp_min", a.c.T_p_min, "Shortest pulse period, s");
  positive(c, "Tp_max", a.c.T_p_max, "Longest pulse period, s");
  number(c, "Tp_count", a.count, "Pulse periods, evenly spaced, 1 to 1000");
  positive(c, "a_max", s.a_max_g, "Highest amplitude scanned, g");
  number(c, "points", a.points, "Amplitudes of the coarse scan, 2 to 10000");
  positive(c, "tol", s.tolerance_g, "Width of each bisected transition, g");
  positive(c, "g", s.g, "Gravity, m/s2");
  flag(c, "linear", a.linear, "The small-angle form, eq. 9");
  flag(c, "no-return", a.no_return,
       "Overturned once past alpha with no return (the pulse over, or on its side), not at |theta| > alpha");
  a.restitution_given =
      number(c, "restitution", a.restitution, "Coefficient of restitution (default: eq. 10)")->option_text("NUMBER");
  flag(c, "json", a.json, "One JSON object");
  return c;
}

int run_collapse(CollapseArgs& a) {
  read_body(a.body);
  a.c.body = a.body.spec;
  pa::CollapseScanOptions& s = a.c.scan;
  if (a.linear) s.form = pa::RockingForm::linearised;
  if (a.no_return) s.overturn = pa::OverturnRule::no_return;
  if (a.restitution_given->count() > 0) s.restitution = a.restitution;
  a.c.T_p_count = whole("Tp_count", a.count, 1, 1000);
  s.coarse_points = whole("points", a.points, 2, 10000);
  if (a.c.T_p_max < a.c.T_p_min) throw BadInput("--Tp_max must be >= --Tp_min");
  const pa::CollapseDiagram d = pa::pulse_collapse_diagram(a.c);
  if (a.json) print_json(polydem::collapse_diagram_json(a.c, d));
  else polydem::report_collapse_diagram(std::cout, a.c, d);
  return 0;
}

struct CrackedArgs {
  pa::SpireGeometry spire;
  double g = pa::standard_gravity, count = 25;
  bool json = false;
};

CLI::App* add_cracked(CLI::App& app, CrackedArgs& a) {
  auto* c = app.add_subcommand("cracked-cone-p",
                               "p of the spire cracked below its solid tip against the cracked height H_bar (Fig. 7a)");
  positive(c, "H", a.spire.H, "Height, m");
  positive(c, "r_b", a.spire.r_b, "Base radius, m");
  positive(c, "tip", a.spire.tip_height, "Height of the solid tip, m");
  positive(c, "thickness", a.spire.wall_thickness, "Wall thickness below the tip, m");
  positive(c, "density", a.spire.density, "Density, kg/m3");
  number(c, "count", a.count, "Values of H_bar from the tip to H, 2 to 10000");
  positive(c, "g", a.g, "Gravity, m/s2");
  flag(c, "json", a.json, "One JSON object");
  return c;
}

int run_cracked(CrackedArgs& a) {
  const pa::CrackedSpireCurve r = pa::cracked_spire_curve(a.spire, whole("count", a.count, 2, 10000), a.g);
  if (a.json) print_json(polydem::cracked_spire_json(r));
  else polydem::report_cracked_spire(std::cout, r);
  return 0;
}

// ------------------------------------------------------- the block models

struct DeckArgs {
  std::string deck;
  bool no_windows = false;
};

void add_deck(CLI::App* c, DeckArgs& a, const std::string& what) {
  file(c, "deck", a.deck, what);
  flag(c, "no-windows", a.no_windows, "Without the spire's windows (the override spire.window_faces=[])");
}

struct RefinedArgs {
  DeckArgs deck;
  double g = pa::standard_gravity;
  bool json = false;
};

CLI::App* add_refined(CLI::App& app, RefinedArgs& a) {
  auto* c = app.add_subcommand("refined-lambda",
                               "Static collapse multiplier of the block model: plane and stepped cracks through a "
                               "base pivot, 16 directions (docs/analytical.md 5)");
  add_deck(c, a.deck, "Deck whose [spire] is used (default: the default [spire])");
  positive(c, "g", a.g, "Gravity, m/s2");
  flag(c, "json", a.json, "One JSON object");
  return c;
}

int run_refined(const RefinedArgs& a) {
  const polydem::SpireLambda r =
      polydem::spire_lambda(polydem::analytic_spire_scene(a.deck.deck, a.deck.no_windows), a.g);
  if (a.json) print_json(polydem::spire_lambda_json(r));
  else polydem::report_spire_lambda(std::cout, r);
  return 0;
}

struct DemArgs {
  DeckArgs deck;
  polydem::DemFrequencyOptions o;
  double threads = 0;
  std::string csv;
  bool json = false;
};

CLI::App* add_dem(CLI::App& app, DemArgs& a) {
  auto* c = app.add_subcommand("dem-frequency",
                               "First natural frequency of the block model by a DEM free vibration, against eq. 4 "
                               "with E = kn * course height (docs/analytical.md 6)");
  add_deck(c, a.deck, "Deck whose [spire] is used (default: the default [spire])");
  positive(c, "duration", a.o.duration, "Free vibration recorded after the pulse, s");
  number(c, "settle", a.o.settle_time, "Under gravity before the pulse, s");
  positive(c, "pulse_g", a.o.pulse_g, "Pulse amplitude, g");
  positive(c, "pulse_period", a.o.pulse_period, "Pulse period, s");
  positive(c, "interval", a.o.history_interval, "Between samples of the tip's position, s");
  flag(c, "keep_damping", a.o.keep_damping, "Keep the joints' damping (default: none)");
  number(c, "threads", a.threads, "OpenMP threads (0: the deck's, else OMP_NUM_THREADS or all cores)");
  file(c, "csv", a.csv, "Write the tip's displacement after the pulse: t_s,u_m");
  flag(c, "json", a.json, "One JSON object");
  return c;
}

int run_dem(DemArgs& a) {
  polydem::DemFrequencyOptions& d = a.o;
  d.threads = static_cast<int>(a.threads);
  if (d.settle_time < 0) throw BadInput("--settle must be >= 0");
  const polydem::SceneSpec scene = polydem::analytic_spire_scene(a.deck.deck, a.deck.no_windows);
  const polydem::DemFrequencyResult r = polydem::measure_dem_frequency(scene, d);
  if (!a.csv.empty()) polydem::write_dem_frequency_csv(a.csv, r);
  if (a.json) print_json(polydem::dem_frequency_json(scene, d, r));
  else polydem::report_dem_frequency(std::cout, scene, d, r);
  return r.unstable ? 1 : 0;
}

struct LimitArgs {
  DeckArgs deck;
  polydem::LimitStudyOptions o;
  double sides = 16;
  std::string pyramid = "both", method = "interior";
  bool interfaces = false, json = false;
};

CLI::App* add_limit(CLI::App& app, LimitArgs& a) {
  auto* c = app.add_subcommand(
      "limit-lp",
      "Friction-aware limit analysis of the block model: the rigid-block equilibrium LP (no tension, Coulomb "
      "pyramid at the joints' vertices, GLPK); the largest static horizontal force lambda m g (docs/analytical.md 7)");
  add_deck(c, a.deck, "Any deck (default: the default [spire])");
  number_list(c, "phi", a.o.friction_angles_deg, "Friction angles, deg, e.g. 20,25,30 (default: the deck's)");
  number_list(c, "direction", a.o.directions_deg, "Azimuths of the static force from +x, deg, e.g. 0,22.5,90",
              "N[,N...]=0");
  number(c, "sides", a.sides, "Sides of the friction pyramid, 3 to 360");
  choice(c, "pyramid", a.pyramid, {"both", "circumscribed", "inscribed"}, "Friction pyramid");
  choice(c, "method", a.method, {"simplex", "interior"}, "GLPK's method");
  flag(c, "interfaces", a.interfaces, "List every opening or sliding interface");
  file(c, "write-lp", a.o.lp_file, "Write the last case's LP there (free MPS, for glpsol)");
  flag(c, "json", a.json, "One JSON object");
  return c;
}

int run_limit(LimitArgs& a) {
  const polydem::SceneSpec scene = polydem::analytic_scene(a.deck.deck, a.deck.no_windows);
  for (double phi : a.o.friction_angles_deg)
    if (!(phi >= 0.0 && phi < 90.0)) throw BadInput("--phi must be in [0, 90) degrees");
  if (a.deck.no_windows && !polydem::spire_of(scene.generators)) throw BadInput("--no-windows needs a deck with a [spire]");
  a.o.pyramid_sides = whole("sides", a.sides, 3, 360);
  a.o.pyramids = *polydem::friction_pyramids_named(a.pyramid);
  a.o.method = *polydem::lp_method_named(a.method);
  const polydem::LimitStudy study = polydem::limit_study(scene, a.o);
  if (a.json) print_json(polydem::limit_study_json(study));
  else polydem::report_limit_study(std::cout, study, a.interfaces);
  return 0;
}

struct ArchArgs {
  std::vector<double> voussoirs{9};
  polydem::ThinnestArchOptions o;
  bool json = false;
};

CLI::App* add_arch(CLI::App& app, ArchArgs& a) {
  auto* c = app.add_subcommand(
      "arch-thickness",
      "The thinnest semicircular arch of n voussoirs that can stand under its own weight (no tension, no sliding): "
      "the limit-analysis LP admits lambda = 0 iff it stands; bisection on t/R, R the centre-line radius "
      "(docs/structures.md; Milankovitch's continuous arch: 0.1075)");
  number_list(c, "voussoirs", a.voussoirs, "Voussoirs, 3 to 400, e.g. 9,17,33", "N[,N...]=9");
  number(c, "phi", a.o.friction_angle_deg, "Friction angle, deg, in (0, 90)");
  number(c, "tol", a.o.tolerance, "Bracket width on t/R to stop at, in [1e-9, 0.01]");
  flag(c, "json", a.json, "One JSON object");
  return c;
}

int run_arch(const ArchArgs& a) {
  std::vector<int> ns;
  for (double n : a.voussoirs) {
    if (n < 3 || n > 400 || n != std::floor(n)) throw BadInput("--voussoirs must be integers in [3, 400]");
    ns.push_back(static_cast<int>(n));
  }
  const double phi = a.o.friction_angle_deg, tol = a.o.tolerance;
  if (!(phi > 0 && phi < 90)) throw BadInput("--phi must be in (0, 90) degrees");
  if (!(tol >= 1e-9 && tol <= 0.01)) throw BadInput("--tol must be in [1e-9, 0.01]");
  if (!a.json) polydem::report_thinnest_arch_heading(std::cout, a.o);
  std::vector<polydem::ThinnestArch> arches;
  for (int n : ns) {
    arches.push_back(polydem::thinnest_arch(n, polydem::unit_semicircular_arch, a.o));
    if (!a.json) polydem::report_thinnest_arch(std::cout, arches.back());
  }
  if (a.json) print_json(polydem::thinnest_arch_json(a.o, arches));
  return 0;
}

}  // namespace

int run_analytic_command(const std::vector<std::string>& args) {
  CLI::App app{"The paper's closed-form and ODE models, and the limit analyses of the block model "
               "(docs/analytical.md). Lengths in m, accelerations in g unless named, times in s; "
               "options may be spelled with '-' or '_'.",
               "polydem analytic"};
  app.require_subcommand(1);
  LambdaArgs lambda;
  BeamArgs beam;
  RockingArgs rocking;
  CollapseArgs collapse;
  CrackedArgs cracked;
  RefinedArgs refined;
  DemArgs dem;
  LimitArgs limit;
  ArchArgs arch;
  CLI::App* lambda_cmd = add_lambda(app, lambda);
  CLI::App* beam_cmd = add_beam(app, beam);
  CLI::App* rocking_cmd = add_rocking(app, rocking);
  CLI::App* collapse_cmd = add_collapse(app, collapse);
  CLI::App* cracked_cmd = add_cracked(app, cracked);
  CLI::App* refined_cmd = add_refined(app, refined);
  CLI::App* dem_cmd = add_dem(app, dem);
  CLI::App* limit_cmd = add_limit(app, limit);
  CLI::App* arch_cmd = add_arch(app, arch);
  const AnalyticModel spectrum = add_spectrum_model(app);
  const std::function<int()> fragility = polydem::add_fragility_command(app);
  const std::function<int()> synthetic = polydem::add_synthetic_command(app);
  for (CLI::App* m : app.get_subcommands({})) m->allow_extras();

  std::vector<std::string> words(args.begin() + (!args.empty() && args[0] == "analytic" ? 1 : 0), args.end());
  if (words.empty()) {
    std::cout << app.help();
    return 2;
  }
  if (words[0] == "help") words[0] = "--help";
  const bool named = words[0].rfind('-', 0) != 0;
  const std::vector<CLI::App*> models = app.get_subcommands({});
  if (named && std::none_of(models.begin(), models.end(), [&](const CLI::App* m) { return m->get_name() == words[0]; })) {
    std::string names;
    for (const CLI::App* m : models) names += (names.empty() ? "" : ", ") + m->get_name();
    std::cerr << "polydem analytic: unknown model '" << words[0] << "' (expected " << names << ")\n";
    return 2;
  }
  const std::string where = named ? "polydem analytic " + words[0] + ": " : std::string("polydem analytic: ");
  try {
    std::reverse(words.begin(), words.end());  // CLI11 takes them last first
    app.parse(words);
    for (const CLI::App* m : app.get_subcommands()) reject_extras(m);
    if (lambda_cmd->parsed()) return run_lambda(lambda);
    if (beam_cmd->parsed()) return run_beam(beam);
    if (rocking_cmd->parsed()) return run_rocking(rocking);
    if (collapse_cmd->parsed()) return run_collapse(collapse);
    if (cracked_cmd->parsed()) return run_cracked(cracked);
    if (refined_cmd->parsed()) return run_refined(refined);
    if (dem_cmd->parsed()) return run_dem(dem);
    if (limit_cmd->parsed()) return run_limit(limit);
    if (arch_cmd->parsed()) return run_arch(arch);
    if (spectrum.command->parsed()) return spectrum.run();
    if (app.got_subcommand("fragility")) return fragility();
    if (app.got_subcommand("synthetic")) return synthetic();
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const std::exception& e) {  // CLI11's, bad values, deck and record errors (complete messages), failed runs
    std::cerr << where << e.what() << "\n";
  }
  return 2;
}
