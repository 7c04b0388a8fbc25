// polydem._polydem.Run: a SceneRun (run/run_scene.hpp) driven from Python.
//
// advance() releases the GIL; the Python half (polydem/run.py) calls it in
// chunks and runs callbacks, progress and the instability exception between
// them. State arrays are numpy views of the block state where its layout
// allows (Vec3 and Quat arrays are contiguous doubles; Mat3 column-major):
// they live as long as the Run and show the state as it is now, changing
// in place as the run steps. Contacts and joint openings are copies (the
// contact arrays are rebuilt at each detection).
#include "python/bindings.hpp"

#include "io/deck.hpp"
#include "io/run_outputs.hpp"
#include "io/snapshots.hpp"
#include "io/summary.hpp"
#include "run/recorder.hpp"
#include "run/run_scene.hpp"
#include "run/scene_error.hpp"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>

namespace polydem::python {

namespace {

// A ground acceleration given as samples: time (s, increasing) and a (m/s²,
// n×3), linear between samples, zero outside them (before the first and
// after the last: the record has not started or has ended).
struct AccelerationTable {
  std::vector<double> time;
  std::vector<Vec3> acceleration;
  Vec3 operator()(double t) const {
    if (time.empty() || t < time.front() || t > time.back()) return Vec3::Zero();
    const auto it = std::upper_bound(time.begin(), time.end(), t);
    if (it == time.end()) return acceleration.back();
    const std::size_t k = static_cast<std::size_t>(it - time.begin());
    const double w = (t - time[k - 1]) / (time[k] - time[k - 1]);
    return (1.0 - w) * acceleration[k - 1] + w * acceleration[k];
  }
};

AccelerationTable acceleration_table(const py::array_t<double>& time, const py::array_t<double>& acc) {
  auto t = time.unchecked<1>();
  auto a = acc.unchecked<2>();
  if (a.shape(0) != t.shape(0) || a.shape(1) != 3)
    raise_python("DeckError", "key 'ground_acceleration': the accelerations must be an array of shape (len(time), 3)");
  if (t.shape(0) < 2) raise_python("DeckError", "key 'ground_acceleration': needs at least two samples");
  AccelerationTable table;
  for (py::ssize_t i = 0; i < t.shape(0); ++i) {
    if (!std::isfinite(t(i)) || (i > 0 && !(t(i) > t(i - 1))))
      raise_python("DeckError", "key 'ground_acceleration': the times must be finite and increasing (sample " +
                                    std::to_string(i + 1) + ")");
    const Vec3 v(a(i, 0), a(i, 1), a(i, 2));
    if (!v.allFinite())
      raise_python("DeckError", "key 'ground_acceleration': sample " + std::to_string(i + 1) + " is not finite");
    table.time.push_back(t(i));
    table.acceleration.push_back(v);
  }
  return table;
}

// A numpy view of a vector of fixed-size Eigen objects (`width` doubles
// each), kept alive by `owner`.
template <class T>
py::array view(const std::vector<T>& v, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
               py::handle owner) {
  py::array a(py::dtype::of<double>(), std::move(shape), std::move(strides),
              reinterpret_cast<const double*>(v.data()), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

py::array vec3s(const std::vector<Vec3>& v, py::handle owner) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  return view(v, {static_cast<py::ssize_t>(v.size()), 3}, {sizeof(Vec3), sizeof(double)}, owner);
}

py::array_t<double> copy_vec3s(const std::vector<Vec3>& v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < 3; ++k) w(static_cast<py::ssize_t>(i), k) = v[i][k];
  return a;
}

py::array_t<double> copy_vec3s(const Vec3Array& v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    w(static_cast<py::ssize_t>(i), 0) = v.x[i];
    w(static_cast<py::ssize_t>(i), 1) = v.y[i];
    w(static_cast<py::ssize_t>(i), 2) = v.z[i];
  }
  return a;
}

py::array_t<double> copy_quats(const std::vector<Quat>& q) {
  py::array_t<double> a({static_cast<py::ssize_t>(q.size()), py::ssize_t{4}});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < q.size(); ++i)
    for (int k = 0; k < 4; ++k) w(static_cast<py::ssize_t>(i), k) = q[i].coeffs()[k];
  return a;
}

