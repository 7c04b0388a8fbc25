#include "apps/scene_runner.hpp"

#include "apps/checks.hpp"
#include "io/ground_motion_record.hpp"

#include <omp.h>

#include <csignal>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace polydem {

bool RunReport::all_checks_passed() const {
  return std::all_of(checks.begin(), checks.end(), [](const CheckResult& c) { return c.passed; });
}

int deck_line_of(const std::string& text, const std::string& key) {
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    if (line.compare(first, key.size(), key) == 0) {
      const auto rest = line.find_first_not_of(" \t", first + key.size());
      if (rest != std::string::npos && line[rest] == '=') return n;
    }
  }
  return 0;
}

namespace {

// One recorded quantity of one block.
struct Channel {
  int block;
  std::string quantity;
};

Vec3 rotation_vector(const Quat& q) {
  const Eigen::AngleAxisd aa(q);
  double angle = aa.angle();
  if (angle > M_PI) angle -= 2 * M_PI;
  return angle * aa.axis();
}

void append_channel(const Simulation& sim, const Channel& c, std::vector<double>& row) {
  const Blocks& b = sim.blocks();
  const int i = c.block;
  Vec3 v = Vec3::Zero();
  if (c.quantity == "position") v = sim.position_at_force_time(i);
  else if (c.quantity == "velocity") v = sim.velocity_at_force_time(i);
  else if (c.quantity == "angular_velocity") v = sim.angular_velocity_at_force_time(i);
  else if (c.quantity == "rotation")
    v = rotation_vector(sim.orientation_at_force_time(i) * b.initial_orientation[i].conjugate());
  else if (c.quantity == "contact_force") v = b.state.contact_force[i];
  row.insert(row.end(), {v.x(), v.y(), v.z()});
}

const char* unit_of(const std::string& q) {
  if (q == "position") return "m";
  if (q == "velocity") return "m/s";
  if (q == "angular_velocity") return "rad/s";
  if (q == "rotation") return "rad";
  if (q == "contact_force") return "N";
  return "-";
}

// The largest opening of the joints between blocks, split into bed joints
// (normal within 45° of vertical) and vertical joints. A joint's opening is
// the largest gap among its subcontacts (negative when it is closed).
struct Openings {
  double bed = 0, vertical = 0;
  int bed_pair = -1, vertical_pair = -1;
};
Openings joint_openings(const Simulation& sim, const Vec3& up) {
  Openings o;
  const ContactSet& c = sim.contacts();
  const auto& st = sim.blocks().state;
  for (std::size_t q = 0; q < c.pairs.size(); ++q) {
    const ContactPair& p = c.pairs[q];
    if (p.count == 0) continue;
    double gap = -std::numeric_limits<double>::infinity();
    for (int s = p.first; s < p.first + p.count; ++s) gap = std::max(gap, -c.sub.overlap[s]);
    const Vec3 n = st.rotation[p.ref_block] * c.sub.ref_normal_local[p.first];
    const bool bed = std::abs(n.dot(up)) > std::sqrt(0.5);
    double& best = bed ? o.bed : o.vertical;
    int& which = bed ? o.bed_pair : o.vertical_pair;
    if (gap > best) {
      best = gap;
      which = static_cast<int>(q);
    }
  }
  return o;
}

double automatic_margin(const Blocks& b) {
  double smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < b.count; ++i)
    if (b.props.motion[i] != BlockMotion::fixed) smallest = std::min(smallest, b.props.size[i]);
  if (!std::isfinite(smallest))
    for (int i = 0; i < b.count; ++i) smallest = std::min(smallest, b.props.size[i]);
  return 0.02 * smallest;
}

}  // namespace

