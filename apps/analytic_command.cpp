#include "apps/analytic_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "analytical/analytical.hpp"
#include "analytical/refined_lambda.hpp"
#include "studies/dem_frequency.hpp"
#include "studies/limit_analysis.hpp"
#include "studies/standing.hpp"
#include "io/deck.hpp"

namespace pa = polydem::analytical;

namespace {

const char* kUsage = R"(usage: polydem analytic <model> [--key value ...] [--json]

models (lengths in m, accelerations in g unless named, times in s):
  lambda            static overturning, eq. 1-2
                    --r_b 1.06 --H 9.4 [--h_c H]
  beam              tapered-cantilever modes, eq. 3-6
                    --H 9.4 --r_b 1.06 --thickness 0.25 --E 30e9 [Pa] --density 2600 [kg/m3]
                    [--section circle|octagon (r_b is then the apothem)] [--modes 3]
  rocking           rocking response, eq. 7-10
                    body: --body block --b 0.2 --h 1.0 | --body shell|cone --r_b --H |
                          --body cracked --H_bar 4.1 [--H --r_b --tip 3.4 --thickness --density]
                    load: --load pulse --a_p 1.0 --T_p 1.0 | --load constant --a 0.2 |
                          --load record --file F (two columns: t [s], a [g]; uniform step)
                    [--dt 1e-3] [--t_end 20] [--linear] [--restitution c] [--print_every 0.1]
  collapse-diagram  one-sine pulse collapse curve (Zhang & Makris 2001)
                    body options as for rocking; --Tp_min 0.2 --Tp_max 3 --Tp_count 15
                    [--a_max 5] [--points 80] [--tol 1e-3] [--linear] [--restitution c]
  cracked-cone-p    p of the spire cracked below its solid tip vs the cracked height H_bar
                    [--H 9.4 --r_b 1.06 --tip 3.4 --thickness 0.25 --density 2600 --count 25]
  refined-lambda    static collapse multiplier of the block model (plane and stepped
                    cracks through a base pivot, 16 directions; docs/analytical.md 5)
                    [--deck FILE (its [spire]; default: the default [spire])] [--no-windows]
  dem-frequency     first natural frequency of the block model by a DEM free vibration,
                    against eq. 4 with E = kn * course height (docs/analytical.md 6)
                    [--deck FILE] [--no-windows] [--duration 0.5] [--settle 0.05]
                    [--pulse_g 0.005] [--pulse_period 0.02] [--interval 2e-4]
                    [--keep_damping] [--threads N] [--csv FILE (t, u of the tip)]
  limit-lp          friction-aware limit analysis of the block model: the rigid-block
                    equilibrium LP (no tension, Coulomb pyramid at the joints' vertices,
                    GLPK); the largest static horizontal force lambda m g (docs/analytical.md 7)
                    [--deck FILE (any deck; default: the default [spire])] [--no-windows]
                    [--phi 30 or 20,25,30 (deg; default: the deck's joint.friction_angle)]
                    [--direction 0 or 0,22.5,90 (deg: azimuth of the static force from +x)]
                    [--sides 16] [--pyramid both|circumscribed|inscribed] [--method interior|simplex]
                    [--interfaces (list every opening or sliding interface)]
                    [--write-lp FILE (the last case's LP, free MPS, for glpsol)]
  arch-thickness    the thinnest semicircular arch of n voussoirs that can stand under its
                    own weight (no tension, no sliding): the limit-analysis LP admits
                    lambda = 0 iff it stands; bisection on t/R, R the centre-line radius
                    (docs/structures.md; Milankovitch's continuous arch: 0.1075)
                    [--voussoirs 9 or 9,17,33] [--phi 85] [--tol 1e-5]
common: [--g 9.81] [--json]
)";

struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// --key value pairs; keys with '-' and '_' treated alike.
struct Options {
  std::map<std::string, std::string> values;
  std::set<std::string> flags;
  std::set<std::string> used;

  bool flag(const std::string& k) {
    used.insert(k);
    return flags.count(k) > 0;
  }
  bool has(const std::string& k) const { return values.count(k) > 0; }
  std::string text(const std::string& k, const std::string& def) {
    used.insert(k);
    auto it = values.find(k);
    return it == values.end() ? def : it->second;
  }
  double number(const std::string& k, double def) {
    used.insert(k);
    auto it = values.find(k);
    if (it == values.end()) return def;
    try {
      std::size_t pos = 0;
      const double v = std::stod(it->second, &pos);
      if (pos != it->second.size() || !std::isfinite(v)) throw std::invalid_argument("");
      return v;
    } catch (const std::exception&) {
      throw BadInput("--" + k + " expects a number, got '" + it->second + "'");
    }
  }
  double positive(const std::string& k, double def) {
    const double v = number(k, def);
    if (!(v > 0.0)) throw BadInput("--" + k + " must be > 0");
    return v;
  }
  void check_all_used() const {
    for (const auto& [k, v] : values)
      if (!used.count(k)) throw BadInput("unknown option --" + k);
    for (const auto& k : flags)
      if (!used.count(k)) throw BadInput("unknown option --" + k);
  }
};

const std::set<std::string> kFlags = {"json", "linear", "help", "no_windows", "keep_damping", "interfaces"};

std::string normalise(std::string k) {
  for (char& c : k)
    if (c == '-') c = '_';
  return k;
}

Options parse(const std::vector<std::string>& args, std::size_t first) {
  Options o;
  for (std::size_t i = first; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0 || a.size() < 3) throw BadInput("expected --key, got '" + a + "'");
    const std::string k = normalise(a.substr(2));
    if (kFlags.count(k)) { o.flags.insert(k); continue; }
    if (i + 1 >= args.size()) throw BadInput("--" + k + " needs a value");
    if (o.values.count(k)) throw BadInput("--" + k + " given twice");
    o.values[k] = args[++i];
  }
  return o;
}

// Numbers for JSON: finite with full precision, otherwise null.
std::string jnum(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

std::string jstr(const std::string& s) { return "\"" + s + "\""; }

std::string fmt(double v, int prec = 6) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", prec, v);
  return buf;
}

// ---------------------------------------------------------------- models

int model_lambda(Options& o) {
  const double r_b = o.positive("r_b", 1.06), H = o.positive("H", 9.4);
  const bool json = o.flag("json");
  const bool at = o.has("h_c");
  const double h_c = o.number("h_c", H);
  o.check_all_used();
  if (h_c < 0.0 || h_c > H) throw BadInput("--h_c must be in [0, H]");
  const double l1 = pa::lambda_cone(r_b, H);
  const auto gov = pa::governing_crack(r_b, H);
  const double l2 = pa::lambda_crack(r_b, H, h_c);
  if (json) {
    std::cout << "{\"model\":\"lambda\",\"inputs\":{\"r_b_m\":" << jnum(r_b) << ",\"H_m\":" << jnum(H)
              << ",\"h_c_m\":" << jnum(h_c) << "},\"lambda_eq1\":" << jnum(l1) << ",\"lambda_eq2_at_h_c\":" << jnum(l2)
              << ",\"lambda_eq2_governing\":" << jnum(gov.lambda) << ",\"h_c_governing_m\":" << jnum(gov.h_c) << "}\n";
    return 0;
  }
  std::cout << "static overturning of a conical shell (paper eq. 1-2)\n"
            << "  inputs   r_b = " << fmt(r_b) << " m, H = " << fmt(H) << " m\n"
            << "  eq. 1    lambda = 3 r_b / H                 = " << fmt(l1) << " g\n";
  if (at) std::cout << "  eq. 2    lambda at h_c = " << fmt(h_c) << " m      = " << fmt(l2) << " g\n";
  std::cout << "  eq. 2    governing lambda (min over h_c)  = " << fmt(gov.lambda) << " g at h_c = " << fmt(gov.h_c)
            << " m\n";
  return 0;
}

int model_beam(Options& o) {
  const double H = o.positive("H", 9.4), r_b = o.positive("r_b", 1.06), t = o.positive("thickness", 0.25);
  const double E = o.positive("E", 30e9), rho = o.positive("density", 2600.0);
  const std::string section = o.text("section", "circle");
  const double nm = o.number("modes", 3);
  const bool json = o.flag("json");
  o.check_all_used();
  if (nm < 1 || nm > 20 || nm != std::floor(nm)) throw BadInput("--modes must be an integer in [1, 20]");
  pa::ShellSection s;
  if (section == "circle") s = pa::hollow_circle_section(r_b, t, rho, E);
  else if (section == "octagon") s = pa::hollow_octagon_section(r_b, t, rho, E);
  else throw BadInput("--section must be circle or octagon");
  const auto om = pa::tapered_cantilever_omegas(static_cast<int>(nm));
  const auto ray = pa::rayleigh_minimum();
  if (json) {
    std::cout << "{\"model\":\"beam\",\"inputs\":{\"H_m\":" << jnum(H) << ",\"r_b_m\":" << jnum(r_b)
              << ",\"thickness_m\":" << jnum(t) << ",\"E_Pa\":" << jnum(E) << ",\"density_kg_m3\":" << jnum(rho)
              << ",\"section\":" << jstr(section) << "},\"m_b_kg_m\":" << jnum(s.mass_per_height)
              << ",\"I_b_m4\":" << jnum(s.second_moment) << ",\"EI_b_Nm2\":" << jnum(s.bending_stiffness) << ",\"modes\":[";
    for (std::size_t i = 0; i < om.size(); ++i)
      std::cout << (i ? "," : "") << "{\"n\":" << i + 1 << ",\"Omega\":" << jnum(om[i])
                << ",\"f_Hz\":" << jnum(pa::natural_frequency_hz(om[i], s.mass_per_height, s.bending_stiffness, H)) << "}";
    std::cout << "],\"rayleigh\":{\"k_min\":" << jnum(ray.k) << ",\"Omega\":" << jnum(ray.Omega) << ",\"f_Hz\":"
              << jnum(pa::natural_frequency_hz(ray.Omega, s.mass_per_height, s.bending_stiffness, H)) << "}}\n";
    return 0;
  }
  std::cout << "tapered cantilever m = (1-y/H) m_b, EI = (1-y/H)^3 EI_b (paper eq. 3-6)\n"
            << "  inputs   H = " << fmt(H) << " m, r_b = " << fmt(r_b) << " m (" << section << "), t = " << fmt(t)
            << " m, E = " << fmt(E) << " Pa, density = " << fmt(rho) << " kg/m3\n"
            << "  base     m_b = " << fmt(s.mass_per_height) << " kg/m, I_b = " << fmt(s.second_moment)
            << " m4, EI_b = " << fmt(s.bending_stiffness) << " N m2\n"
            << "  mode  Omega_n      f_n [Hz]\n";
  for (std::size_t i = 0; i < om.size(); ++i) {
    char line[128];
    std::snprintf(line, sizeof line, "  %4zu  %-11.6g  %.6g\n", i + 1, om[i],
                  pa::natural_frequency_hz(om[i], s.mass_per_height, s.bending_stiffness, H));
    std::cout << line;
  }
  std::cout << "  Rayleigh (eq. 5-6): k_min = " << fmt(ray.k) << ", Omega = " << fmt(ray.Omega) << ", f = "
            << fmt(pa::natural_frequency_hz(ray.Omega, s.mass_per_height, s.bending_stiffness, H)) << " Hz\n";
  return 0;
}

struct BodyChoice {
  pa::RockingBody body;
  std::string description;
  std::string json;
};

BodyChoice read_body(Options& o, double g) {
  const std::string kind = o.text("body", "shell");
  BodyChoice c;
  if (kind == "block") {
    const double b = o.positive("b", 0.2), h = o.positive("h", 1.0);
    c.body = pa::rectangular_block(b, h, 1.0, g);
    c.description = "rectangular block, half-width b = " + fmt(b) + " m, half-height h = " + fmt(h) + " m";
    c.json = "{\"kind\":\"block\",\"b_m\":" + jnum(b) + ",\"h_m\":" + jnum(h) + "}";
  } else if (kind == "shell" || kind == "cone") {
    const double r_b = o.positive("r_b", 1.06), H = o.positive("H", 9.4);
    c.body = kind == "shell" ? pa::conical_shell(r_b, H, 1.0, g) : pa::solid_cone(r_b, H, 1.0, g);
    c.description = (kind == "shell" ? "conical shell (eq. 8)" : "solid cone") + std::string(", r_b = ") + fmt(r_b) +
                    " m, H = " + fmt(H) + " m";
    c.json = "{\"kind\":" + jstr(kind) + ",\"r_b_m\":" + jnum(r_b) + ",\"H_m\":" + jnum(H) + "}";
  } else if (kind == "cracked") {
    pa::SpireGeometry s;
    s.H = o.positive("H", s.H);
    s.r_b = o.positive("r_b", s.r_b);
    s.tip_height = o.positive("tip", s.tip_height);
    s.wall_thickness = o.positive("thickness", s.wall_thickness);
    s.density = o.positive("density", s.density);
    const double hb = o.positive("H_bar", s.tip_height);
    c.body = pa::cracked_spire_body(s, hb, g);
    c.description = "cracked spire, H_bar = " + fmt(hb) + " m (H = " + fmt(s.H) + " m, r_b = " + fmt(s.r_b) +
                    " m, solid tip " + fmt(s.tip_height) + " m, wall " + fmt(s.wall_thickness) + " m)";
    c.json = "{\"kind\":\"cracked\",\"H_bar_m\":" + jnum(hb) + ",\"H_m\":" + jnum(s.H) + ",\"r_b_m\":" + jnum(s.r_b) +
             ",\"tip_m\":" + jnum(s.tip_height) + ",\"thickness_m\":" + jnum(s.wall_thickness) +
             ",\"density_kg_m3\":" + jnum(s.density) + "}";
  } else {
    throw BadInput("--body must be block, shell, cone or cracked");
  }
  return c;
}

std::string body_json(const pa::RockingBody& b) {
  return "{\"R_m\":" + jnum(b.R) + ",\"alpha_rad\":" + jnum(b.alpha) + ",\"p_rad_s\":" + jnum(b.p) +
         ",\"I0_over_M_m2\":" + jnum(b.I0 / b.mass) + ",\"restitution\":" + jnum(b.restitution) +
         ",\"uplift_g\":" + jnum(std::tan(b.alpha)) + "}";
}

void print_body(const BodyChoice& c) {
  const auto& b = c.body;
  std::cout << "  body     " << c.description << "\n"
            << "           R = " << fmt(b.R) << " m, alpha = " << fmt(b.alpha) << " rad, I0/M = " << fmt(b.I0 / b.mass)
            << " m2, p = " << fmt(b.p) << " rad/s, c (eq. 10) = " << fmt(b.restitution)
            << ", uplift at tan(alpha) = " << fmt(std::tan(b.alpha)) << " g\n";
}

pa::GroundMotion read_record(const std::string& path, double g, std::string& note) {
  std::ifstream in(path);
  if (!in) throw BadInput("cannot open record file '" + path + "'");
  std::vector<double> t, a;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    for (char& ch : line)
      if (ch == ',' || ch == ';' || ch == '\t') ch = ' ';
    if (line.find_first_not_of(" \r") == std::string::npos || line[line.find_first_not_of(' ')] == '#') continue;
    std::istringstream ls(line);
    double ti, ai;
    if (!(ls >> ti >> ai)) {
      if (t.empty()) continue;  // a header line
      throw BadInput(path + ":" + std::to_string(lineno) + ": expected two numbers (t [s], a [g])");
    }
    t.push_back(ti);
    a.push_back(ai * g);
  }
  if (t.size() < 2) throw BadInput(path + ": needs at least two samples");
  const double dt = t[1] - t[0];
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(std::abs(t[i] - t[i - 1] - dt) <= 1e-6 * dt) || !(dt > 0.0))
      throw BadInput(path + ": time step must be uniform and positive");
  if (t[0] != 0.0) note = " (record shifted to start at t = 0)";
  return pa::sampled_ground_motion(dt, std::move(a));
}

int model_rocking(Options& o) {
  const double g = o.positive("g", pa::standard_gravity);
  const bool json = o.flag("json");
  const BodyChoice bc = read_body(o, g);
  const std::string load = o.text("load", "pulse");
  pa::GroundMotion gm;
  std::string load_text, load_json, note;
  if (load == "pulse") {
    const double ap = o.number("a_p", 1.0), Tp = o.positive("T_p", 1.0);
    gm = pa::sine_pulse_ground_motion(ap * g, Tp);
    load_text = "one-sine pulse a_p = " + fmt(ap) + " g, T_p = " + fmt(Tp) + " s";
    load_json = "{\"kind\":\"pulse\",\"a_p_g\":" + jnum(ap) + ",\"T_p_s\":" + jnum(Tp) + "}";
  } else if (load == "constant") {
    const double a = o.number("a", 0.2);
    gm = pa::constant_ground_motion(a * g);
    load_text = "constant a = " + fmt(a) + " g";
    load_json = "{\"kind\":\"constant\",\"a_g\":" + jnum(a) + "}";
  } else if (load == "record") {
    const std::string file = o.text("file", "");
    if (file.empty()) throw BadInput("--load record needs --file");
    gm = read_record(file, g, note);
    load_text = "record " + file + note;
    load_json = "{\"kind\":\"record\",\"file\":" + jstr(file) + "}";
  } else {
    throw BadInput("--load must be pulse, constant or record");
  }
  pa::RockingOptions ro;
  ro.g = g;
  ro.dt = o.positive("dt", 1e-3);
  ro.t_end = o.positive("t_end", 20.0);
  if (o.flag("linear")) ro.form = pa::RockingForm::linearised;
  if (o.has("restitution")) ro.restitution = o.number("restitution", 0.0);
  const double every = o.positive("print_every", 0.1);
  ro.record_history = true;
  o.check_all_used();
  const auto r = pa::simulate_rocking(bc.body, gm, ro);

  if (json) {
    std::cout << "{\"model\":\"rocking\",\"body\":" << bc.json << ",\"properties\":" << body_json(bc.body)
              << ",\"load\":" << load_json << ",\"form\":" << jstr(ro.form == pa::RockingForm::linearised ? "eq9" : "eq7")
              << ",\"dt_s\":" << jnum(ro.dt) << ",\"uplifted\":" << (r.uplifted ? "true" : "false")
              << ",\"t_uplift_s\":" << (r.uplifted ? jnum(r.t_uplift) : "null")
              << ",\"overturned\":" << (r.overturned ? "true" : "false") << ",\"mode\":" << jstr(pa::to_string(r.mode))
              << ",\"t_overturn_s\":" << (r.overturned ? jnum(r.t_overturn) : "null") << ",\"impacts\":" << r.impacts
              << ",\"max_abs_theta_rad\":" << jnum(r.max_abs_theta) << ",\"t_final_s\":" << jnum(r.t_final)
              << ",\"impact_times_s\":[";
    for (std::size_t i = 0; i < r.impact_times.size(); ++i) std::cout << (i ? "," : "") << jnum(r.impact_times[i]);
    std::cout << "],\"history\":[";
    double next = 0.0;
    bool first = true;
    for (const auto& s : r.history) {
      if (s.t + 1e-12 < next && &s != &r.history.back()) continue;
      next = s.t + every;
      std::cout << (first ? "" : ",") << "[" << jnum(s.t) << "," << jnum(s.theta) << "," << jnum(s.omega) << ","
                << jnum(s.a_g / g) << "]";
      first = false;
    }
    std::cout << "],\"history_columns\":[\"t_s\",\"theta_rad\",\"omega_rad_s\",\"a_g_g\"]}\n";
    return 0;
  }
  std::cout << "rocking on a rigid base (paper eq. 7" << (ro.form == pa::RockingForm::linearised ? "/9" : "")
            << ", restitution eq. 10)\n";
  print_body(bc);
  std::cout << "  load     " << load_text << "\n"
            << "  step     RK4 dt = " << fmt(ro.dt) << " s, t_end = " << fmt(ro.t_end) << " s, c used = "
            << fmt(ro.restitution.value_or(bc.body.restitution)) << "\n"
            << "  result   uplift " << (r.uplifted ? "at t = " + fmt(r.t_uplift) + " s" : std::string("never")) << ", "
            << r.impacts << " impacts, max |theta| = " << fmt(r.max_abs_theta) << " rad ("
            << fmt(r.max_abs_theta / bc.body.alpha, 4) << " alpha), "
            << (r.overturned ? "OVERTURNED (" + std::string(pa::to_string(r.mode)) + ") at t = " + fmt(r.t_overturn) + " s"
                             : std::string("no overturning"))
            << ", stopped at t = " << fmt(r.t_final) << " s\n"
            << "  t [s]        theta [rad]     omega [rad/s]   a_g [g]\n";
  double next = 0.0;
  for (const auto& s : r.history) {
    if (s.t + 1e-12 < next && &s != &r.history.back()) continue;
    next = s.t + every;
    char line[160];
    std::snprintf(line, sizeof line, "  %-11.5f  %-14.6e  %-14.6e  %.5f\n", s.t, s.theta, s.omega, s.a_g / g);
    std::cout << line;
  }
  return 0;
}

int model_collapse(Options& o) {
  const double g = o.positive("g", pa::standard_gravity);
  const bool json = o.flag("json");
  const BodyChoice bc = read_body(o, g);
  const double t0 = o.positive("Tp_min", 0.2), t1 = o.positive("Tp_max", 3.0);
  const double cnt = o.number("Tp_count", 15);
  pa::CollapseScanOptions so;
  so.g = g;
  so.a_max_g = o.positive("a_max", 5.0);
  const double pts = o.number("points", 80);
  so.tolerance_g = o.positive("tol", 1e-3);
  if (o.flag("linear")) so.form = pa::RockingForm::linearised;
  if (o.has("restitution")) so.restitution = o.number("restitution", 0.0);
  o.check_all_used();
  if (cnt < 1 || cnt > 1000 || cnt != std::floor(cnt)) throw BadInput("--Tp_count must be an integer in [1, 1000]");
  if (pts < 2 || pts > 10000 || pts != std::floor(pts)) throw BadInput("--points must be an integer in [2, 10000]");
  if (t1 < t0) throw BadInput("--Tp_max must be >= --Tp_min");
  so.coarse_points = static_cast<int>(pts);
  std::vector<double> Ts;
  const int n = static_cast<int>(cnt);
  for (int i = 0; i < n; ++i) Ts.push_back(n == 1 ? t0 : t0 + (t1 - t0) * i / (n - 1));
  const auto cols = pa::collapse_diagram(bc.body, Ts, so);

  if (json) {
    std::cout << "{\"model\":\"collapse-diagram\",\"body\":" << bc.json << ",\"properties\":" << body_json(bc.body)
              << ",\"a_max_g\":" << jnum(so.a_max_g) << ",\"tolerance_g\":" << jnum(so.tolerance_g) << ",\"columns\":[";
    for (std::size_t i = 0; i < cols.size(); ++i) {
      const auto& c = cols[i];
      std::cout << (i ? "," : "") << "{\"T_p_s\":" << jnum(c.T_p) << ",\"omega_p_over_p\":" << jnum(c.omega_ratio)
                << ",\"min_collapse_g\":" << jnum(c.min_collapse_g) << ",\"mode2_boundary_g\":" << jnum(c.mode2_boundary_g)
                << ",\"mode1_intervals_g\":[";
      for (std::size_t k = 0; k < c.mode1_intervals.size(); ++k)
        std::cout << (k ? "," : "") << "[" << jnum(c.mode1_intervals[k].first) << "," << jnum(c.mode1_intervals[k].second)
                  << "]";
      std::cout << "],\"transitions\":[";
      for (std::size_t k = 0; k < c.transitions.size(); ++k)
        std::cout << (k ? "," : "") << "{\"a_g\":" << jnum(c.transitions[k].a_g) << ",\"below\":"
                  << jstr(pa::to_string(c.transitions[k].below)) << ",\"above\":"
                  << jstr(pa::to_string(c.transitions[k].above)) << "}";
      std::cout << "]}";
    }
    std::cout << "]}\n";
    return 0;
  }
  std::cout << "collapse diagram for one-sine pulses a_p sin(2 pi t / T_p) (Zhang & Makris 2001)\n";
  print_body(bc);
  std::cout << "  scan     a_p from tan(alpha) to " << fmt(so.a_max_g) << " g, " << so.coarse_points
            << " points, transitions to " << fmt(so.tolerance_g) << " g\n"
            << "  T_p [s]   w_p/p    min collapse [g]  Mode II from [g]  Mode I regions [g]\n";
  for (const auto& c : cols) {
    std::ostringstream intervals;  // (not string + chains: g++ 12 warns falsely on them at -O2)
    for (const auto& [lo, hi] : c.mode1_intervals) intervals << '[' << fmt(lo, 4) << ", " << fmt(hi, 4) << "] ";
    const std::string m1 = intervals.str();
    char line[200];
    std::snprintf(line, sizeof line, "  %-8.4g  %-7.4g  %-16s  %-16s  %s\n", c.T_p, c.omega_ratio,
                  fmt(c.min_collapse_g, 5).c_str(), fmt(c.mode2_boundary_g, 5).c_str(), m1.empty() ? "-" : m1.c_str());
    std::cout << line;
  }
  return 0;
}

int model_cracked(Options& o) {
  const double g = o.positive("g", pa::standard_gravity);
  const bool json = o.flag("json");
  pa::SpireGeometry s;
  s.H = o.positive("H", s.H);
  s.r_b = o.positive("r_b", s.r_b);
  s.tip_height = o.positive("tip", s.tip_height);
  s.wall_thickness = o.positive("thickness", s.wall_thickness);
  s.density = o.positive("density", s.density);
  const double cnt = o.number("count", 25);
  o.check_all_used();
  if (cnt < 2 || cnt > 10000 || cnt != std::floor(cnt)) throw BadInput("--count must be an integer in [2, 10000]");
  const int n = static_cast<int>(cnt);
  const auto mx = pa::cracked_spire_p_max(s, g);
  if (json) {
    std::cout << "{\"model\":\"cracked-cone-p\",\"inputs\":{\"H_m\":" << jnum(s.H) << ",\"r_b_m\":" << jnum(s.r_b)
              << ",\"tip_m\":" << jnum(s.tip_height) << ",\"thickness_m\":" << jnum(s.wall_thickness)
              << ",\"density_kg_m3\":" << jnum(s.density) << "},\"p_max_rad_s\":" << jnum(mx.p)
              << ",\"H_bar_at_p_max_m\":" << jnum(mx.H_bar) << ",\"curve\":[";
    for (int i = 0; i < n; ++i) {
      const double hb = s.tip_height + (s.H - s.tip_height) * i / (n - 1);
      const auto b = pa::cracked_spire_body(s, hb, g);
      std::cout << (i ? "," : "") << "{\"H_bar_m\":" << jnum(hb) << ",\"p_rad_s\":" << jnum(b.p)
                << ",\"mass_kg\":" << jnum(b.mass) << ",\"R_m\":" << jnum(b.R) << ",\"alpha_rad\":" << jnum(b.alpha) << "}";
    }
    std::cout << "]}\n";
    return 0;
  }
  std::cout << "p of the spire cracked just below its solid tip, vs cracked height H_bar (paper Fig. 7a)\n"
            << "  inputs   H = " << fmt(s.H) << " m, r_b = " << fmt(s.r_b) << " m, solid tip " << fmt(s.tip_height)
            << " m, wall " << fmt(s.wall_thickness) << " m, density " << fmt(s.density) << " kg/m3, g = " << fmt(g)
            << " m/s2\n"
            << "  H_bar [m]  p [rad/s]  mass [kg]    R [m]     alpha [rad]\n";
  for (int i = 0; i < n; ++i) {
    const double hb = s.tip_height + (s.H - s.tip_height) * i / (n - 1);
    const auto b = pa::cracked_spire_body(s, hb, g);
    char line[160];
    std::snprintf(line, sizeof line, "  %-9.4f  %-9.5f  %-11.5g  %-8.5f  %.5f\n", hb, b.p, b.mass, b.R, b.alpha);
    std::cout << line;
  }
  std::cout << "  max p = " << fmt(mx.p) << " rad/s at H_bar = " << fmt(mx.H_bar) << " m\n";
  return 0;
}

// The spire scene of --deck (or the default [spire]), windows removed on
// --no-windows.
polydem::SceneSpec spire_scene(Options& o) {
  const std::string deck = o.text("deck", "");
  std::vector<std::string> overrides;
  if (o.flag("no_windows")) overrides.push_back("spire.window_faces=[]");
  polydem::SceneSpec s = deck.empty() ? polydem::parse_deck("[spire]\n", "<default [spire]>", overrides)
                                      : polydem::read_deck(deck, overrides);
  if (!s.spire) throw BadInput("the deck " + deck + " has no [spire]");
  return s;
}

double spire_density(const polydem::SceneSpec& s, const polydem::SpireModel& m) {
  for (const auto& sb : m.blocks)
    for (const auto& b : s.blocks)
      if (b.name == sb.name && sb.kind != polydem::SpireBlockKind::base) return b.density;
  return 2600.0;
}

std::string crack_text(const pa::Mechanism& m) {
  char buf[200];
  if (m.family != pa::CrackFamily::stepped) {
    std::snprintf(buf, sizeof buf, "beta in (%.2f, %.2f] deg", m.beta_low * 180.0 / std::numbers::pi, m.beta_high * 180.0 / std::numbers::pi);
    return buf;
  }
  std::string s = "trailing course " + std::to_string(m.trailing_course) + ", first course per face";
  for (std::size_t k = 0; k < m.face_course.size(); ++k) {
    s += k ? ',' : ' ';
    s += std::to_string(m.face_course[k]);
  }
  return s;
}

std::string mechanism_json(const pa::Mechanism& m) {
  std::string s = "{\"direction\":" + jstr(m.direction.name) + ",\"azimuth_rad\":" + jnum(m.direction.azimuth) +
                  ",\"family\":" + jstr(pa::to_string(m.family)) + ",\"lambda\":" + jnum(m.lambda) +
                  ",\"blocks\":" + std::to_string(m.blocks.size()) + ",\"mass_kg\":" + jnum(m.mass) +
                  ",\"centroid_m\":[" + jnum(m.centroid.x()) + "," + jnum(m.centroid.y()) + "," + jnum(m.centroid.z()) +
                  "],\"pivot_m\":[" + jnum(m.pivot.x()) + "," + jnum(m.pivot.y()) + "," + jnum(m.pivot.z()) + "]";
  if (m.family != pa::CrackFamily::stepped) {
    s += ",\"beta_low_rad\":" + jnum(m.beta_low) + ",\"beta_high_rad\":" + jnum(m.beta_high);
  } else {
    s += ",\"trailing_course\":" + std::to_string(m.trailing_course) + ",\"face_course\":[";
    for (std::size_t k = 0; k < m.face_course.size(); ++k) {
      if (k) s += ',';
      s += std::to_string(m.face_course[k]);
    }
    s += "]";
  }
  return s + "}";
}

int model_refined(Options& o) {
  const bool json = o.flag("json");
  const double g = o.positive("g", pa::standard_gravity);
  const polydem::SceneSpec scene = spire_scene(o);
  o.check_all_used();
  const polydem::SpireModel model = polydem::build_spire(*scene.spire);
  const double rho = spire_density(scene, model);
  pa::RefinedLambdaOptions opt;
  opt.g = g;
  const auto r = pa::refined_lambda(model, rho, opt);
  const auto& sp = *scene.spire;
  const double l1 = pa::lambda_cone(sp.base_inradius, sp.height);
  const auto l2 = pa::governing_crack(sp.base_inradius, sp.height);
  const std::string src = scene.deck_path;
  if (json) {
    std::cout << "{\"model\":\"refined-lambda\",\"deck\":" << jstr(src) << ",\"blocks\":" << model.blocks.size()
              << ",\"courses\":" << model.n_courses << ",\"windows\":" << sp.window_faces.size()
              << ",\"density_kg_m3\":" << jnum(rho) << ",\"total_mass_kg\":" << jnum(r.total_mass)
              << ",\"candidates\":" << r.candidates << ",\"lambda_eq1\":" << jnum(l1)
              << ",\"lambda_eq2\":" << jnum(l2.lambda) << ",\"lambda_refined\":" << jnum(r.governing.lambda)
              << ",\"governing\":" << mechanism_json(r.governing) << ",\"plane\":[";
    for (std::size_t i = 0; i < r.plane.size(); ++i) std::cout << (i ? "," : "") << mechanism_json(r.plane[i]);
    std::cout << "],\"plane_cover\":[";
    for (std::size_t i = 0; i < r.plane_cover.size(); ++i) std::cout << (i ? "," : "") << mechanism_json(r.plane_cover[i]);
    std::cout << "],\"stepped\":[";
    for (std::size_t i = 0; i < r.stepped.size(); ++i) std::cout << (i ? "," : "") << mechanism_json(r.stepped[i]);
    std::cout << "]}\n";
    return 0;
  }
  std::cout << "refined static lambda on the block model (rigid part above a crack, pivot on the base)\n"
            << "  spire    " << src << ": H = " << fmt(sp.height) << " m, r_b = " << fmt(sp.base_inradius)
            << " m (mid-wall apothem), " << model.blocks.size() << " blocks, " << model.n_courses << " courses, "
            << sp.window_faces.size() << " windows, density " << fmt(rho) << " kg/m3, free mass "
            << fmt(r.total_mass) << " kg\n"
            << "  direction = of the equivalent static force; the pivot is the base edge/corner that way\n"
            << "  direction    family       lambda     blocks  mass [kg]   crack\n";
  for (std::size_t i = 0; i < r.plane.size(); ++i)
    for (const auto* m : {&r.plane[i], &r.plane_cover[i], &r.stepped[i]}) {
      char line[320];
      std::snprintf(line, sizeof line, "  %-11s  %-11s  %-9.5f  %-6zu  %-10.1f  %s\n", m->direction.name.c_str(),
                    pa::to_string(m->family), m->lambda, m->blocks.size(), m->mass, crack_text(*m).c_str());
      std::cout << line;
    }
  std::cout << "  eq. 1 lambda = " << fmt(l1) << ", eq. 2 governing = " << fmt(l2.lambda) << " (r_b, H of the spire)\n"
            << "  refined lambda = " << fmt(r.governing.lambda) << ": " << r.governing.direction.name << ", "
            << pa::to_string(r.governing.family) << " crack, " << crack_text(r.governing) << ", "
            << r.governing.blocks.size() << " blocks, " << fmt(r.governing.mass) << " kg ("
            << r.candidates << " mechanisms evaluated)\n";
  return 0;
}

int model_dem_frequency(Options& o) {
  const bool json = o.flag("json");
  polydem::DemFrequencyOptions d;
  d.duration = o.positive("duration", d.duration);
  d.settle_time = o.number("settle", d.settle_time);
  d.pulse_g = o.positive("pulse_g", d.pulse_g);
  d.pulse_period = o.positive("pulse_period", d.pulse_period);
  d.history_interval = o.positive("interval", d.history_interval);
  d.keep_damping = o.flag("keep_damping");
  const double th = o.number("threads", 0);
  d.threads = static_cast<int>(th);
  const std::string csv = o.text("csv", "");
  const polydem::SceneSpec scene = spire_scene(o);
  o.check_all_used();
  if (d.settle_time < 0) throw BadInput("--settle must be >= 0");
  const auto r = polydem::measure_dem_frequency(scene, d);
  if (!csv.empty()) {
    std::ofstream f(csv);
    if (!f) throw BadInput("cannot write " + csv);
    f << "t_s,u_m\n";
    char line[96];
    for (std::size_t i = 0; i < r.t.size(); ++i) {
      std::snprintf(line, sizeof line, "%.9g,%.9g\n", r.t[i], r.u[i]);
      f << line;
    }
  }
  const double ratio = r.f_beam_hz > 0 ? r.f_fourier_hz / r.f_beam_hz : 0.0;
  if (json) {
    std::cout << "{\"model\":\"dem-frequency\",\"deck\":" << jstr(scene.deck_path) << ",\"tip\":" << jstr(r.tip)
              << ",\"blocks\":" << r.blocks << ",\"windows\":" << scene.spire->window_faces.size()
              << ",\"damping_s\":" << jnum(d.keep_damping ? scene.joint.damping : 0.0)
              << ",\"pulse_g\":" << jnum(d.pulse_g) << ",\"pulse_period_s\":" << jnum(d.pulse_period)
              << ",\"settle_s\":" << jnum(d.settle_time) << ",\"duration_s\":" << jnum(d.duration)
              << ",\"status\":" << jstr(r.status) << ",\"unstable\":" << (r.unstable ? "true" : "false")
              << ",\"steps\":" << r.steps << ",\"time_step_s\":" << jnum(r.time_step)
              << ",\"wall_s\":" << jnum(r.wall_seconds) << ",\"samples\":" << r.samples
              << ",\"amplitude_m\":" << jnum(r.amplitude_m) << ",\"f_dem_fourier_Hz\":" << jnum(r.f_fourier_hz)
              << ",\"f_dem_zero_crossing_Hz\":" << jnum(r.f_zero_crossing_hz)
              << ",\"zero_crossings\":" << r.zero_crossings << ",\"kn_Pa_m\":" << jnum(r.kn)
              << ",\"course_height_m\":" << jnum(r.course_height) << ",\"E_eq_Pa\":" << jnum(r.E_eq)
              << ",\"outer_apothem_m\":" << jnum(r.outer_apothem) << ",\"thickness_m\":" << jnum(r.wall_thickness)
              << ",\"m_b_kg_m\":" << jnum(r.section.mass_per_height)
              << ",\"EI_b_Nm2\":" << jnum(r.section.bending_stiffness) << ",\"Omega1\":" << jnum(r.Omega1)
              << ",\"f_beam_Hz\":" << jnum(r.f_beam_hz) << ",\"ratio_dem_to_beam\":" << jnum(ratio) << "}\n";
    return r.unstable ? 1 : 0;
  }
  std::cout << "first natural frequency of the block model, DEM free vibration against eq. 4\n"
            << "  spire    " << scene.deck_path << ": " << r.blocks << " blocks, " << scene.spire->window_faces.size()
            << " windows, tip block '" << r.tip << "'\n"
            << "  run      gravity, joint damping " << (d.keep_damping ? fmt(scene.joint.damping) : std::string("0"))
            << " s, sine pulse " << fmt(d.pulse_g) << " g x " << fmt(d.pulse_period) << " s at t = "
            << fmt(d.settle_time) << " s, free vibration " << fmt(d.duration) << " s; " << r.steps
            << " steps of " << fmt(r.time_step) << " s, " << fmt(r.wall_seconds, 3) << " s wall, status " << r.status
            << (r.unstable ? " (UNSTABLE: " + r.instability + ")" : std::string()) << "\n"
            << "  DEM      tip amplitude " << fmt(r.amplitude_m) << " m; f = " << fmt(r.f_fourier_hz)
            << " Hz (Fourier peak), " << fmt(r.f_zero_crossing_hz) << " Hz (" << r.zero_crossings
            << " zero crossings)\n"
            << "  beam     E_eq = kn h = " << fmt(r.kn) << " Pa/m x " << fmt(r.course_height) << " m = " << fmt(r.E_eq)
            << " Pa; hollow octagon a_out = " << fmt(r.outer_apothem) << " m, t = " << fmt(r.wall_thickness)
            << " m: m_b = " << fmt(r.section.mass_per_height) << " kg/m, EI_b = " << fmt(r.section.bending_stiffness)
            << " N m2; Omega1 = " << fmt(r.Omega1) << ", H = " << fmt(r.height) << " m: f = " << fmt(r.f_beam_hz)
            << " Hz\n"
            << "  ratio    DEM / beam = " << fmt(ratio, 4) << "\n";
  return r.unstable ? 1 : 0;
}

// Comma-separated numbers of --key ("20,25,30").
std::vector<double> number_list(Options& o, const std::string& k, double def) {
  if (!o.has(k)) {
    o.used.insert(k);
    return {def};
  }
  const std::string text = o.text(k, "");
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    try {
      std::size_t pos = 0;
      const double v = std::stod(item, &pos);
      if (pos != item.size() || !std::isfinite(v)) throw std::invalid_argument("");
      out.push_back(v);
    } catch (const std::exception&) {
      throw BadInput("--" + k + " expects numbers separated by commas, got '" + text + "'");
    }
    start = comma + 1;
  }
  return out;
}

struct LimitCase {
  double direction_deg = 0, phi_deg = 0;
  std::vector<polydem::LimitAnalysisResult> results;  // one per pyramid asked
};

std::string limit_result_json(const polydem::LimitModel& model, const polydem::LimitAnalysisResult& r) {
  std::ostringstream s;
  const auto& m = r.mechanism;
  s << "{\"status\":" << jstr(polydem::to_string(r.status)) << ",\"lambda\":" << jnum(r.lambda)
    << ",\"generator_mu\":" << jnum(r.generator_mu) << ",\"rows\":" << r.rows << ",\"columns\":" << r.columns
    << ",\"nonzeros\":" << r.nonzeros << ",\"build_s\":" << jnum(r.build_seconds)
    << ",\"solve_s\":" << jnum(r.solve_seconds) << ",\"primal_residual\":" << jnum(r.primal_residual)
    << ",\"dual_residual\":" << jnum(r.dual_residual);
  if (r.status == polydem::LimitStatus::optimal) {
    s << ",\"mechanism\":{\"blocks_moving\":" << m.blocks_moving << ",\"mass_moving_kg\":" << jnum(m.mass_moving)
      << ",\"opening\":" << m.opening << ",\"opening_bed\":" << m.opening_bed << ",\"sliding\":" << m.sliding
      << ",\"sliding_bed\":" << m.sliding_bed << ",\"moving_blocks\":[";
    bool first = true;
    for (std::size_t i = 0; i < m.moving.size(); ++i)
      if (m.moving[i]) {
        const auto& v = m.velocity[i];
        const auto& w = m.angular_velocity[i];
        s << (first ? "" : ",") << "{\"name\":" << jstr(model.names[i]) << ",\"speed\":" << jnum(m.speed[i])
          << ",\"velocity\":[" << jnum(v.x()) << "," << jnum(v.y()) << "," << jnum(v.z()) << "],\"angular_velocity\":["
          << jnum(w.x()) << "," << jnum(w.y()) << "," << jnum(w.z()) << "]}";
        first = false;
      }
    s << "],\"interfaces\":[";
    first = true;
    for (std::size_t q = 0; q < m.motion.size(); ++q) {
      if (m.motion[q] == polydem::InterfaceMotion::closed) continue;
      const auto& f = model.interfaces[q];
      s << (first ? "" : ",") << "{\"blocks\":[" << jstr(model.names[f.ref]) << "," << jstr(model.names[f.inc])
        << "],\"bed\":" << (f.bed ? "true" : "false") << ",\"motion\":" << jstr(polydem::to_string(m.motion[q]))
        << ",\"normal\":[" << jnum(f.normal.x()) << "," << jnum(f.normal.y()) << "," << jnum(f.normal.z()) << "]}";
      first = false;
    }
    s << "]}";
  }
  s << "}";
  return s.str();
}

std::string mechanism_text(const polydem::LimitAnalysisResult& r) {
  if (r.status == polydem::LimitStatus::failed && r.primal_residual + r.dual_residual > 0) {
    std::ostringstream s;
    s << "failed: the solution misses the check (equilibrium residual " << fmt(r.primal_residual, 3)
      << ", mechanism residual " << fmt(r.dual_residual, 3) << ", limit 1e-5)";
    return s.str();
  }
  if (r.status != polydem::LimitStatus::optimal) return polydem::to_string(r.status);
  const auto& m = r.mechanism;
  std::ostringstream s;
  s << m.blocks_moving << " blocks (" << fmt(m.mass_moving, 5) << " kg) moving; interfaces opening " << m.opening
    << " (" << m.opening_bed << " bed), sliding " << m.sliding << " (" << m.sliding_bed << " bed)";
  return s.str();
}

// The thinnest standing semicircle (studies/standing.hpp) per voussoir count:
// centre-line radius 1 m, intrados radius 1 − t/2, on a fixed base.
int model_arch_thickness(Options& o) {
  const bool json = o.flag("json");
  const std::vector<double> ns = number_list(o, "voussoirs", 9);
  const double phi = o.number("phi", 85.0);
  const double tol = o.number("tol", 1e-5);
  o.check_all_used();
  for (double n : ns)
    if (n < 3 || n > 400 || n != std::floor(n)) throw BadInput("--voussoirs must be integers in [3, 400]");
  if (!(phi > 0 && phi < 90)) throw BadInput("--phi must be in (0, 90) degrees");
  if (!(tol >= 1e-9 && tol <= 0.01)) throw BadInput("--tol must be in [1e-9, 0.01]");
  polydem::LimitAnalysisOptions opt;
  opt.friction_angle_deg = phi;
  opt.method = polydem::LpMethod::simplex;
  if (json) std::cout << "{\"model\":\"arch-thickness\",\"phi_deg\":" << jnum(phi) << ",\"cases\":[";
  else std::cout << "thinnest semicircular arch under self-weight (limit-analysis LP, phi = " << fmt(phi)
                 << " deg): t/R, R the centre-line radius; Milankovitch (continuous): 0.1075\n"
                 << "  voussoirs   t/R        vs 0.1075   trials   seconds\n";
  for (std::size_t k = 0; k < ns.size(); ++k) {
    const int n = static_cast<int>(ns[k]);
    auto scene_at = [n](double eta) {
      std::ostringstream d;
      d.precision(17);
      d << "[[arch]]\nradius = " << 1.0 - 0.5 * eta << "\nthickness = " << eta << "\nvoussoirs = " << n
        << "\ndepth = 1\nsupports = \"base\"\n";
      return polydem::parse_deck(d.str(), "<arch-thickness>");
    };
    const auto start = std::chrono::steady_clock::now();
    polydem::ThinnestStanding r;
    try {
      r = polydem::thinnest_standing(scene_at, 0.001, 0.6, tol, opt);
    } catch (const std::invalid_argument&) {
      // It stands at t/R = 0.001 (few voussoirs: an equilibrium of the
      // hinged chain through the joints' points exists however thin).
      r.falls = 0.0;
      r.stands = 0.001;
      r.trials = 1;
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (json)
      std::cout << (k ? "," : "") << "{\"voussoirs\":" << n << ",\"t_over_R\":" << jnum(r.threshold())
                << ",\"falls\":" << jnum(r.falls) << ",\"stands\":" << jnum(r.stands) << ",\"trials\":" << r.trials
                << ",\"seconds\":" << jnum(s) << "}";
    else {
      char line[160];
      if (r.falls == 0.0)
        std::snprintf(line, sizeof line, "  %9d   < 0.001    (stands however thin)\n", n);
      else
        std::snprintf(line, sizeof line, "  %9d   %.6f   %+7.2f %%   %6d   %7.2f\n", n, r.threshold(),
                      100.0 * (r.threshold() / 0.1075 - 1.0), r.trials, s);
      std::cout << line;
    }
  }
  if (json) std::cout << "]}\n";
  return 0;
}

int model_limit_lp(Options& o) {
  const bool json = o.flag("json");
  const bool list = o.flag("interfaces");
  const std::string deck = o.text("deck", "");
  std::vector<std::string> overrides;
  if (o.flag("no_windows")) overrides.push_back("spire.window_faces=[]");
  const polydem::SceneSpec scene = deck.empty() ? polydem::parse_deck("[spire]\n", "<default [spire]>", overrides)
                                                : polydem::read_deck(deck, overrides);
  const std::vector<double> phis = number_list(o, "phi", scene.joint.friction_angle);
  const std::vector<double> dirs = number_list(o, "direction", 0.0);
  const double sides = o.number("sides", 16);
  const std::string pyramid = o.text("pyramid", "both");
  const std::string method = o.text("method", "interior");
  const std::string lp_file = o.text("write_lp", "");
  o.check_all_used();
  if (!overrides.empty() && !scene.spire) throw BadInput("--no-windows needs a deck with a [spire]");
  for (double phi : phis)
    if (!(phi >= 0.0 && phi < 90.0)) throw BadInput("--phi must be in [0, 90) degrees");
  if (sides < 3 || sides > 360 || sides != std::floor(sides)) throw BadInput("--sides must be an integer in [3, 360]");
  std::vector<polydem::FrictionPyramid> pyramids;
  if (pyramid == "both" || pyramid == "circumscribed") pyramids.push_back(polydem::FrictionPyramid::circumscribed);
  if (pyramid == "both" || pyramid == "inscribed") pyramids.push_back(polydem::FrictionPyramid::inscribed);
  if (pyramids.empty()) throw BadInput("--pyramid must be both, circumscribed or inscribed");
  polydem::LimitAnalysisOptions opt;
  opt.pyramid_sides = static_cast<int>(sides);
  opt.lp_file = lp_file;
  if (method == "simplex") opt.method = polydem::LpMethod::simplex;
  else if (method == "interior") opt.method = polydem::LpMethod::interior_point;
  else throw BadInput("--method must be simplex or interior");

  const polydem::LimitModel model = polydem::limit_model(scene);
  std::vector<LimitCase> cases;
  for (double dir : dirs)
    for (double phi : phis) {
      LimitCase c;
      c.direction_deg = dir;
      c.phi_deg = phi;
      const double a = dir * std::numbers::pi / 180.0;
      opt.direction = polydem::Vec3(std::cos(a), std::sin(a), 0.0);
      opt.friction_angle_deg = phi;
      for (const auto p : pyramids) {
        opt.pyramid = p;
        c.results.push_back(polydem::limit_analysis(model, opt));
      }
      cases.push_back(std::move(c));
    }
  int free_blocks = 0;
  for (char f : model.free) free_blocks += f;
  const std::string src = scene.deck_path.empty() ? std::string("<default [spire]>") : scene.deck_path;
  if (json) {
    std::cout << "{\"model\":\"limit-lp\",\"deck\":" << jstr(src) << ",\"blocks\":" << model.mass.size()
              << ",\"free_blocks\":" << free_blocks << ",\"interfaces\":" << model.interfaces.size()
              << ",\"vertices\":" << model.vertices << ",\"pyramid_sides\":" << opt.pyramid_sides
              << ",\"method\":" << jstr(polydem::to_string(opt.method)) << ",\"initial_mesh_s\":"
              << jnum(model.detection_seconds) << ",\"cases\":[";
    for (std::size_t i = 0; i < cases.size(); ++i) {
      std::cout << (i ? "," : "") << "{\"direction_deg\":" << jnum(cases[i].direction_deg)
                << ",\"friction_angle_deg\":" << jnum(cases[i].phi_deg);
      for (std::size_t k = 0; k < pyramids.size(); ++k)
        std::cout << "," << jstr(polydem::to_string(pyramids[k])) << ":" << limit_result_json(model, cases[i].results[k]);
      std::cout << "}";
    }
    std::cout << "]}\n";
    return 0;
  }
  const auto& first = cases.front().results.front();
  std::cout << "limit analysis of the block model: rigid blocks, no tension, Coulomb friction (docs/analytical.md 7)\n"
            << "  deck     " << src << ": " << model.mass.size() << " blocks (" << free_blocks << " free), "
            << model.interfaces.size() << " interfaces touching at t = 0, " << model.vertices
            << " patch vertices; blocks and initial mesh in " << fmt(model.detection_seconds, 3) << " s\n"
            << "  LP       " << opt.pyramid_sides << "-sided friction pyramid at every vertex (generators), GLPK "
            << polydem::to_string(opt.method) << "; " << first.rows << " rows, " << first.columns << " columns, "
            << first.nonzeros << " nonzeros\n"
            << "  load     lambda m |g| horizontally along the direction's azimuth from +x (the static equivalent of\n"
            << "           a ground acceleration -lambda g the opposite way), on the dead load m g\n"
            << "  bound    circumscribed pyramid: an upper bound on any lambda at which the blocks can stand in their\n"
            << "           initial geometry; inscribed: below the exact cone's value (the two bracket it)\n";
  std::cout << "  dir [deg]  phi [deg]";
  for (const auto p : pyramids) std::cout << (p == polydem::FrictionPyramid::circumscribed ? "  lambda circ." : "  lambda inscr.");
  std::cout << "  solve [s]  mechanism (" << polydem::to_string(pyramids.front()) << ")\n";
  for (const auto& c : cases) {
    char line[96];
    std::snprintf(line, sizeof line, "  %-9.4g  %-9.4g", c.direction_deg, c.phi_deg);
    std::cout << line;
    double t = 0;
    for (const auto& r : c.results) {
      std::snprintf(line, sizeof line, "  %-12.6g", r.lambda);
      std::cout << line << (pyramids.size() > 1 && &r == &c.results.back() ? " " : "");
      t += r.build_seconds + r.solve_seconds;
    }
    std::snprintf(line, sizeof line, "  %-9.3f", t);
    std::cout << line << "  " << mechanism_text(c.results.front()) << "\n";
  }
  if (list)
    for (const auto& c : cases) {
      const auto& r = c.results.front();
      if (r.status != polydem::LimitStatus::optimal) continue;
      std::cout << "  interfaces moving at direction " << fmt(c.direction_deg) << " deg, phi " << fmt(c.phi_deg)
                << " deg (" << polydem::to_string(pyramids.front()) << "):\n";
      for (std::size_t q = 0; q < r.mechanism.motion.size(); ++q) {
        if (r.mechanism.motion[q] == polydem::InterfaceMotion::closed) continue;
        const auto& f = model.interfaces[q];
        std::cout << "    " << model.names[f.ref] << " | " << model.names[f.inc] << "  "
                  << (f.bed ? "bed" : "vertical") << "  " << polydem::to_string(r.mechanism.motion[q]) << "\n";
      }
    }
  return 0;
}

}  // namespace

int run_analytic_command(const std::vector<std::string>& args) {
  std::size_t first = 0;
  if (!args.empty() && args[0] == "analytic") first = 1;
  if (first >= args.size() || args[first] == "--help" || args[first] == "-h" || args[first] == "help") {
    std::cout << kUsage;
    return first >= args.size() ? 2 : 0;
  }
  const std::string model = args[first];
  static const std::map<std::string, std::function<int(Options&)>> models = {
      {"lambda", model_lambda},
      {"beam", model_beam},
      {"rocking", model_rocking},
      {"collapse-diagram", model_collapse},
      {"cracked-cone-p", model_cracked},
      {"refined-lambda", model_refined},
      {"dem-frequency", model_dem_frequency},
      {"limit-lp", model_limit_lp},
      {"arch-thickness", model_arch_thickness},
  };
  auto it = models.find(model);
  if (it == models.end()) {
    std::cerr << "polydem analytic: unknown model '" << model
              << "' (expected lambda, beam, rocking, collapse-diagram, cracked-cone-p, refined-lambda, dem-frequency, limit-lp, arch-thickness)\n";
    return 2;
  }
  try {
    Options o = parse(args, first + 1);
    if (o.flags.count("help")) {
      std::cout << kUsage;
      return 0;
    }
    return it->second(o);
  } catch (const BadInput& e) {
    std::cerr << "polydem analytic " << model << ": " << e.what() << "\n";
  } catch (const std::invalid_argument& e) {
    std::cerr << "polydem analytic " << model << ": " << e.what() << "\n";
  } catch (const std::runtime_error& e) {  // deck errors (complete messages), failed runs
    std::cerr << "polydem analytic " << model << ": " << e.what() << "\n";
  }
  return 2;
}