// A history table as a dict of column name -> 1-D array (copies).
py::dict table_dict(const HistoryTable& t) {
  py::dict d;
  const std::size_t n = t.row_count(), c = t.columns.size();
  for (std::size_t j = 0; j < c; ++j) {
    py::array_t<double> col(static_cast<py::ssize_t>(n));
    auto w = col.mutable_unchecked<1>();
    for (std::size_t i = 0; i < n; ++i) w(static_cast<py::ssize_t>(i)) = t.rows[i * c + j];
    d[py::str(t.columns[j])] = col;
  }
  return d;
}

py::dict units_dict(const HistoryTable& t) {
  py::dict d;
  for (std::size_t j = 0; j < t.columns.size() && j < t.units.size(); ++j) d[py::str(t.columns[j])] = t.units[j];
  return d;
}

}  // namespace

// One run of a parsed scene. Outputs (snapshots during the run, results.h5
// and summary.json at the end) go to `out` when it is not empty, written by
// the same io/ code as `polydem run`.
class Run {
 public:
  Run(const Scene& scene, const std::string& out, int threads, RunControl control)
      : spec_(scene.spec), out_(out) {
    control.threads = threads;
    if (!out_.empty() && spec_.output.snapshot_interval > 0) {
      snapshots_ = std::make_unique<SnapshotWriter>(out_ + "/vtk", spec_.output.snapshot_joints);
      control.snapshot = [this](const Simulation& sim, double t) { snapshots_->write(sim, t); };
    }
    try {
      py::gil_scoped_release nogil;
      run_ = std::make_unique<SceneRun>(spec_, control);
    } catch (const SceneError& e) {
      raise_python("SceneError", locate_scene_error(e, spec_));
    }
    threads_ = run_->simulation().profile().threads_given;
    const Simulation& sim = run_->simulation();
    up_ = spec_.simulation.gravity.norm() > 0 ? Vec3(-spec_.simulation.gravity.normalized()) : Vec3(0, 0, 1);
    mesh_ = JointMesh::from_contacts(sim, up_, spec_.simulation.overlap_tolerance);
  }

  long advance(long max_steps, double until) {
    if (max_steps <= 0) return 0;
    py::gil_scoped_release nogil;
    return run_->advance(max_steps, until);
  }

  // The end: the report, and the outputs when there is a directory.
  void finish() {
    if (run_->finished()) return;
    {
      py::gil_scoped_release nogil;
      const RunReport& r = run_->finish();
      if (snapshots_) snapshots_->finish();
      if (!out_.empty()) write_run_outputs(out_, spec_, r, threads_);
    }
  }

  std::string summary_text() const {
    if (!run_->finished()) raise_python("PolydemError", "the run is not finished: call finish() first");
    return summary_json(spec_, run_->report(), threads_).dump(2);
  }

  const SceneRun& scene_run() const { return *run_; }
  const Simulation& sim() const { return run_->simulation(); }
  const SceneSpec& spec() const { return spec_; }
  const std::string& out() const { return out_; }
  int threads() const { return threads_; }

  // The initial mesh's joints and their openings now (m, > 0 open), as in
  // the recorder's walking channels (run/recorder.hpp).
  py::dict joint_openings() const {
    const auto n = static_cast<py::ssize_t>(mesh_.joints.size());
    py::array_t<int> a(n), b(n);
    py::array_t<bool> bed(n);
    py::array_t<double> opening(n);
    auto wa = a.mutable_unchecked<1>();
    auto wb = b.mutable_unchecked<1>();
    auto wbed = bed.mutable_unchecked<1>();
    auto wo = opening.mutable_unchecked<1>();
    for (py::ssize_t k = 0; k < n; ++k) {
      const InitialJoint& j = mesh_.joints[static_cast<std::size_t>(k)];
      wa(k) = j.a;
      wb(k) = j.b;
      wbed(k) = j.bed;
      wo(k) = mesh_.opening(sim(), j);
    }
    py::dict d;
    d["block_a"] = a;
    d["block_b"] = b;
    d["bed"] = bed;
    d["opening"] = opening;
    return d;
  }

