// polydem._polydem: the collapse search (studies/collapse_search.hpp) and
// sweeps (studies/sweep_grid.hpp, studies/sweep_search.hpp) from Python.
//
// The searches run with the GIL released; the progress function (may be
// None) is called with the GIL after every run. Sweep points run one after
// the other in this process (each on `threads` OpenMP threads): the same
// scene with the point's overrides, as `polydem sweep` runs `polydem run
// --set ...`, and what a study keeps of a run (PointResult) is read from the
// run's summary the way polydem sweep reads summary.json (io/summary.hpp).
// The Python half (polydem/studies.py) makes numpy structured arrays. An
// ensemble is the sweep of its replicas (ensemble.replica = 0..N-1),
// summarised by studies/ensemble.hpp as `polydem ensemble` does. An IDA is
// studies/ida.hpp's search over the suite's records, its runs as a sweep's.
#include "python/bindings.hpp"

#include "io/collapse_results.hpp"
#include "io/deck.hpp"
#include "io/ida_tables.hpp"
#include "io/record_suite.hpp"
#include "io/summary.hpp"
#include "studies/collapse_search.hpp"
#include "studies/ensemble.hpp"
#include "studies/ida.hpp"
#include "studies/sweep_search.hpp"

#include <pybind11/stl.h>

#include <filesystem>
#include <map>

