#include "apps/run_command.hpp"
#include "core/units.hpp"

#include "apps/checkpoint.hpp"
#include "apps/scene_runner.hpp"
#include "geometry/polyhedron.hpp"
#include "io/atomic_file.hpp"
#include "io/deck.hpp"
#include "io/ground_motion_record.hpp"
#include "io/hdf5_results.hpp"
#include "io/json.hpp"
#include "io/vtk.hpp"

#include <fmt/core.h>
#include <omp.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

#ifndef POLYDEM_VERSION
#define POLYDEM_VERSION "0.1.0"
#endif

namespace polydem {

namespace {

Json summary_json(const SceneSpec& spec, const RunReport& r, int threads) {
  Json s = Json::object();
  s.set("polydem_version", POLYDEM_VERSION);
  s.set("deck", spec.deck_path);
  s.set("status", r.status);
  if (r.unstable) {
    s.set("instability", r.instability);
    s.set("last_good_time_s", r.last_good_time);
  }
  s.set("settled", r.settled);
  const Assessment& a = r.assessment;
  Json as = Json::object();
  as.set("collapse_mode", a.collapse_mode);
  as.set("collapse_time_s", a.collapse_time >= 0 ? Json(a.collapse_time) : Json());
  as.set("damage_time_s", a.damage_time >= 0 ? Json(a.damage_time) : Json());
  // Under a rising load this is the acceleration at which the mechanism formed.
  as.set("ground_acceleration_at_damage_g",
         a.damage_time >= 0 ? Json(a.ground_acceleration_at_damage / kGravity) : Json());
  as.set("max_displacement_m", a.max_displacement);
  as.set("max_displacement_block", a.max_displacement_block);
  as.set("max_residual_displacement_m", a.max_residual_displacement);
  as.set("monitor_block", a.monitor_block);
  as.set("monitor_peak_displacement_m", a.monitor_peak_displacement);
  as.set("moved_blocks", static_cast<int>(a.moved_blocks.size()));
  as.set("opened_joints", a.opened_joints);
  as.set("crack_angle_deg", a.crack_angle_deg >= 0 ? Json(a.crack_angle_deg) : Json());
  as.set("crack_lowest_z_m", a.crack_angle_deg >= 0 ? Json(a.crack_low_z) : Json());
  as.set("crack_highest_z_m", a.crack_angle_deg >= 0 ? Json(a.crack_high_z) : Json());
  s.set("assessment", std::move(as));
  if (!r.walking.bed_joint.empty() || !r.walking.vertical_joint.empty()) {
    Json w = Json::object();
    w.set("residual_bed_opening_m", r.walking.bed_opening);
    w.set("residual_bed_joint", r.walking.bed_joint);
    w.set("residual_vertical_opening_m", r.walking.vertical_opening);
    w.set("residual_vertical_joint", r.walking.vertical_joint);
    w.set("max_bed_opening_m", r.walking.max_bed_opening);
    w.set("max_vertical_opening_m", r.walking.max_vertical_opening);
    s.set("walking", std::move(w));
  }
  s.set("checks_passed", r.all_checks_passed());
  s.set("end_time_s", r.end_time);
  s.set("steps", r.steps);
  s.set("time_step_s", r.time_step);
  s.set("initial_time_step_s", r.initial_time_step);
  s.set("time_step_reductions", r.time_step_reductions);
  s.set("critical_time_step_s", r.critical.critical);
  s.set("highest_frequency_rad_s", r.critical.omega_max);
  s.set("damping_ratio_at_highest_frequency", r.critical.damping_ratio);
  s.set("contact_margin_m", r.margin);
  s.set("blocks", r.blocks);
  s.set("free_blocks", r.free_blocks);
  s.set("contact_detections", r.detections);
  s.set("subcontact_updates", r.subcontact_updates);
  if (r.checkpoints > 0) {
    Json c = Json::object();
    c.set("written", r.checkpoints);
    c.set("state_bytes", r.checkpoint_bytes);
    c.set("wall_seconds", r.checkpoint_wall_seconds);
    s.set("checkpoints", std::move(c));
  }
  s.set("threads", threads);
  s.set("wall_seconds", r.wall_seconds);
  s.set("subcontact_updates_per_second", r.wall_seconds > 0 ? r.subcontact_updates / r.wall_seconds : 0.0);
  Json e = Json::object();
  e.set("kinetic_J", r.energy.kinetic);
  e.set("gravitational_J", r.energy.gravitational);
  e.set("strain_J", r.energy.strain);
  e.set("slip_dissipation_J", r.energy.slip);
  e.set("damping_dissipation_J", r.energy.damping);
  e.set("load_work_J", r.energy.load_work);
  e.set("balance_J", r.energy.balance);
  e.set("reference_J", r.energy_reference);
  s.set("energy", std::move(e));
  s.set("energy_balance_error", r.energy_balance_error);
  Json checks = Json::array();
  for (const CheckResult& c : r.checks) {
    Json j = Json::object();
    j.set("name", c.name);
    j.set("measured", c.measured);
    j.set("expected", c.expected);
    j.set("tolerance", c.tolerance);
    j.set("unit", c.unit);
    j.set("passed", c.passed);
    j.set("note", c.note);
    checks.push_back(std::move(j));
  }
  s.set("checks", std::move(checks));
  return s;
}

void write_table(ResultsFile& f, const std::string& group, const HistoryTable& t) {
  const std::size_t rows = t.row_count(), cols = t.columns.size();
  for (std::size_t c = 0; c < cols; ++c) {
    std::vector<double> col(rows);
    for (std::size_t r = 0; r < rows; ++r) col[r] = t.rows[r * cols + c];
    f.write_vector(group + "/" + t.columns[c], col, t.units[c]);
  }
}

// ParaView output: one .vtu per snapshot for the blocks and one for the
// joints, listed in .pvd series written at the end.
class SnapshotWriter {
 public:
  explicit SnapshotWriter(std::string dir, bool joints) : dir_(std::move(dir)), joints_(joints) {
    std::filesystem::create_directories(dir_);
  }