  // Every subcontact now (copies): blocks, point, force on the incident
  // block, normal force, the blocks' overlap (m, > 0 closed), the spring's
  // crush (hold_normal_strain), tributary area.
  py::dict contacts() const {
    const Subcontacts& s = sim().contacts().sub;
    const auto n = static_cast<py::ssize_t>(s.size());
    py::array_t<int> ref(n), inc(n);
    py::array_t<double> normal(n), overlap(n), crush(n), area(n);
    auto wr = ref.mutable_unchecked<1>();
    auto wi = inc.mutable_unchecked<1>();
    auto wn = normal.mutable_unchecked<1>();
    auto wo = overlap.mutable_unchecked<1>();
    auto wc = crush.mutable_unchecked<1>();
    auto war = area.mutable_unchecked<1>();
    for (py::ssize_t k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(k);
      wr(k) = s.ref_block[i];
      wi(k) = s.inc_block[i];
      wn(k) = s.normal_force[i];
      wo(k) = s.geometric_overlap(i);
      wc(k) = s.crush[i];
      war(k) = s.area[i];
    }
    py::dict d;
    d["reference_block"] = ref;
    d["incident_block"] = inc;
    d["point"] = copy_vec3s(s.point);
    std::vector<Vec3> force(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) force[i] = sim().subcontact_force(i);  // the split scheme's rest too
    d["force"] = copy_vec3s(force);
    d["shear_force"] = copy_vec3s(s.shear_force);
    d["normal_force"] = normal;
    d["overlap"] = overlap;
    d["crush"] = crush;
    d["area"] = area;
    return d;
  }

 private:
  SceneSpec spec_;
  std::string out_;
  int threads_ = 1;
  std::unique_ptr<SnapshotWriter> snapshots_;
  std::unique_ptr<SceneRun> run_;
  Vec3 up_;
  JointMesh mesh_;
};