namespace polydem::python {

namespace {

py::dict trial_dict(const char* method, const CollapseTrial& t) {
  py::dict d;
  d["method"] = method;
  d["direction_deg"] = t.direction_deg;
  d["acceleration_g"] = t.acceleration_g;
  d["collapsed"] = t.collapsed;
  d["status"] = t.assessment.status;
  d["collapse_mode"] = t.assessment.collapse_mode;
  d["crack_angle_deg"] = t.assessment.crack_angle_deg;
  d["steps"] = t.steps;
  d["wall_seconds"] = t.wall_seconds;
  return d;
}

PointResult run_point(const Scene& scene, const SweepPoint& point, int threads) {
  std::vector<std::string> overrides = scene.overrides;
  for (const std::string& o : point.overrides()) overrides.push_back(o);
  const SceneSpec spec = parse_deck(scene.spec.deck_text, scene.name, overrides);
  try {
    RunControl control;
    control.threads = threads;
    const RunReport r = run_scene(spec, control);
    PointResult p = point_result_from_summary(summary_json(spec, r, r.profile.threads_given).dump(2), point.label());
    p.exit_code = r.unstable ? 3 : r.all_checks_passed() ? 0 : 1;
    return p;
  } catch (const SceneError& e) {
    PointResult p;
    p.status = "error";
    p.exit_code = 2;
    p.message = locate_scene_error(e, spec);
    return p;
  }
}

py::dict point_dict(const SweepPoint& point, const PointResult& r) {
  py::dict d;
  for (const auto& [key, value] : point.values) d[py::str(key)] = value;
  d["status"] = r.status;
  d["collapse_mode"] = r.collapse_mode;
  d["peak_tip_displacement"] = r.peak_tip_displacement;
  d["peak_displacement"] = r.peak_displacement;
  d["residual_displacement"] = r.residual_displacement;
  d["collapse_time"] = r.collapse_time;
  d["dislodged"] = r.dislodged;
  d["steps"] = r.steps;
  d["wall_seconds"] = r.wall_seconds;
  d["exit_code"] = r.exit_code;
  d["message"] = r.message;
  return d;
}

}  // namespace

void bind_studies(py::module_& m) {
  m.def(
      "collapse_search",
      [](const Scene& scene, const std::vector<double>& directions, const std::string& method,
         const CollapseSearchOptions& options, const std::string& out, py::object progress) {
        if (method != "bisection" && method != "ramp" && method != "both")
          raise_python("DeckError", "key 'method': must be \"bisection\", \"ramp\" or \"both\" (got \"" + method + "\")");
        CollapseStudy study;
        study.deck = scene.name;
        study.method = method;
        study.tolerance_g = options.tolerance_g;
        study.ramp_rate_g = options.ramp_rate_g;
        py::list trials;
        const TrialObserver observe = [&](const char* how, const CollapseTrial& t) {
          py::gil_scoped_acquire gil;
          py::dict d = trial_dict(how, t);
          trials.append(d);
          if (!progress.is_none()) progress(d);
        };
        try {
          py::gil_scoped_release nogil;
          for (double deg : directions) {
            CollapseDirection d;
            d.direction_deg = deg;
            if (method == "bisection" || method == "both") d.bisection = bisect_collapse(scene.spec, deg, options, observe);
            if (method == "ramp" || method == "both") d.ramp = ramp_collapse(scene.spec, deg, options, observe);
            study.directions.push_back(std::move(d));
          }
          if (!out.empty()) {
            std::filesystem::create_directories(out);
            write_collapse_json(out + "/collapse.json", study);
          }
        } catch (const SceneError& e) {
          raise_python("SceneError", locate_scene_error(e, scene.spec));
        }
        py::list rows;
        for (const CollapseDirection& d : study.directions) {
          py::dict r;
          r["direction_deg"] = d.direction_deg;
          const bool bisected = d.bisection && d.bisection->error.empty();
          r["bisection_g"] = bisected ? d.bisection->collapse_g : NAN;
          r["low_g"] = bisected ? d.bisection->low_g : NAN;
          r["high_g"] = bisected ? d.bisection->high_g : NAN;
          r["bisection_runs"] = d.bisection ? d.bisection->runs : 0;
          r["bisection_error"] = d.bisection ? d.bisection->error : std::string();
          r["ramp_g"] = d.ramp ? d.ramp->acceleration_g : NAN;
          double crack = bisected ? d.bisection->last_collapse.assessment.crack_angle_deg : -1;
          if (crack < 0 && d.ramp) crack = d.ramp->assessment.crack_angle_deg;
          r["crack_angle_deg"] = crack;
          r["collapse_mode"] = bisected ? d.bisection->last_collapse.assessment.collapse_mode
                               : d.ramp ? d.ramp->assessment.collapse_mode
                                        : std::string();
          rows.append(r);
        }
        return py::make_tuple(rows, trials, study.lowest_g());
      },
      py::arg("scene"), py::arg("directions"), py::arg("method"), py::arg("options"), py::arg("out"),
      py::arg("progress"));

  py::class_<CollapseSearchOptions>(m, "CollapseSearchOptions")
      .def(py::init<>())
      .def_readwrite("low_g", &CollapseSearchOptions::low_g)
      .def_readwrite("high_g", &CollapseSearchOptions::high_g)
      .def_readwrite("tolerance_g", &CollapseSearchOptions::tolerance_g)
      .def_readwrite("rise_time", &CollapseSearchOptions::rise_time)
      .def_readwrite("hold_time", &CollapseSearchOptions::hold_time)
      .def_readwrite("ramp_rate_g", &CollapseSearchOptions::ramp_rate_g)
      .def_readwrite("threads", &CollapseSearchOptions::threads);

  m.def(
      "ensemble",
      [](const Scene& scene, long replicas, int threads, py::object progress) {
        std::vector<std::string> unperturbed = scene.overrides;
        unperturbed.push_back(std::string(kReplicaKey) + "=0");
        const SceneSpec base = parse_deck(scene.spec.deck_text, scene.name, unperturbed);
        const std::uint64_t seed = base.ensemble.seed;
        std::vector<SweepPoint> points;
        for (long k = 0; k < replicas; ++k) points.push_back(SweepPoint{{{kReplicaKey, static_cast<double>(k)}}});
        for (const SweepPoint& p : points) {  // every replica's deck is valid before anything runs
          std::vector<std::string> overrides = scene.overrides;
          for (const std::string& o : p.overrides()) overrides.push_back(o);
          (void)parse_deck(scene.spec.deck_text, scene.name, overrides);
        }
        py::list rows;
        std::vector<PointResult> results;
        {
          py::gil_scoped_release nogil;
          for (long k = 0; k < replicas; ++k) {
            results.push_back(run_point(scene, points[static_cast<std::size_t>(k)], threads));
            const EnsembleDraw drawn = draw_perturbation(base, k, seed).drawn;
            py::gil_scoped_acquire gil;
            const PointResult& r = results.back();
            py::dict d;
            d["replica"] = k;
            d["seed"] = seed;
            d["friction_angle_shift_deg"] = drawn.friction_angle_shift;
            d["normal_stiffness_factor"] = drawn.normal_stiffness_factor;
            d["shear_stiffness_factor"] = drawn.shear_stiffness_factor;
            d["time_shift_s"] = drawn.time_shift;
            d["largest_initial_speed_m_s"] = drawn.largest_initial_speed;
            d["status"] = r.status;
            d["collapse_mode"] = r.collapse_mode;
            for (const EnsembleQuantity& q : ensemble_quantities()) d[q.name] = q.of(r);
            d["dislodged_blocks"] = r.dislodged;
            d["steps"] = r.steps;
            d["wall_seconds"] = r.wall_seconds;
            d["exit_code"] = r.exit_code;
            d["message"] = r.message;
            rows.append(d);
            if (!progress.is_none()) progress(d);
          }
        }
        const EnsembleOutcome o = summarise_ensemble(results);
        py::dict counts, modes, distributions;
        for (const auto& [status, n] : o.status_counts) counts[py::str(status)] = n;
        modes["I"] = o.mode_I;
        modes["II"] = o.mode_II;
        auto as_dict = [](const Distribution& d) {
          py::dict q;
          q["n"] = d.n;
          q["p16"] = d.p16;
          q["median"] = d.median;
          q["p84"] = d.p84;
          return q;
        };
        const auto quantities = ensemble_quantities();
        for (std::size_t i = 0; i < quantities.size(); ++i) distributions[quantities[i].name] = as_dict(o.quantities[i]);
        py::dict summary;
        summary["replicas"] = o.replicas;
        summary["seed"] = seed;
        summary["status_counts"] = counts;
        summary["collapse_modes"] = modes;
        summary["distributions"] = distributions;
        py::list courses;  // output.walking: per course from the bottom
        const auto cq = course_quantities();
        for (const CourseDistribution& c : o.courses) {
          py::dict dc;
          dc["level_m"] = c.level;
          dc["bed_joints"] = c.bed_joints;
          dc["vertical_joints"] = c.vertical_joints;
          for (std::size_t i = 0; i < cq.size(); ++i) dc[cq[i].name] = as_dict(c.quantities[i]);
          courses.append(dc);
        }
        summary["courses"] = courses;
        return py::make_tuple(rows, summary);
      },
      py::arg("scene"), py::arg("replicas"), py::arg("threads"), py::arg("progress"));

  m.def(
      "sweep",
      [](const Scene& scene, const std::vector<std::pair<std::string, std::vector<double>>>& vary,
         const std::string& search, double resolution, int threads, py::object progress) {
        std::vector<SweepAxis> axes;
        for (const auto& [key, values] : vary) axes.push_back(SweepAxis{key, values});
        const std::vector<SweepPoint> grid = grid_points(axes);
        SearchAxis axis;
        try {
          if (!search.empty()) axis = parse_search_axis(search, resolution);
        } catch (const std::invalid_argument& e) {
          raise_python("DeckError", e.what());
        }
        // Every point's deck is valid before anything runs (as polydem sweep).
        std::vector<SweepPoint> check = grid;
        if (!search.empty()) {
          check.clear();
          for (const SweepPoint& p : grid) {
            check.push_back(p.with(axis.key, axis.start));
            check.push_back(p.with(axis.key, axis.stop));
          }
        }
        for (const SweepPoint& p : check) {
          std::vector<std::string> overrides = scene.overrides;
          for (const std::string& o : p.overrides()) overrides.push_back(o);
          (void)parse_deck(scene.spec.deck_text, scene.name, overrides);
        }
        py::list rows;
        long done = 0;
        const BatchRunner run = [&](const std::vector<SweepPoint>& batch) {
          std::vector<PointResult> results;
          for (const SweepPoint& p : batch) {
            results.push_back(run_point(scene, p, threads));
            py::gil_scoped_acquire gil;
            py::dict d = point_dict(p, results.back());
            rows.append(d);
            ++done;
            if (!progress.is_none()) progress(d);
          }
          return results;
        };
        py::list columns;
        {
          py::gil_scoped_release nogil;
          if (search.empty()) {
            (void)run(grid);
          } else {
            const SearchReport rep = boundary_search(grid, axis, run);
            py::gil_scoped_acquire gil;
            for (const ColumnResult& c : rep.columns) {
              py::dict d;
              for (const auto& [key, value] : c.outer.values) d[py::str(key)] = value;
              d["damage_threshold"] = c.damage_threshold;
              d["stones_lost_threshold"] = c.stones_threshold;
              d["collapse_threshold"] = c.collapse_threshold;
              d["collapse_mode"] = c.collapse_mode;
              d["runs"] = static_cast<long>(c.runs.size());
              d["wall_seconds"] = c.wall_seconds;
              columns.append(d);
            }
          }
        }
        return py::make_tuple(rows, columns);
      },
      py::arg("scene"), py::arg("vary"), py::arg("search"), py::arg("resolution"), py::arg("threads"),
      py::arg("progress"));

  m.def(
      "ida",
      [](const Scene& scene, const std::string& suite_path, const std::string& measure, double period, double damping,
         const std::string& mode, const std::vector<double>& levels, const HuntAndFill& hunt, int threads,
         const std::string& out, py::object progress) {
        IntensitySpec im;
        if (measure == "sa") {
          im.measure = IntensityMeasure::sa;
          im.period = period;
          im.damping = damping;
          if (!(period > 0)) raise_python("DeckError", "im \"sa\" needs a period > 0 (got " + value_text(period) + ")");
          if (!(damping >= 0 && damping < 1)) raise_python("DeckError", "damping must be in [0, 1)");
        } else if (measure != "pga") {
          raise_python("DeckError", "im must be \"pga\" or \"sa\" (got \"" + measure + "\")");
        }
        const RecordSuite suite = read_record_suite(suite_path);
        const SceneSpec base = parse_deck(scene.spec.deck_text, scene.name, scene.overrides);
        std::vector<std::string> names, motions;
        std::vector<double> record_ims;
        for (const SuiteRecord& r : suite.records) {
          try {
            record_ims.push_back(record_intensity(r, im));
          } catch (const std::invalid_argument& e) {
            raise_python("DeckError", suite.path + ":" + std::to_string(r.line) + ": " + e.what());
          }
          names.push_back(r.name);
          motions.push_back(record_motion_override(r, suite, base.ground_motion));
          std::vector<std::string> overrides = scene.overrides;  // the deck takes every record
          for (const std::string& o : record_point(r, motions.back(), 1.0).overrides()) overrides.push_back(o);
          (void)parse_deck(scene.spec.deck_text, scene.name, overrides);
        }
        std::map<std::vector<std::string>, std::pair<std::size_t, double>> at;  // a run's record and IM
        const IdaPointOf point_of = [&](std::size_t r, double x, double factor) {
          SweepPoint p = record_point(suite.records[r], motions[r], factor);
          at[p.overrides()] = {r, x};
          return p;
        };
        const BatchRunner run = [&](const std::vector<SweepPoint>& batch) {
          std::vector<PointResult> results;
          for (const SweepPoint& p : batch) {
            results.push_back(run_point(scene, p, threads));
            if (progress.is_none()) continue;
            py::gil_scoped_acquire gil;
            py::dict d;
            const auto [r, x] = at[p.overrides()];
            d["record"] = names[r];
            d["im"] = x;
            d["status"] = results.back().status;
            d["collapse_mode"] = results.back().collapse_mode;
            d["wall_seconds"] = results.back().wall_seconds;
            progress(d);
          }
          return results;
        };
        IdaReport report;
        try {
          py::gil_scoped_release nogil;
          report = mode == "hunt" ? hunt_and_fill(names, record_ims, hunt, point_of, run)
                                  : run_stripes(names, record_ims, levels, mode == "scales", point_of, run);
          if (!out.empty()) write_ida_tables(out, report);
        } catch (const std::invalid_argument& e) {
          raise_python("DeckError", e.what());
        }
        py::list rows, records;
        for (const IdaRecord& rec : report.records) {
          for (const IdaRun& r : rec.runs) {
            py::dict d = point_dict(SweepPoint{}, r.result);
            d["record"] = rec.name;
            d["im"] = r.im;
            d["scale"] = r.factor;
            d["state"] = r.state;
            d["damage_time"] = r.result.damage_time;
            d["max_bed_opening"] = r.result.max_bed_opening;
            d["max_vertical_opening"] = r.result.max_vertical_opening;
            rows.append(d);
          }
          py::dict c;
          c["record"] = rec.name;
          c["record_im"] = rec.record_im;
          c["damage_im"] = rec.damage_im;
          c["stones_lost_im"] = rec.stones_im;
          c["collapse_im"] = rec.collapse_im;
          c["below_collapse_im"] = rec.below_collapse_im;
          c["collapse_scale"] = rec.collapse_im / rec.record_im;
          c["runs"] = static_cast<long>(rec.runs.size());
          c["undetermined"] = rec.undetermined;
          records.append(c);
        }
        return py::make_tuple(rows, records);
      },
      py::arg("scene"), py::arg("suite"), py::arg("im"), py::arg("period"), py::arg("damping"), py::arg("mode"),
      py::arg("levels"), py::arg("hunt"), py::arg("threads"), py::arg("out"), py::arg("progress"));

  py::class_<HuntAndFill>(m, "HuntAndFill")
      .def(py::init<>())
      .def_readwrite("first", &HuntAndFill::first)
      .def_readwrite("step", &HuntAndFill::step)
      .def_readwrite("growth", &HuntAndFill::growth)
      .def_readwrite("tolerance", &HuntAndFill::tolerance)
      .def_readwrite("max_runs", &HuntAndFill::max_runs);
}

}  // namespace polydem::python