  void write(const Simulation& sim, double time) {
    const Blocks& b = sim.blocks();
    std::vector<Polyhedron> shapes;
    std::vector<int> id, course;
    std::vector<Vec3> disp, vel;
    for (int i = 0; i < b.count; ++i) {
      shapes.push_back(world_shape(b, i));
      id.push_back(i);
      course.push_back(b.props.course[i]);
      disp.push_back(b.state.position[i] - b.initial_position[i]);
      vel.push_back(b.state.velocity[i]);
    }
    VtkCellData data;
    data.add_ints("block_id", id).add_ints("course", course).add_vectors("displacement", disp).add_vectors("velocity",
                                                                                                           vel);
    const std::string name = fmt::format("blocks_{:05d}.vtu", count_);
    write_vtu(dir_ + "/" + name, shapes, data);
    blocks_.push_back({time, name});
    if (joints_) {
      const ContactSet& c = sim.contacts();
      std::vector<std::vector<Vec3>> polys;
      std::vector<double> fn, fs, opening, slip;
      for (const ContactPair& p : c.pairs) {
        if (p.count == 0) continue;
        std::vector<Vec3> poly;
        double n = 0, t = 0, open = -std::numeric_limits<double>::infinity(), e = 0;
        for (int s = p.first; s < p.first + p.count; ++s) {
          poly.push_back(c.sub.point[s]);
          n += c.sub.normal_force[s];
          t += c.sub.shear_force[s].norm();
          open = std::max(open, -c.sub.overlap[s]);
          e += c.sub.slip_energy[s];
        }
        polys.push_back(std::move(poly));
        fn.push_back(n);
        fs.push_back(t);
        opening.push_back(open);
        slip.push_back(e);
      }
      VtkCellData jd;
      jd.add_scalars("normal_force", fn).add_scalars("shear_force", fs).add_scalars("opening", opening).add_scalars(
          "slip_energy", slip);
      const std::string jname = fmt::format("joints_{:05d}.vtu", count_);
      write_vtu_polygons(dir_ + "/" + jname, polys, jd);
      joints_series_.push_back({time, jname});
    }
    ++count_;
  }

