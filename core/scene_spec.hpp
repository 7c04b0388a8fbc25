// What a deck describes, as plain data (one struct per deck section).
//
// io/deck.cpp fills these from TOML and validates every value once, naming
// the deck file, line and key on error; everything after that trusts them.
// Units are SI throughout (m, kg, s, N, Pa); angles in decks are degrees and
// are stored here in degrees too (the joint law converts once).
#pragma once

#include "geometry/polyhedron.hpp"
#include "core/units.hpp"

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace polydem {

// How each detection bounds the highest frequency of the blocks on their
// joints (integrators/critical_time_step.hpp): `block` takes each block on its
// joints with its neighbours held and multiplies by √2; `joint` shares each
// joint between its two blocks in the ratio of their stiffness. Both are
// proved upper bounds and both runs start from the all-faces estimate;
// `joint` usually allows a larger step (1.14× on the spire, 0.999× on the
// horseshoe arch), `block` is the default every documented figure was
// measured with.
enum class StepBound { block, joint };

// How the joints' stiffness-proportional dashpots enter the step
// (integrators/split_damping.hpp): `explicit_lagged` ("explicit") applies
// each dashpot with the spring, from the velocities at t − dt/2, as 3DEC
// does, and the step pays for it (half the springs' step at the spire's
// stiffest stones); `split` applies part of it with the spring and the rest
// from the velocities after the update, before the blocks move, and the step
// is the springs' one up to ξ ≈ 0.5 and twice the explicit one at the
// spire's ξ = 0.83, for a second pass over the subcontacts each step.
enum class DampingScheme { explicit_lagged, split };

// How a joint's forces are computed (contact/joint_law.hpp,
// contact/overlap_joint.hpp): `subcontacts` samples it at points fixed in the
// blocks between detections, 3DEC style; `overlap` integrates a Winkler
// layer over the blocks' current overlap at every step, with the shear and
// twist of the joint taken whole.
enum class JointModel { subcontacts, overlap };

// What re-samples the joints (contact/detection.hpp): `scene`, the whole
// contact set once any two blocks may have moved relative to each other by
// the detection travel; `pair`, each pair on its own once its two blocks
// have moved relative to each other by the travel since the pair was
// sampled, and the whole scene (for new pairs) once any two blocks may have
// closed by half the margin. `automatic`: `pair` under the subcontact
// model, `scene` under the overlap model (which samples nothing).
enum class DetectionTrigger { automatic, scene, pair };

// Where a subcontact's point is between detections (contact/moving_points.hpp):
// `detection`, fixed in the incident block where the detection's clip put it,
// with the area it gave; `step`, where its definition in the blocks'
// geometry (a corner of the incident face, an incident edge's crossing with a
// side plane, a reference corner's line on the incident face) puts it at
// every step, with its share of the polygon by its corner's angle, taken at
// the detection; `clip`, the pair's face polygon clipped again at every step,
// each point its vertex now with its corner's share of the polygon now, and
// the load the exact gradient of the springs' energy (contact/clip_joint.hpp).
// `automatic`: `clip` where the joints are re-sampled pair by pair (the
// default), `detection` where scene-wide or under the overlap model.
enum class JointSampling { automatic, detection, step, clip };

// [simulation]
struct SimulationSpec {
  double end_time = 1.0;          // s, > 0
  double time_step = 0.0;         // s; 0 = automatic. A deck may only lower the automatic step.
  double safety_factor = 0.8;     // fraction of the critical step, in (0, 1]
  StepBound time_step_bound = StepBound::block;
  DampingScheme damping_scheme = DampingScheme::explicit_lagged;
  JointModel joint_model = JointModel::subcontacts;
  Vec3 gravity{0.0, 0.0, -kGravity};  // m/s²
  double contact_margin = 0.0;    // m; 0 = automatic (2 % of the smallest block's size)
  // m; how far blocks may move relative to each other between two contact
  // detections, at most half the margin; 0 = automatic (subcontacts pair by
  // pair: 0.016 % of the smallest block's size, scene-wide 0.25 %; overlap
  // model: half the margin)
  double detection_travel = 0.0;
  DetectionTrigger detection_trigger = DetectionTrigger::automatic;
  JointSampling joint_sampling = JointSampling::automatic;
  int threads = 0;                // 0 = OpenMP default
  // Let the run drop to one thread while more are slower (a competing
  // process on a core; integrators/thread_governor.hpp). Same bits either way.
  bool adaptive_threads = true;
  double overlap_tolerance = 1e-6;  // m; blocks overlapping more than this at t = 0 are an error
  // Stop early when every free block's speed stays below this for
  // settle_time (0 = never stop early). m/s.
  double settle_velocity = 0.0;
  double settle_time = 0.0;
  // Gravity rises linearly from 0 over this time (s), then holds; 0 = applied
  // in full at t = 0 (core/loads.hpp gravity_at).
  double gravity_rise_time = 0.0;
};

// Whether the run re-samples its joints pair by pair (DetectionTrigger).
inline bool pair_by_pair(const SimulationSpec& s) {
  return s.detection_trigger == DetectionTrigger::pair ||
         (s.detection_trigger == DetectionTrigger::automatic && s.joint_model == JointModel::subcontacts);
}

// The run's joint sampling, `automatic` resolved (JointSampling).
inline JointSampling joint_sampling_of(const SimulationSpec& s) {
  if (s.joint_sampling != JointSampling::automatic) return s.joint_sampling;
  return pair_by_pair(s) ? JointSampling::clip : JointSampling::detection;
}

// [equilibrium] : a static stage before the dynamic one, as 3DEC's
// `model solve` (run/equilibrium.hpp): gravity only, Cundall's local damping
// on every free block, stepped until the unbalanced-force ratio is below
// `ratio`. The dynamic stage then starts from that state at t = 0, at rest.
struct EquilibriumSpec {
  bool enabled = false;         // true when the deck has the section (enabled = false switches it off)
  double ratio = 1e-5;          // unbalanced-force ratio tolerance, > 0
  long max_steps = 1000000;     // more without convergence is an error
  double local_damping = 0.8;   // alpha, in (0, 1)
  // Density scaling: each block's inertia set in the stage so that it
  // vibrates at the step's frequency over √(1 + α)
  // (integrators/static_stage.hpp).
  bool density_scaling = false;
  int deck_line = 0;
};

// [joint] : the Coulomb joint law of every contact (compression positive).
// Which normal force bounds a joint's friction (`[joint] friction_normal_force`):
// the spring's (3DEC's) or the spring's and the dashpot's together.
enum class FrictionNormal { elastic, total };

struct JointSpec {
  double normal_stiffness = 98e9;    // kn, Pa/m (Table 1)
  double shear_stiffness = 39.2e9;   // ks, Pa/m (0.4 kn unless given)
  double friction_angle = 30.0;      // degrees (Table 1)
  double cohesion = 0.0;             // Pa
  double tensile_strength = 0.0;     // Pa
  double damping = 2.1e-5;           // stiffness-proportional beta, s (Table 1)
  FrictionNormal friction_normal = FrictionNormal::elastic;
};

// [[joint]] with `between`: the law of the joints between blocks of two
// groups (the same group twice: the joints inside it). Every key it does not
// give is the default law's (the deck's [joint], or its [[joint]] without
// `between`). A contact between blocks whose pair of groups has no entry
// (or a block without a group) takes the default law.
struct JointPairSpec {
  std::string group_a, group_b;
  JointSpec joint;
  int deck_line = 0;
};

// [[group]] : settings of one group of blocks (the blocks are named into it
// by `[[block]] group` or by their generator).
struct GroupSpec {
  std::string name;
  double density = 0;  // kg/m³; 0 = the blocks' own (applied to the BlockSpecs by the reader)
  int deck_line = 0;
};

// A piecewise-linear history f(t) through the points (time[k], value[k]),
// constant beyond the ends; empty = the constant 1 (a load) or the given
// vector (a prescribed velocity).
struct TimeTable {
  std::vector<double> time;   // s, increasing
  std::vector<Vec3> value;    // one vector per time (a factor: (f, 0, 0))
  bool empty() const { return time.empty(); }
};

// [[load]] : a point force and/or a moment on each selected free block
// (3DEC's `block apply`), times a factor f(t) (1 without a table).
struct LoadSpec {
  std::vector<std::string> blocks, groups;  // the selection (union)
  Vec3 force = Vec3::Zero();   // N, world
  Vec3 moment = Vec3::Zero();  // N·m, world
  bool at_point = false;       // false: at the centroid
  Vec3 point = Vec3::Zero();   // m, world at t = 0 (moves with the block)
  TimeTable factor;            // value[k].x() is the factor
  int deck_line = 0;
};

// [[prescribe]] : the selected blocks become kinematic and move with a
// prescribed velocity (and angular velocity about their centroid) (3DEC's
// `block fix` with a velocity): constant, or a table of (t, vx, vy, vz).
struct PrescribeSpec {
  std::vector<std::string> blocks, groups;
  Vec3 velocity = Vec3::Zero();          // m/s (without a table)
  Vec3 angular_velocity = Vec3::Zero();  // rad/s (without a table)
  TimeTable velocity_table;              // (t, v): replaces `velocity` when given
  // (t, u): the displacement from the block's position at t = 0 (zero at
  // t = 0); replaces `velocity` when given. The block is put at x0 + u(t)
  // exactly and moves over each step with the mean velocity (u(t+dt) − u(t))/dt.
  TimeTable displacement_table;
  int deck_line = 0;
};

enum class BlockMotion { free, fixed, kinematic };

// [[block]] : one block. Shapes are built by io from the deck keys
// (shape = "box" | "prism" | "hull") and stored here in world coordinates.
struct BlockSpec {
  std::string name;          // unique; used by histories and checks
  Polyhedron shape;          // world coordinates at t = 0
  double density = 2600.0;   // kg/m³
  BlockMotion motion = BlockMotion::free;
  Vec3 velocity = Vec3::Zero();          // m/s at t = 0
  Vec3 angular_velocity = Vec3::Zero();  // rad/s at t = 0
  int course = -1;           // masonry course index (spire), -1 if none
  // The block's group (3DEC's `group`): a name that joint properties,
  // densities, loads, histories and the assessment can select by. Generators
  // name it after what the block is ("course03", "voussoir", "drum", "tip");
  // a [[block]] gives it with `group = "..."`; empty = no group.
  std::string group;
  int deck_line = 0;         // line of the [[block]] header in the deck, for messages
};

// [ground_motion] : horizontal ground acceleration a_g(t)·direction.
// applied_as = body_force: every free block feels -m·a_g (inertial force);
//              kinematic:  kinematic blocks move with velocity ∫a_g dt.
enum class GroundMotionKind { none, constant, ramp, sine_pulse, record };
enum class GroundMotionApplication { body_force, kinematic };
struct GroundMotionSpec {
  GroundMotionKind kind = GroundMotionKind::none;
  GroundMotionApplication applied_as = GroundMotionApplication::body_force;
  Vec3 direction{1.0, 0.0, 0.0};  // unit, horizontal
  double start_time = 0.0;        // s: zero before
  double acceleration = 0.0;      // m/s²: constant value, or pulse amplitude a_p
  double rise_time = 0.0;         // s: a constant acceleration rises linearly over this time, then holds
  double rate = 0.0;              // m/s³: ramp a = rate·(t - start_time)
  double period = 1.0;            // s: one-sine pulse a_p·sin(2π(t-t0)/T_p) for 0 ≤ t-t0 ≤ T_p
  std::string record_path;        // record file (PEER .AT2, ESM .ASC or two-column CSV), resolved relative to the deck
  // The record's samples, read with the deck (kind = record only): time (s)
  // and acceleration (m/s², before `scale`). A run never opens a file.
  std::vector<double> record_time, record_acceleration;
  double scale = 1.0;             // record multiplier
  // The supporting tower's fundamental mode as a linear filter (paper 3.4):
  // the record drives a damped oscillator of this frequency and its absolute
  // acceleration is the motion at the spire's base. 0 = no filter.
  double tower_frequency = 0.0;   // Hz
  double tower_damping = 0.05;    // damping ratio
  // [[ground_motion.component]]: further components (any direction, e.g.
  // the second horizontal and the vertical record of a PEER NGA set), each
  // its own kind, direction, start time, scale and record; applied as this
  // section says (applied_as); no tower filter.
  std::vector<GroundMotionSpec> components;
  int deck_line = 0;
};

// [output]
// A history of a group: "group:NAME.QUANTITY" (HistorySpec::block is then
// "group:NAME"); quantities position, velocity, contact_force (run/recorder.hpp).
inline constexpr std::string_view kGroupPrefix = "group:";
struct HistorySpec {
  std::string block;     // block name, or "group:" + group name
  std::string quantity;  // "position" | "velocity" | "rotation" | "angular_velocity" | "contact_force"
};
struct OutputSpec {
  double history_interval = 0.0;  // s; 0 = every step
  std::vector<HistorySpec> histories;
  bool energies = true;
  // Histories of the largest joint openings (bed and vertical joints): the
  // stones' "walking" under an earthquake (paper 3.4).
  bool walking = false;
  // ParaView snapshots (a .pvd series of .vtu files) every this many
  // seconds; 0 = none. Joints (the contact patches) go in a second series.
  double snapshot_interval = 0.0;
  bool snapshot_joints = true;
  // Checkpoints of the whole run state (DIR/checkpoint.bin, the latest
  // only) every this many seconds of simulated time; 0 = none. A run can be
  // continued from one (polydem run --restart DIR) with the same result.
  double checkpoint_interval = 0.0;
};

// [assessment] : how a run is judged, on where the blocks end up
// (run/assessment.hpp). A free block whose centroid ends more than
// damage_displacement from where it started is visible damage; one that
// ends more than collapse_displacement away is dislodged (a stone lost),
// and fallen if it ends that far below its place. The structure has
// collapsed when the dislodged blocks make up collapse_mass_fraction of the
// free blocks' mass at the end, or when the fallen blocks do during the run. The monitor
// block (default: the highest free block, the spire's tip) gives the
// collapse mode: Mode I if its horizontal displacement along the ground
// motion changed sign before collapse (it rocked back and impacted), Mode II
// if not (Zhang & Makris 2001, paper section 3.3).
struct AssessmentSpec {
  double damage_displacement = 0.005;  // m
  double collapse_displacement = 0.1;  // m
  // Collapse when the free blocks lost (dislodged at the end, or fallen)
  // make up at least this fraction of the free blocks' mass; 0: the first
  // one does.
  // 0.1: a tenth of the structure (the spire's solid tip is 11 % of it) has
  // come away, not one stone falling out of a standing structure.
  double collapse_mass_fraction = 0.1;
  bool stop_on_collapse = false;      // only once collapse is certain (the fallen mass)
  std::string monitor_block;           // empty: the highest free block against gravity
  std::string monitor_group;           // not empty: the highest free block of this group
  int deck_line = 0;
};

// [[check]] : a verification check evaluated after the run.
// kind: "resting_weight" | "no_drift" | "slide_acceleration" | "stick" |
//       "rocking_onset" | "housner_restitution" | "rocking_first_impact" |
//       "energy_conservation" | "energy_no_growth" | "pulse_peak_rotation"
// `expected` NaN means polydem computes the theoretical value itself.
struct CheckSpec {
  std::string kind;
  std::string block;  // block the check is about (if any)
  double expected = std::numeric_limits<double>::quiet_NaN();
  double tolerance = 0.01;  // relative unless the kind says otherwise
  int deck_line = 0;
};

// [ensemble] : replica `replica` of an ensemble (studies/ensemble.hpp): the
// deck with seeded perturbations that leave it "the same structure". The
// sizes are half-widths of uniform draws; replica 0 is the deck as written.
// The reader draws and applies the perturbation of replica > 0 and keeps
// what it drew in `drawn`.
struct EnsembleDraw {
  double friction_angle_shift = 0;    // degrees, added to every joint law's friction angle
  double normal_stiffness_factor = 1; // times every joint law's normal stiffness
  double shear_stiffness_factor = 1;  // times every joint law's shear stiffness
  double time_shift = 0;              // s, added to the ground motion's start times
  double largest_initial_speed = 0;   // m/s, the largest initial velocity added to a free block
};
struct EnsembleSpec {
  bool given = false;              // the deck (or an override) has the section
  long replica = 0;                // 0: no perturbation
  std::uint64_t seed = 1;
  double friction_angle = 0.5;     // degrees
  double stiffness = 0.05;         // fraction of kn and of ks
  double velocity = 5e-5;          // m/s, largest initial speed of a free block
  double time_shift = 0.5;         // fraction of the motion's sample step
  double sample_step = 0.01;       // s, the sample step of a pulse, ramp or constant motion
  EnsembleDraw drawn;
  int deck_line = 0;
};

// What the deck's generator sections were given (structures/generator_specs.hpp),
// kept for the analyses that rebuild a structure's block model from it (the
// refined lambda and the DEM frequency of the spire). core knows no
// generator: it holds them by name only; io fills them, run and the layers
// above read them.
struct GeneratorSpecs;

struct SceneSpec {
  std::string deck_path;  // as given on the command line
  std::string deck_text;  // verbatim, stored in results
  SimulationSpec simulation;
  JointSpec joint;                       // the default law
  std::vector<JointPairSpec> joint_pairs;  // [[joint]] with `between`
  std::vector<GroupSpec> groups;         // [[group]]
  std::vector<LoadSpec> loads;           // [[load]]
  std::vector<PrescribeSpec> prescribed; // [[prescribe]]
  std::vector<BlockSpec> blocks;  // [[block]] tables, then the generators' blocks
  std::shared_ptr<const GeneratorSpecs> generators;  // null when no deck made the scene
  GroundMotionSpec ground_motion;
  OutputSpec output;
  AssessmentSpec assessment;
  std::vector<CheckSpec> checks;
  EquilibriumSpec equilibrium;
  EnsembleSpec ensemble;
  // Warnings the deck reader found (a deck that is valid but probably not
  // what was meant), each "FILE:LINE: key 'KEY': what" like the errors.
  std::vector<std::string> warnings;
};

}  // namespace polydem
