// polydem._polydem: the models of `polydem analytic` -- the closed-form and
// ODE models (analytical/) and the limit analyses and DEM frequency of the
// block model (studies/). Each returns the JSON text the command line's
// --json prints (io/analytic_results.hpp), at full precision; the Python
// half (polydem/analytical.py) reads it into a dict. The keyword arguments
// are the command line's options, with the same defaults (taken from the
// models' structs).
//
// fragility fits the runs of a CSV file or of lists (fragility_json);
// synthetic_suite returns its records' histories in the JSON and writes the
// command line's files when given a directory.
//
// The block models take a parsed scene (the deck of --deck, or
// analytic_scene() for the default [spire]) and run with the GIL released.
#include "python/bindings.hpp"

#include "io/analytic_inputs.hpp"
#include "io/analytic_results.hpp"
#include "io/fragility_tables.hpp"
#include "io/synthetic_suite.hpp"

#include <pybind11/stl.h>

#include <cmath>

namespace polydem::python {

namespace pa = analytical;

namespace {

pa::BodySpec body_spec(const std::string& shape, double b, double h, double r_b, double H, double tip, double thickness,
                       double density, std::optional<double> H_bar) {
  const auto named = pa::body_shape_named(shape);
  if (!named) throw py::value_error("body must be block, shell, cone or cracked (got \"" + shape + "\")");
  return pa::BodySpec{*named, b, h, r_b, H, tip, thickness, density, H_bar};
}

// m.def(name, f, the body's keyword arguments (BodySpec's defaults), extra...):
// rocking and collapse_diagram take the same body.
template <typename F, typename... Extra>
void def_with_body(py::module_& m, const char* name, F&& f, Extra&&... extra) {
  const pa::BodySpec d;
  m.def(name, std::forward<F>(f), py::arg("body") = std::string(pa::to_string(d.shape)), py::arg("b") = d.b,
        py::arg("h") = d.h, py::arg("r_b") = d.r_b, py::arg("H") = d.H, py::arg("tip") = d.tip,
        py::arg("thickness") = d.thickness, py::arg("density") = d.density,
        py::arg("H_bar") = py::none(), std::forward<Extra>(extra)...);
}

std::string text(const Json& j) { return j.dump(0); }

}  // namespace

void bind_analytical(py::module_& m) {
  m.def(
      "analytic_scene",
      [](const std::string& deck, bool no_windows) {
        Scene s;
        {
          py::gil_scoped_release nogil;
          s.spec = analytic_scene(deck, no_windows);
        }
        s.name = s.spec.deck_path;
        return s;
      },
      py::arg("deck"), py::arg("no_windows"));

  m.def(
      "static_lambda",
      [](double r_b, double H, std::optional<double> h_c) {
        return text(cone_overturning_json(pa::cone_overturning(r_b, H, h_c.value_or(H))));
      },
      py::arg("r_b") = 1.06, py::arg("H") = 9.4, py::arg("h_c") = py::none());

  const pa::SpireBeam beam;
  m.def(
      "beam",
      [](double H, double r_b, double thickness, double E, double density, const std::string& section, int modes) {
        if (section != "circle" && section != "octagon")
          throw py::value_error("section must be circle or octagon (got \"" + section + "\")");
        const pa::SectionShape shape = section == "octagon" ? pa::SectionShape::octagon : pa::SectionShape::circle;
        const pa::SpireBeam b{H, r_b, thickness, E, density, shape, modes};
        return text(spire_beam_json(pa::spire_beam_modes(b)));
      },
      py::arg("H") = beam.H, py::arg("r_b") = beam.r_b, py::arg("thickness") = beam.thickness, py::arg("E") = beam.E,
      py::arg("density") = beam.density, py::arg("section") = "circle", py::arg("modes") = beam.modes);

  const pa::LoadSpec load;
  const pa::RockingOptions rocking;
  def_with_body(
      m, "rocking",
      [](const std::string& body, double b, double h, double r_b, double H, double tip, double thickness,
         double density, std::optional<double> H_bar, const std::string& load, double a_p, double T_p, double a,
         const std::string& file, double g, double dt, double t_end, bool linear, std::optional<double> restitution,
         double every) {
        const auto kind = pa::load_kind_named(load);
        if (!kind) throw py::value_error("load must be pulse, constant or record (got \"" + load + "\")");
        pa::RockingCase c;
        c.body = body_spec(body, b, h, r_b, H, tip, thickness, density, H_bar);
        if (*kind == pa::LoadKind::record) c.load = record_load(file);
        c.load.kind = *kind;
        c.load.a_p = a_p;
        c.load.T_p = T_p;
        c.load.a = a;
        c.options.g = g;
        c.options.dt = dt;
        c.options.t_end = t_end;
        if (linear) c.options.form = pa::RockingForm::linearised;
        c.options.restitution = restitution;
        py::gil_scoped_release nogil;
        return text(rocking_json(c, pa::rocking_response(c), every));
      },
      py::arg("load") = "pulse", py::arg("a_p") = load.a_p, py::arg("T_p") = load.T_p, py::arg("a") = load.a,
      py::arg("file") = "", py::arg("g") = rocking.g, py::arg("dt") = rocking.dt, py::arg("t_end") = rocking.t_end,
      py::arg("linear") = false, py::arg("restitution") = py::none(), py::arg("every") = 0.0);

  const pa::CollapseDiagramCase diagram;
  def_with_body(
      m, "collapse_diagram",
      [](const std::string& body, double b, double h, double r_b, double H, double tip, double thickness,
         double density, std::optional<double> H_bar, double Tp_min, double Tp_max, int Tp_count, double a_max,
         int points, double tol, double g, bool linear, std::optional<double> restitution) {
        pa::CollapseDiagramCase c;
        c.body = body_spec(body, b, h, r_b, H, tip, thickness, density, H_bar);
        c.T_p_min = Tp_min;
        c.T_p_max = Tp_max;
        c.T_p_count = Tp_count;
        c.scan.a_max_g = a_max;
        c.scan.coarse_points = points;
        c.scan.tolerance_g = tol;
        c.scan.g = g;
        if (linear) c.scan.form = pa::RockingForm::linearised;
        c.scan.restitution = restitution;
        py::gil_scoped_release nogil;
        return text(collapse_diagram_json(c, pa::pulse_collapse_diagram(c)));
      },
      py::arg("Tp_min") = diagram.T_p_min, py::arg("Tp_max") = diagram.T_p_max, py::arg("Tp_count") = diagram.T_p_count,
      py::arg("a_max") = diagram.scan.a_max_g, py::arg("points") = diagram.scan.coarse_points,
      py::arg("tol") = diagram.scan.tolerance_g, py::arg("g") = diagram.scan.g, py::arg("linear") = false,
      py::arg("restitution") = py::none());

  const pa::SpireGeometry spire;
  m.def(
      "cracked_cone_p",
      [](double H, double r_b, double tip, double thickness, double density, int count, double g) {
        const pa::SpireGeometry s{H, r_b, tip, thickness, density};
        return text(cracked_spire_json(pa::cracked_spire_curve(s, count, g)));
      },
      py::arg("H") = spire.H, py::arg("r_b") = spire.r_b, py::arg("tip") = spire.tip_height,
      py::arg("thickness") = spire.wall_thickness, py::arg("density") = spire.density, py::arg("count") = 25,
      py::arg("g") = pa::standard_gravity);

  m.def(
      "refined_lambda",
      [](const Scene& scene, double g) {
        py::gil_scoped_release nogil;
        return text(spire_lambda_json(spire_lambda(scene.spec, g)));
      },
      py::arg("scene"), py::arg("g") = pa::standard_gravity);

  const DemFrequencyOptions dem;
  m.def(
      "dem_frequency",
      [](const Scene& scene, double duration, double settle, double pulse_g, double pulse_period, double interval,
         bool keep_damping, int threads) {
        DemFrequencyOptions o;
        o.duration = duration;
        o.settle_time = settle;
        o.pulse_g = pulse_g;
        o.pulse_period = pulse_period;
        o.history_interval = interval;
        o.keep_damping = keep_damping;
        o.threads = threads;
        DemFrequencyResult r;
        {
          py::gil_scoped_release nogil;
          r = measure_dem_frequency(scene.spec, o);
        }
        return py::make_tuple(text(dem_frequency_json(scene.spec, o, r)), r.t, r.u);
      },
      py::arg("scene"), py::arg("duration") = dem.duration, py::arg("settle") = dem.settle_time,
      py::arg("pulse_g") = dem.pulse_g, py::arg("pulse_period") = dem.pulse_period,
      py::arg("interval") = dem.history_interval, py::arg("keep_damping") = dem.keep_damping,
      py::arg("threads") = dem.threads);

  const LimitStudyOptions limit;
  m.def(
      "limit_lp",
      [](const Scene& scene, const std::vector<double>& phi, const std::vector<double>& direction, int sides,
         const std::string& pyramid, const std::string& method, const std::string& lp_file) {
        LimitStudyOptions o;
        o.friction_angles_deg = phi;
        o.directions_deg = direction;
        o.pyramid_sides = sides;
        const auto pyramids = friction_pyramids_named(pyramid);
        if (!pyramids) throw py::value_error("pyramid must be both, circumscribed or inscribed (got \"" + pyramid + "\")");
        const auto lp = lp_method_named(method);
        if (!lp) throw py::value_error("method must be simplex or interior (got \"" + method + "\")");
        o.pyramids = *pyramids;
        o.method = *lp;
        o.lp_file = lp_file;
        py::gil_scoped_release nogil;
        return text(limit_study_json(limit_study(scene.spec, o)));
      },
      py::arg("scene"), py::arg("phi") = limit.friction_angles_deg, py::arg("direction") = limit.directions_deg,
      py::arg("sides") = limit.pyramid_sides, py::arg("pyramid") = "both", py::arg("method") = "interior",
      py::arg("lp_file") = "");

  const ThinnestArchOptions arch;
  m.def(
      "arch_thickness",
      [](const std::vector<int>& voussoirs, double phi, double tol) {
        const ThinnestArchOptions o{phi, tol};
        py::gil_scoped_release nogil;
        std::vector<ThinnestArch> arches;
        for (int n : voussoirs) arches.push_back(thinnest_arch(n, unit_semicircular_arch, o));
        return text(thinnest_arch_json(o, arches));
      },
      py::arg("voussoirs") = std::vector<int>{9}, py::arg("phi") = arch.friction_angle_deg,
      py::arg("tol") = arch.tolerance);

  const pa::FragilityOptions fragility;
  m.def(
      "fragility",
      [](const std::string& csv, const std::vector<double>& im, const std::vector<std::string>& state,
         const std::vector<std::string>& record, const std::string& method, int bootstrap, std::uint64_t seed,
         double confidence, int points, const std::string& out) {
        FragilityInput in;
        if (!csv.empty()) {
          if (!im.empty() || !state.empty() || !record.empty())
            throw py::value_error("give either csv or im and state (and record), not both");
          in = read_fragility_runs(csv);
        } else {
          if (im.size() != state.size() || (!record.empty() && record.size() != im.size()))
            throw py::value_error("im, state (and record) must have the same length");
          for (std::size_t i = 0; i < im.size(); ++i) {
            const auto s = pa::damage_state_named(state[i]);
            if (!s) throw py::value_error("state '" + state[i] + "' is not intact, damaged, stones_lost, collapsed or 0-3");
            in.runs.push_back({record.empty() ? std::string() : record[i], im[i], *s});
          }
          in.has_records = !record.empty();
        }
        if (method != "auto" && method != "ida" && method != "stripes")
          throw py::value_error("method must be auto, ida or stripes (got \"" + method + "\")");
        pa::FragilityOptions o;
        o.method = method == "stripes" || (method == "auto" && !in.has_records) ? pa::FragilityMethod::stripes
                                                                                 : pa::FragilityMethod::ida;
        o.bootstrap = bootstrap, o.seed = seed, o.confidence = confidence, o.points = points;
        pa::FragilityResult r;
        {
          py::gil_scoped_release nogil;
          r = pa::fit_fragility(in.runs, o);
        }
        if (!out.empty()) write_fragility_tables(out, r);
        return text(fragility_json(r));
      },
      py::arg("csv") = "", py::arg("im") = std::vector<double>{}, py::arg("state") = std::vector<std::string>{},
      py::arg("record") = std::vector<std::string>{}, py::arg("method") = "auto",
      py::arg("bootstrap") = fragility.bootstrap, py::arg("seed") = fragility.seed,
      py::arg("confidence") = fragility.confidence, py::arg("points") = fragility.points, py::arg("out") = "");

  const pa::SyntheticOptions synthetic;
  m.def(
      "synthetic_suite",
      [](double magnitude, double distance, double vs30, int count, std::uint64_t seed, const std::string& fault,
         double dt, double high_pass, const std::string& prefix, const std::string& out) {
        if (fault != "strike-slip" && fault != "reverse")
          throw py::value_error("fault must be strike-slip or reverse (got \"" + fault + "\")");
        SyntheticSuiteRun run;
        run.scenario = {magnitude, distance, vs30, fault == "reverse"};
        run.seed = seed;
        run.options.dt = dt;
        run.options.high_pass = high_pass;
        {
          py::gil_scoped_release nogil;
          run.records = pa::synthetic_suite(run.scenario, count, seed, run.options, prefix);
        }
        if (!out.empty()) write_synthetic_suite(out, run);
        return text(synthetic_suite_json(run, true));
      },
      py::arg("magnitude"), py::arg("distance"), py::arg("vs30"), py::arg("count") = 20, py::arg("seed") = 1,
      py::arg("fault") = "strike-slip", py::arg("dt") = synthetic.dt, py::arg("high_pass") = synthetic.high_pass,
      py::arg("prefix") = "synthetic", py::arg("out") = "");
}

}  // namespace polydem::python