  void finish() {
    if (!blocks_.empty()) write_pvd(dir_ + "/blocks.pvd", blocks_);
    if (!joints_series_.empty()) write_pvd(dir_ + "/joints.pvd", joints_series_);
  }

  // Checkpoints: the series so far. A restart continues the numbering and
  // overwrites the snapshots written after the checkpoint.
  void save(ByteWriter& w) const {
    w.put(static_cast<std::int32_t>(count_));
    for (const auto* series : {&blocks_, &joints_series_}) {
      w.put(static_cast<std::uint64_t>(series->size()));
      for (const PvdEntry& e : *series) {
        w.put(e.time);
        w.put(e.file);
      }
    }
  }
  void load(ByteReader& r) {
    std::int32_t count = 0;
    r.get(count);
    count_ = count;
    for (auto* series : {&blocks_, &joints_series_}) {
      std::uint64_t n = 0;
      r.get(n);
      if (n > r.remaining()) throw StateFormatError("snapshot series: count beyond the data");
      series->resize(static_cast<std::size_t>(n));
      for (PvdEntry& e : *series) {
        r.get(e.time);
        r.get(e.file);
      }
    }
  }

 private:
  std::string dir_;
  bool joints_;
  int count_ = 0;
  std::vector<PvdEntry> blocks_, joints_series_;
};

void print_report(const RunReport& r, const std::string& out_dir) {
  std::cerr << fmt::format("polydem: {} steps of {:.3e} s to t = {:.4g} s in {:.2f} s ({:.3g} subcontact updates/s)\n",
                           r.steps, r.time_step, r.end_time, r.wall_seconds,
                           r.wall_seconds > 0 ? r.subcontact_updates / r.wall_seconds : 0.0);
  std::cerr << fmt::format("polydem: energy balance error {:.3e} (relative)\n", r.energy_balance_error);
  for (const CheckResult& c : r.checks)
    std::cerr << fmt::format("  check {:<34} measured {:>13.6g} expected {:>13.6g} tol {:>9.3g} {} [{}]\n", c.name,
                             c.measured, c.expected, c.tolerance, c.unit, c.passed ? "passed" : "FAILED");
  std::cerr << "polydem: results in " << out_dir << "/summary.json and " << out_dir << "/results.h5\n";
}

}  // namespace

int run_command(const RunOptions& o) {
  SceneSpec spec;
  try {
    spec = o.use_default ? parse_deck(default_deck_text(), "<built-in default deck>", o.overrides)
                         : read_deck(o.deck_path, o.overrides);
  } catch (const std::exception& e) {
    std::cerr << "polydem: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  // Checkpoints and restarts: the fingerprint ties a checkpoint to the deck
  // text, the overrides, the record's bytes and the polydem version.
  const std::string out_dir = o.restart_dir.empty() ? o.out_dir : o.restart_dir;
  std::string restart_state;
  std::uint64_t fingerprint = 0;
  if (spec.output.checkpoint_interval > 0 || !o.restart_dir.empty()) {
    fingerprint = run_fingerprint(spec, o.overrides);
  }
  if (!o.restart_dir.empty()) {
    try {
      const std::string path = o.restart_dir + "/" + kCheckpointFile;
      restart_state = decode_checkpoint(read_checkpoint_file(path), fingerprint, path);
    } catch (const std::exception& e) {
      std::cerr << "polydem: error: " << e.what() << "\n";
      return exit_bad_input;
    }
  }

  RunControl control;
  control.threads = o.threads;
  if (!o.restart_dir.empty()) control.restart = &restart_state;
  if (spec.output.checkpoint_interval > 0) {
    control.checkpoint = [&out_dir, fingerprint, made = false](const std::string& state) mutable {
      if (!made) {
        std::filesystem::create_directories(out_dir);
        made = true;
      }
      write_file_atomic(out_dir + "/" + kCheckpointFile, encode_checkpoint(fingerprint, state));
    };
  }
  if (const char* kill = std::getenv("POLYDEM_KILL_AT_STEP")) control.kill_at_step = std::atol(kill);
  if (!o.quiet) {
    const bool tty = isatty(STDERR_FILENO);
    control.progress_every = 2000;
    control.progress = [tty, end = spec.simulation.end_time,
                        start = std::chrono::steady_clock::now(), last_print = -1.0](const Simulation& sim) mutable {
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!tty && wall - last_print < 5.0) return;
      last_print = wall;
      const double frac = sim.time() / end;
      const double eta = frac > 0 ? wall * (1 - frac) / frac : 0;
      std::cerr << fmt::format("{}t = {:.4f} / {:.4g} s  {:.0f} steps/s  dt = {:.3e} s  ETA {:.0f} s{}",
                               tty ? "\r" : "", sim.time(), end, sim.steps() / std::max(wall, 1e-9), sim.dt(), eta,
                               tty ? "   " : "\n");
    };
  }
  std::unique_ptr<SnapshotWriter> snapshots;
  if (spec.output.snapshot_interval > 0) {
    snapshots = std::make_unique<SnapshotWriter>(out_dir + "/vtk", spec.output.snapshot_joints);
    control.snapshot = [&snapshots](const Simulation& sim, double t) { snapshots->write(sim, t); };
    control.save_extra = [&snapshots](ByteWriter& w) { snapshots->save(w); };
    control.load_extra = [&snapshots](ByteReader& r) { snapshots->load(r); };
  }
  RunReport report;
  try {
    report = run_scene(spec, control);
  } catch (const StateFormatError& e) {
    std::cerr << "\npolydem: error: " << o.restart_dir << "/" << kCheckpointFile
              << ": the checkpoint does not fit this scene: " << e.what() << "\n";
    return exit_bad_input;
  } catch (const InstabilityError& e) {
    std::cerr << "\npolydem: stopped: " << e.what() << "\n";
    if (snapshots) snapshots->finish();  // the snapshots before the instability stay readable
    return exit_instability;
  } catch (const std::exception& e) {
    std::cerr << "\npolydem: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  if (!o.quiet && isatty(STDERR_FILENO)) std::cerr << "\n";
  if (snapshots) snapshots->finish();

  std::filesystem::create_directories(out_dir);
  {
    ResultsFile h5(out_dir + "/results.h5");
    h5.write_string("/deck", spec.deck_text);
    h5.write_attribute("/deck", "path", spec.deck_path);
    h5.write_attribute("/deck", "polydem_version", POLYDEM_VERSION);
    if (report.histories.columns.size() > 1) write_table(h5, "/histories", report.histories);
    if (!report.energies.columns.empty()) write_table(h5, "/energies", report.energies);
    h5.commit();
  }
  if (report.unstable) {
    write_vtu(out_dir + "/last_good_state.vtu", report.final_shapes);
    if (snapshots) snapshots->finish();
  }
  write_file_atomic(out_dir + "/summary.json", summary_json(spec, report, omp_get_max_threads()).dump(2) + "\n");
  if (report.unstable) {
    std::cerr << "\npolydem: stopped: " << report.instability << "\npolydem: last good state in " << out_dir
              << "/last_good_state.vtu, results so far in " << out_dir << "/summary.json and results.h5\n";
    return exit_instability;
  }
  if (!o.quiet) print_report(report, out_dir);
  return report.all_checks_passed() ? exit_success : exit_check_failed;
}

}  // namespace polydem