RunReport run_scene(const SceneSpec& spec, const RunControl& control) {
  const auto wall_start = std::chrono::steady_clock::now();
  if (control.threads > 0) omp_set_num_threads(control.threads);
  RunReport rep;
  Blocks blocks = build_blocks(spec.blocks);
  rep.blocks = blocks.count;
  rep.free_blocks = static_cast<int>(blocks.free_blocks.size());
  rep.margin = spec.simulation.contact_margin > 0 ? spec.simulation.contact_margin : automatic_margin(blocks);

  // Time step: automatic, or the deck's if it is smaller.
  rep.critical = critical_time_step(blocks, spec.joint, spec.simulation.safety_factor);
  double dt = rep.critical.chosen;
  if (spec.simulation.time_step > 0) {
    if (rep.critical.chosen > 0 && spec.simulation.time_step > rep.critical.chosen) {
      std::ostringstream m;
      const int line = deck_line_of(spec.deck_text, "time_step");
      m << spec.deck_path << (line > 0 ? ":" + std::to_string(line) + ":" : std::string(": --set"))
        << " key 'simulation.time_step': " << spec.simulation.time_step
        << " s exceeds the stable step " << rep.critical.chosen << " s (critical " << rep.critical.critical
        << " s times safety factor " << spec.simulation.safety_factor << "); a deck may only lower it";
      throw std::runtime_error(m.str());
    }
    dt = spec.simulation.time_step;
  }
  if (dt <= 0) dt = spec.simulation.end_time / 1000.0;  // nothing moves: any step will do
  rep.time_step = dt;

  // Ground motion (a record is read only when the deck asks for one).
  GroundMotion motion;
  if (spec.ground_motion.kind == GroundMotionKind::record) {
    GroundMotionRecord rec = read_record(spec.ground_motion.record_path, 1.0);
    motion = make_ground_motion(spec.ground_motion, std::move(rec.time), std::move(rec.acceleration));
  } else {
    motion = make_ground_motion(spec.ground_motion);
  }

  Simulation sim(std::move(blocks), spec.simulation, spec.joint, std::move(motion), rep.margin, dt);
  sim.set_parallel_threshold(control.parallel_threshold);
  rep.initial_time_step = sim.dt();

  // Blocks must not overlap at the start beyond the tolerance.
  {
    const ContactSet& cs = sim.contacts();
    for (std::size_t s = 0; s < cs.sub.size(); ++s) {
      if (cs.sub.overlap[s] <= spec.simulation.overlap_tolerance) continue;
      const int r = cs.sub.ref_block[s], c = cs.sub.inc_block[s];
      const auto& pr = sim.blocks().props;
      const int line = std::max(pr.deck_line[r], pr.deck_line[c]);
      const std::string& late = pr.deck_line[r] >= pr.deck_line[c] ? pr.name[r] : pr.name[c];
      const std::string& other = late == pr.name[r] ? pr.name[c] : pr.name[r];
      std::ostringstream m;
      m << spec.deck_path << ":" << line << ": key 'block' ('" << late << "'): overlaps block '" << other << "' by "
        << cs.sub.overlap[s] << " m at the start (tolerance simulation.overlap_tolerance = "
        << spec.simulation.overlap_tolerance << " m)";
      throw std::runtime_error(m.str());
    }
  }

  AssessmentMonitor assessment(spec.assessment, sim);
  std::vector<std::unique_ptr<CheckMonitor>> monitors;
  for (const CheckSpec& c : spec.checks) monitors.push_back(make_check(c, spec, sim));

  // History channels: only what the deck asks for.
  std::vector<Channel> channels;
  rep.histories.columns.push_back("time");
  rep.histories.units.push_back("s");
  for (const HistorySpec& h : spec.output.histories) {
    const int i = sim.blocks().find(h.block);
    if (i < 0) continue;  // the deck reader has checked the names
    channels.push_back({i, h.quantity});
    for (const char* axis : {"x", "y", "z"}) {
      rep.histories.columns.push_back(h.block + "." + h.quantity + "." + axis);
      rep.histories.units.push_back(unit_of(h.quantity));
    }
  }
  const bool walking = spec.output.walking;
  const Vec3 up = spec.simulation.gravity.norm() > 0 ? Vec3(-spec.simulation.gravity.normalized()) : Vec3(0, 0, 1);
  const bool ground_channel = sim.ground_motion().active() && (!channels.empty() || walking);
  if (walking) {
    for (const char* c : {"walking.bed_opening", "walking.vertical_opening"}) {
      rep.histories.columns.push_back(c);
      rep.histories.units.push_back("m");
    }
  }
  if (ground_channel) {
    rep.histories.columns.push_back("ground.acceleration");
    rep.histories.units.push_back("m/s^2");
  }
  if (spec.output.energies) {
    rep.energies.columns = {"time", "kinetic", "gravitational", "strain", "slip", "damping", "load_work", "balance"};
    rep.energies.units = {"s", "J", "J", "J", "J", "J", "J", "J"};
  }
  const double interval = spec.output.history_interval;
  const long expected_rows = interval > 0 ? static_cast<long>(spec.simulation.end_time / interval) + 2
                                          : static_cast<long>(spec.simulation.end_time / dt) + 2;
  const bool any_history = !channels.empty() || walking;
  if (any_history) rep.histories.rows.reserve(expected_rows * rep.histories.columns.size());
  if (spec.output.energies) rep.energies.rows.reserve(expected_rows * rep.energies.columns.size());

  double next_record = 0.0;
  double balance0 = 0, reference = 0, worst = 0;
  bool first_energy = true;
  auto record = [&]() {
    const double t = std::max(0.0, sim.time() - sim.dt());  // force time
    if (any_history) {
      rep.histories.rows.push_back(t);
      for (const Channel& c : channels) append_channel(sim, c, rep.histories.rows);
      if (walking) {
        const Openings o = joint_openings(sim, up);
        rep.histories.rows.push_back(o.bed);
        rep.histories.rows.push_back(o.vertical);
        rep.walking.max_bed_opening = std::max(rep.walking.max_bed_opening, o.bed);
        rep.walking.max_vertical_opening = std::max(rep.walking.max_vertical_opening, o.vertical);
      }
      if (ground_channel) rep.histories.rows.push_back(sim.ground_motion().acceleration_at(t));
    }
    if (spec.output.energies) {
      const EnergyLedger e = sim.energies();
      rep.energies.rows.insert(rep.energies.rows.end(),
                               {t, e.kinetic, e.gravitational, e.strain, e.slip, e.damping, e.load_work, e.balance});
      if (first_energy) {
        balance0 = e.balance;
        first_energy = false;
      }
      reference = std::max(reference, e.kinetic + e.strain + std::abs(e.gravitational) + e.slip + e.damping +
                                          std::abs(e.load_work));
      worst = std::max(worst, std::abs(e.balance - balance0));
    }
  };

  const double end = spec.simulation.end_time;
  const bool snapshots = spec.output.snapshot_interval > 0 && control.snapshot;
  double next_snapshot = 0.0;
  double quiet_since = -1;
  const double checkpoint_interval = spec.output.checkpoint_interval;
  const bool checkpoints = checkpoint_interval > 0 && control.checkpoint;
  double next_checkpoint = checkpoint_interval;
  double wall_before = 0;  // s, spent before the restart

  // The runner's own state, in checkpoint order (see the header).
  constexpr std::uint32_t kRunnerTag = 0x52554e52;  // "RUNR"
  auto save_runner = [&](ByteWriter& w) {
    w.put(kRunnerTag);
    w.put(rep.histories.rows);
    w.put(rep.energies.rows);
    w.put(rep.walking.max_bed_opening);
    w.put(rep.walking.max_vertical_opening);
    w.put(rep.subcontact_updates);
    w.put(static_cast<std::int32_t>(rep.checkpoints + 1));  // counting the one being written
    w.put(rep.checkpoint_wall_seconds);
    for (double x : {next_record, balance0, reference, worst, next_snapshot, quiet_since, next_checkpoint}) w.put(x);
    w.put(first_energy);
    w.put(wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count());
  };
  auto load_runner = [&](ByteReader& r) {
    std::uint32_t tag = 0;
    r.get(tag);
    if (tag != kRunnerTag) throw StateFormatError("runner section missing");
    r.get(rep.histories.rows);
    r.get(rep.energies.rows);
    if (rep.histories.rows.size() % std::max<std::size_t>(1, rep.histories.columns.size()) != 0 ||
        (!rep.energies.columns.empty() && rep.energies.rows.size() % rep.energies.columns.size() != 0))
      throw StateFormatError("history rows do not fit the deck's columns");
    r.get(rep.walking.max_bed_opening);
    r.get(rep.walking.max_vertical_opening);
    r.get(rep.subcontact_updates);
    std::int32_t written = 0;
    r.get(written);
    rep.checkpoints = written;
    rep.checkpoint_bytes = static_cast<long>(control.restart->size());  // the last one written
    r.get(rep.checkpoint_wall_seconds);
    for (double* x : {&next_record, &balance0, &reference, &worst, &next_snapshot, &quiet_since, &next_checkpoint})
      r.get(*x);
    r.get(first_energy);
    r.get(wall_before);
  };
  std::string checkpoint_buffer;  // reused: one allocation for the run
  auto write_checkpoint = [&]() {
    const auto t0 = std::chrono::steady_clock::now();
    checkpoint_buffer.clear();
    ByteWriter w(checkpoint_buffer);
    sim.save_state(w);
    assessment.save(w);
    w.put(static_cast<std::uint64_t>(monitors.size()));
    for (const auto& m : monitors) m->save(w);
    save_runner(w);
    w.put(static_cast<bool>(control.save_extra));
    if (control.save_extra) control.save_extra(w);
    control.checkpoint(checkpoint_buffer);
    ++rep.checkpoints;
    rep.checkpoint_bytes = static_cast<long>(checkpoint_buffer.size());
    rep.checkpoint_wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };

  if (control.restart) {
    ByteReader r(*control.restart);
    sim.load_state(r);
    assessment.load(r);
    std::uint64_t count = 0;
    r.get(count);
    if (count != monitors.size())
      throw StateFormatError("the checkpoint has " + std::to_string(count) + " checks, the deck " +
                             std::to_string(monitors.size()));
    for (auto& m : monitors) m->load(r);
    load_runner(r);
    bool extra = false;
    r.get(extra);
    if (extra != static_cast<bool>(control.load_extra))
      throw StateFormatError("the caller's section does not fit (snapshots on one side only)");
    if (extra) control.load_extra(r);
    if (!r.at_end()) throw StateFormatError(std::to_string(r.remaining()) + " bytes left over");
    if (any_history) rep.histories.rows.reserve(expected_rows * rep.histories.columns.size());
    if (spec.output.energies) rep.energies.rows.reserve(expected_rows * rep.energies.columns.size());
  } else if (snapshots) {
    control.snapshot(sim, 0.0);
    next_snapshot = spec.output.snapshot_interval;
  }
  try {
    while (sim.time() < end - 0.5 * sim.dt()) {
      sim.step();
      rep.subcontact_updates += static_cast<long>(sim.contacts().sub.size());
      for (auto& m : monitors) m->observe(sim);
      assessment.observe(sim);
      if (spec.assessment.stop_on_collapse && assessment.collapsed()) break;
      if (sim.time() - sim.dt() >= next_record - 1e-12 * end) {
        record();
        next_record += interval > 0 ? interval : 0.0;
      }
      if (control.progress && sim.steps() % control.progress_every == 0) control.progress(sim);
      if (snapshots && sim.time() >= next_snapshot - 1e-12 * end) {
        control.snapshot(sim, sim.time());
        next_snapshot += spec.output.snapshot_interval;
      }
      if (spec.simulation.settle_velocity > 0) {
        double vmax = 0;
        for (int i : sim.blocks().free_blocks) vmax = std::max(vmax, sim.blocks().state.velocity[i].norm());
        if (vmax < spec.simulation.settle_velocity) {
          if (quiet_since < 0) quiet_since = sim.time();
          if (sim.time() - quiet_since >= spec.simulation.settle_time) {
            rep.settled = true;
            break;
          }
        } else {
          quiet_since = -1;
        }
      }
      if (checkpoints && sim.time() >= next_checkpoint - 1e-12 * end) {
        while (next_checkpoint <= sim.time() + 1e-12 * end) next_checkpoint += checkpoint_interval;
        write_checkpoint();
      }
      if (sim.steps() == control.kill_at_step) std::raise(SIGKILL);
    }
  } catch (const InstabilityError& e) {
    // Stop, but keep what was computed: the histories so far and the state
    // of the last passed check.
    rep.unstable = true;
    rep.instability = e.what();
  }
  if (spec.output.energies && !rep.unstable) record();  // the final state is always in the ledger
  if (snapshots && sim.time() > next_snapshot - spec.output.snapshot_interval + 1e-12 * end)
    control.snapshot(sim, sim.time());

  if (walking) {
    const Openings o = joint_openings(sim, up);
    auto name = [&](int q) {
      if (q < 0) return std::string();
      const ContactPair& p = sim.contacts().pairs[q];
      return sim.blocks().props.name[p.a] + "|" + sim.blocks().props.name[p.b];
    };
    rep.walking.bed_opening = o.bed;
    rep.walking.vertical_opening = o.vertical;
    rep.walking.bed_joint = name(o.bed_pair);
    rep.walking.vertical_joint = name(o.vertical_pair);
  }
  rep.assessment = assessment.finish(sim);
  rep.status = rep.assessment.status;
  rep.steps = sim.steps();
  rep.time_step = sim.dt();
  rep.time_step_reductions = sim.time_step_reductions();
  rep.end_time = sim.time();
  rep.detections = sim.contacts().detections;
  rep.energy = sim.energies();
  rep.energy_reference = reference;
  rep.energy_balance_error = reference > 0 ? worst / reference : 0.0;
  for (auto& m : monitors) rep.checks.push_back(m->finish(sim));
  const BlockState& final_state = rep.unstable ? sim.last_good_state() : sim.blocks().state;
  rep.final_position = final_state.position;
  rep.final_velocity = final_state.velocity;
  rep.final_orientation = final_state.orientation;
  if (rep.unstable) {
    rep.status = "unstable";
    rep.last_good_time = sim.last_good_time();
    for (int i = 0; i < sim.blocks().count; ++i)
      rep.final_shapes.push_back(transformed(sim.blocks().props.local_shape[i], final_state.rotation[i],
                                             final_state.position[i]));
  }
  rep.wall_seconds =
      wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return rep;
}

}  // namespace polydem