void bind_run(py::module_& m) {
  py::class_<Run>(m, "Run", "One run of a scene, step by step (use polydem.Run)")
      .def(py::init([](const Scene& scene, const std::string& out, int threads, py::object acceleration,
                       py::object acceleration_time) {
             RunControl control;
             if (!acceleration.is_none()) {
               if (!acceleration_time.is_none()) {
                 AccelerationTable table = acceleration_table(acceleration_time.cast<py::array_t<double>>(),
                                                              acceleration.cast<py::array_t<double>>());
                 control.ground_acceleration_final_time = table.time.back();
                 control.ground_acceleration = std::move(table);
               } else {
                 // A Python function of t, called once per step with the GIL.
                 py::function f = acceleration.cast<py::function>();
                 control.ground_acceleration = [f](double t) {
                   py::gil_scoped_acquire gil;
                   const auto a = f(t).cast<std::vector<double>>();
                   if (a.size() != 3) raise_python("DeckError", "key 'ground_acceleration': the function must return 3 values");
                   return Vec3(a[0], a[1], a[2]);
                 };
               }
             }
             return std::make_unique<Run>(scene, out, threads, std::move(control));
           }),
           py::arg("scene"), py::arg("out") = "", py::arg("threads") = 0, py::arg("acceleration") = py::none(),
           py::arg("acceleration_time") = py::none())
      .def("advance", &Run::advance, py::arg("max_steps"),
           py::arg("until") = std::numeric_limits<double>::infinity())
      .def("finish", &Run::finish)
      .def("summary_text", &Run::summary_text)
      .def_property_readonly("over", [](const Run& r) { return r.scene_run().over(); })
      .def_property_readonly("finished", [](const Run& r) { return r.scene_run().finished(); })
      .def_property_readonly("unstable", [](const Run& r) { return r.scene_run().report().unstable; })
      .def_property_readonly("instability", [](const Run& r) { return r.scene_run().report().instability; })
      .def_property_readonly("settled", [](const Run& r) { return r.scene_run().report().settled; })
      .def_property_readonly("time", [](const Run& r) { return r.sim().time(); })
      .def_property_readonly("end_time", [](const Run& r) { return r.spec().simulation.end_time; })
      .def_property_readonly("steps", [](const Run& r) { return r.sim().steps(); })
      .def_property_readonly("dt", [](const Run& r) { return r.sim().dt(); })
      .def_property_readonly("out", &Run::out)
      .def_property_readonly("threads", &Run::threads)
      .def_property_readonly("block_names", [](const Run& r) { return r.sim().blocks().props.name; })
      .def_property_readonly("masses",
                             [](const Run& r) {
                               const auto& m = r.sim().blocks().props.mass;
                               return py::array_t<double>(static_cast<py::ssize_t>(m.size()), m.data());
                             })
      .def_property_readonly("free",
                             [](const Run& r) {
                               const Blocks& b = r.sim().blocks();
                               py::array_t<bool> a(b.count);
                               auto w = a.mutable_unchecked<1>();
                               for (int i = 0; i < b.count; ++i) w(i) = b.is_free(i);
                               return a;
                             })
      // Views of the hot state (read-only; valid while the Run lives).
      .def_property_readonly("positions",
                             [](py::object self) {
                               return vec3s(self.cast<const Run&>().sim().blocks().state.position, self);
                             })
      .def_property_readonly("velocities",
                             [](py::object self) {
                               return vec3s(self.cast<const Run&>().sim().blocks().state.velocity, self);
                             })
      .def_property_readonly("angular_velocities",
                             [](py::object self) {
                               return vec3s(self.cast<const Run&>().sim().blocks().state.angular_velocity, self);
                             })
      .def_property_readonly("contact_forces",
                             [](py::object self) {
                               return vec3s(self.cast<const Run&>().sim().blocks().state.contact_force, self);
                             })
      .def_property_readonly("contact_torques",
                             [](py::object self) {
                               return vec3s(self.cast<const Run&>().sim().blocks().state.contact_torque, self);
                             })
      .def_property_readonly("orientations",
                             [](py::object self) {
                               static_assert(sizeof(Quat) == 4 * sizeof(double));
                               const auto& q = self.cast<const Run&>().sim().blocks().state.orientation;
                               return view(q, {static_cast<py::ssize_t>(q.size()), 4},
                                           {sizeof(Quat), sizeof(double)}, self);
                             })
      .def_property_readonly("rotations",
                             [](py::object self) {
                               static_assert(sizeof(Mat3) == 9 * sizeof(double));
                               const auto& r = self.cast<const Run&>().sim().blocks().state.rotation;
                               // Column-major 3×3: element (row, col) at col·3 + row.
                               return view(r, {static_cast<py::ssize_t>(r.size()), 3, 3},
                                           {sizeof(Mat3), sizeof(double), 3 * sizeof(double)}, self);
                             })
      .def_property_readonly("initial_positions",
                             [](py::object self) {
                               return vec3s(self.cast<const Run&>().sim().blocks().initial_position, self);
                             })
      .def_property_readonly("last_good_time", [](const Run& r) { return r.sim().last_good_time(); })
      .def_property_readonly("last_good_step", [](const Run& r) { return r.sim().last_good_step(); })
      .def("last_good_state",
           [](const Run& r) {
             const BlockState& s = r.sim().last_good_state();
             py::dict d;
             d["time"] = r.sim().last_good_time();
             d["step"] = r.sim().last_good_step();
             d["positions"] = copy_vec3s(s.position);
             d["orientations"] = copy_quats(s.orientation);
             d["velocities"] = copy_vec3s(s.velocity);
             d["angular_velocities"] = copy_vec3s(s.angular_velocity);
             return d;
           })
      .def("energies",
           [](const Run& r) {
             const EnergyLedger e = r.sim().energies();
             py::dict d;
             d["kinetic"] = e.kinetic;
             d["gravitational"] = e.gravitational;
             d["strain"] = e.strain;
             d["slip"] = e.slip;
             d["damping"] = e.damping;
             d["load_work"] = e.load_work;
             d["balance"] = e.balance;
             d["numerical_at_detections"] = r.sim().contacts().numerical_at_detections();
             return d;
           })
      .def("ground_acceleration",
           [](const Run& r) {
             const GroundMotion& g = r.sim().ground_motion();
             const double t = r.sim().time();
             Vec3 a = g.any_active() ? g.acceleration_vector(t) : Vec3(Vec3::Zero());
             if (g.extra) {
               py::gil_scoped_release nogil;  // a Python function takes the GIL itself
               a += g.extra(t);
             }
             return std::vector<double>{a.x(), a.y(), a.z()};
           })
      .def("joint_openings", &Run::joint_openings)
      .def("contacts", &Run::contacts)
      .def("histories",
           [](const Run& r) {
             if (!r.scene_run().finished()) raise_python("PolydemError", "the run is not finished: call finish() first");
             return py::make_tuple(table_dict(r.scene_run().report().histories),
                                   units_dict(r.scene_run().report().histories));
           })
      .def("energy_histories",
           [](const Run& r) {
             if (!r.scene_run().finished()) raise_python("PolydemError", "the run is not finished: call finish() first");
             return py::make_tuple(table_dict(r.scene_run().report().energies),
                                   units_dict(r.scene_run().report().energies));
           });
}

}  // namespace polydem::python
