// The deck reader. Layout of this file, top to bottom:
//   1. the schema (which keys each section accepts; deck_keys() lists it,
//      with the generators' sections of io/generators.hpp),
//   4. one reader per section, filling one struct of core/scene_spec.hpp,
//   5. overrides (applied to the parsed table before any validation),
//   6. the public entry points.
// Where an error is (2.) and the typed table reader (3.) are in
// io/deck_reader.hpp, shared with the generators' section readers.
// Every check is always on: a deck that passes here is trusted downstream.
#include "io/deck.hpp"
#include "io/cut_section.hpp"
#include "io/deck_reader.hpp"
#include "io/generators.hpp"
#include "io/ground_motion_record.hpp"
#include "io/record_processing.hpp"
#include "core/loads.hpp"
#include "core/materials.hpp"
#include "core/units.hpp"
#include "studies/ensemble.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace polydem {
namespace {

using namespace deck_reader;

// ---------------------------------------------------------------- 1. schema


constexpr std::string_view kSimulationKeys[] = {
    "end_time",          "time_step",       "safety_factor", "gravity",           "contact_margin",  "detection_travel",
    "threads",           "adaptive_threads", "overlap_tolerance", "settle_velocity", "settle_time",
    "gravity_rise_time", "time_step_bound", "damping_scheme",    "joint_model",
    "detection_trigger", "joint_sampling"};
constexpr std::string_view kJointKeys[] = {"normal_stiffness", "shear_stiffness",  "friction_angle",
                                           "cohesion",         "tensile_strength", "damping", "between",
                                           "friction_normal_force"};
constexpr std::string_view kGroupKeys[] = {"name", "density"};
constexpr std::string_view kLoadKeys[] = {"blocks", "groups", "force", "moment", "point", "table"};
constexpr std::string_view kPrescribeKeys[] = {"blocks", "groups", "velocity", "angular_velocity", "table",
                                               "displacement_table"};
constexpr std::string_view kBlockKeys[] = {"name",     "shape",    "size",   "center",   "polygon",
                                           "z",        "vertices", "rotation", "offset", "density",
                                           "motion",   "velocity", "angular_velocity", "course", "group"};
constexpr std::string_view kGroundMotionKeys[] = {"kind",           "applied_as", "direction", "start_time",
                                                  "acceleration",   "acceleration_g", "rate",  "rate_g",
                                                  "period",         "record",         "scale",
                                                  "rise_time",      "tower_frequency", "tower_damping",
                                                  "baseline_order", "length_scale",    "component"};
constexpr std::string_view kGroundMotionComponentKeys[] = {
    "kind", "direction", "start_time", "acceleration", "acceleration_g", "rate", "rate_g", "period", "record", "scale",
    "rise_time", "baseline_order", "length_scale"};
constexpr std::string_view kOutputKeys[] = {"history_interval",  "histories",       "energies",
                                            "walking",           "snapshot_interval", "snapshot_joints",
                                            "checkpoint_interval"};
constexpr std::string_view kAssessmentKeys[] = {"damage_displacement", "collapse_displacement", "stop_on_collapse",
                                                "monitor_block", "collapse_mass_fraction", "monitor_group"};
constexpr std::string_view kCheckKeys[] = {"kind", "block", "expected", "tolerance"};
constexpr std::string_view kEquilibriumKeys[] = {"enabled", "ratio", "max_steps", "local_damping", "density_scaling"};
constexpr std::string_view kEnsembleKeys[] = {"replica",  "seed",       "friction_angle", "stiffness",
                                              "velocity", "time_shift", "sample_step"};

struct SectionSchema {
  std::string_view name;
  bool array_of_tables;  // [[name]] rather than [name]
  std::span<const std::string_view> keys;
};
constexpr SectionSchema kSections[] = {
    {"simulation", false, kSimulationKeys}, {"joint", false, kJointKeys},
    {"block", true, kBlockKeys},            {"ground_motion", false, kGroundMotionKeys},
    {"output", false, kOutputKeys},         {"check", true, kCheckKeys},
    {"assessment", false, kAssessmentKeys}, {"equilibrium", false, kEquilibriumKeys},
    {"group", true, kGroupKeys},            {"load", true, kLoadKeys},
    {"prescribe", true, kPrescribeKeys},    {"ensemble", false, kEnsembleKeys},
};

// Keys that define a block's shape, by shape.
constexpr std::string_view kShapeKeys[] = {"size", "center", "polygon", "z", "vertices"};

constexpr std::string_view kHistoryQuantities[] = {"position", "velocity", "rotation", "angular_velocity",
                                                   "contact_force"};
constexpr std::string_view kGroupHistoryQuantities[] = {"position", "velocity", "contact_force"};
constexpr std::string_view kCheckKinds[] = {"resting_weight",      "no_drift",
                                            "slide_acceleration",  "stick",
                                            "rocking_onset",       "housner_restitution",
                                            "rocking_first_impact", "energy_conservation",
                                            "energy_no_growth",    "pulse_peak_rotation",
                                            "stack_pulse_peak_rotation"};

// ------------------------------------------------------ 4. section readers


SimulationSpec read_simulation(const Deck& deck) {
  const TableReader r(deck, table_or_empty(deck, "simulation"), "simulation", kSimulationKeys);
  SimulationSpec s;
  s.end_time = r.number("end_time", s.end_time, Range::positive);
  s.time_step = r.number("time_step", s.time_step, Range::non_negative);
  s.safety_factor = r.number("safety_factor", s.safety_factor, Range::positive);
  if (s.safety_factor > 1.0)
    r.fail("safety_factor", "must be in (0, 1] (got " + format_number(s.safety_factor) + ")");
  s.time_step_bound = r.choice<StepBound>("time_step_bound", {{"block", StepBound::block}, {"joint", StepBound::joint}},
                                          s.time_step_bound);
  s.damping_scheme = r.choice<DampingScheme>(
      "damping_scheme", {{"explicit", DampingScheme::explicit_lagged}, {"split", DampingScheme::split}},
      s.damping_scheme);
  s.joint_model = r.choice<JointModel>(
      "joint_model", {{"subcontacts", JointModel::subcontacts}, {"overlap", JointModel::overlap}}, s.joint_model);
  if (s.joint_model == JointModel::overlap && s.damping_scheme == DampingScheme::split)
    r.fail("joint_model", "\"overlap\" works with damping_scheme = \"explicit\" only");
  s.gravity = r.vec3("gravity").value_or(s.gravity);
  s.contact_margin = r.number("contact_margin", s.contact_margin, Range::non_negative);
  s.detection_travel = r.number("detection_travel", s.detection_travel, Range::non_negative);
  s.detection_trigger = r.choice<DetectionTrigger>(
      "detection_trigger", {{"scene", DetectionTrigger::scene}, {"pair", DetectionTrigger::pair}}, s.detection_trigger);
  if (s.joint_model == JointModel::overlap && s.detection_trigger == DetectionTrigger::pair)
    r.fail("detection_trigger", "\"pair\" re-samples subcontacts: it needs joint_model = \"subcontacts\"");
  s.joint_sampling = r.choice<JointSampling>(
      "joint_sampling",
      {{"automatic", JointSampling::automatic},
       {"detection", JointSampling::detection},
       {"step", JointSampling::step},
       {"clip", JointSampling::clip}},
      s.joint_sampling);
  if (s.joint_model == JointModel::overlap && s.joint_sampling != JointSampling::detection &&
      s.joint_sampling != JointSampling::automatic)
    r.fail("joint_sampling", std::string(s.joint_sampling == JointSampling::step ? "\"step\"" : "\"clip\"") +
                                 " moves subcontacts: it needs joint_model = \"subcontacts\"");
  if (s.joint_sampling == JointSampling::clip && s.detection_trigger == DetectionTrigger::scene)
    r.fail("joint_sampling", "\"clip\" re-samples a pair when its polygon's vertices change: it needs "
                             "detection_trigger = \"pair\" (the default)");
  if (const auto t = r.integer("threads")) {
    if (*t < 0 || *t > 4096) r.fail("threads", "must be in [0, 4096], 0 = OpenMP default (got " + std::to_string(*t) + ")");
    s.threads = static_cast<int>(*t);
  }
  s.adaptive_threads = r.boolean("adaptive_threads").value_or(s.adaptive_threads);
  s.overlap_tolerance = r.number("overlap_tolerance", s.overlap_tolerance, Range::non_negative);
  s.settle_velocity = r.number("settle_velocity", s.settle_velocity, Range::non_negative);
  s.settle_time = r.number("settle_time", s.settle_time, Range::non_negative);
  s.gravity_rise_time = r.number("gravity_rise_time", s.gravity_rise_time, Range::non_negative);
  return s;
}


// One joint law from a table: every key it does not give is `base`'s (the
// stiffness ratio: shear_stiffness follows normal_stiffness by `shear_ratio`
// unless the table gives it).
JointSpec read_joint_keys(const TableReader& r, const JointSpec& base, double shear_ratio, bool base_given_shear) {
  JointSpec j = base;
  j.normal_stiffness = r.number("normal_stiffness", base.normal_stiffness, Range::positive);
  const double ks_default =
      base_given_shear && !r.has("normal_stiffness") ? base.shear_stiffness
                                                     : joint_shear_stiffness(j.normal_stiffness, shear_ratio);
  j.shear_stiffness = r.number("shear_stiffness", ks_default, Range::positive);
  j.friction_angle = r.number("friction_angle", base.friction_angle, Range::non_negative);
  if (j.friction_angle >= 90.0)
    r.fail("friction_angle", "must be in [0, 90) degrees (got " + format_number(j.friction_angle) + ")");
  j.cohesion = r.number("cohesion", base.cohesion, Range::non_negative);
  j.tensile_strength = r.number("tensile_strength", base.tensile_strength, Range::non_negative);
  j.damping = r.number("damping", base.damping, Range::non_negative);
  j.friction_normal = r.choice<FrictionNormal>(
      "friction_normal_force", {{"elastic", FrictionNormal::elastic}, {"total", FrictionNormal::total}},
      base.friction_normal);
  return j;
}

// Friction on the total normal force bounds the dashpots' force, which the
// split scheme applies in part after the joint law (integrators/
// split_damping.hpp) where no cap can see it: refused with "split".
void refuse_total_friction_for_split(const Deck& deck, const SceneSpec& scene) {
  auto total = [](const JointSpec& j) { return j.friction_normal == FrictionNormal::total; };
  const std::string why = "friction_normal_force = \"total\" works with simulation.damping_scheme = \"explicit\" only";
  const toml::node* node = deck.root().get("joint");
  if (total(scene.joint)) deck.fail("joint", node, why);
  for (const JointPairSpec& p : scene.joint_pairs)
    if (total(p.joint))
      deck.fail("joint", node, "the law between '" + p.group_a + "' and '" + p.group_b + "': " + why);
}

// The overlap joint model's layer carries compression only
// (contact/overlap_joint.hpp): a law with cohesion or tensile strength is
// refused where it is given.
void refuse_bonds(const Deck& deck, const SceneSpec& scene, const std::string& setting,
                  const std::string& instead) {
  auto bonds = [](const JointSpec& j) { return j.cohesion > 0 || j.tensile_strength > 0; };
  const std::string why =
      "cohesion or tensile strength is not modelled by " + setting + " (compression and friction only); use " + instead;
  const toml::node* node = deck.root().get("joint");
  if (bonds(scene.joint)) deck.fail("joint", node, why);
  for (const JointPairSpec& p : scene.joint_pairs)
    if (bonds(p.joint))
      deck.fail("joint", node, "the law between '" + p.group_a + "' and '" + p.group_b + "': " + why);
}

JointSpec default_joint(const JointDefaults& defaults) {
  JointSpec j;
  j.normal_stiffness = defaults.normal_stiffness;
  j.shear_stiffness = joint_shear_stiffness(j.normal_stiffness, defaults.shear_ratio);
  return j;
}

// [joint] (one law for every joint) or
// [[joint]] (an array: the entry without `between` is the default, at most
// one; every other entry is the law between two groups, its missing keys the
// default's). TOML cannot hold both forms, so a deck chooses one; every deck
// written with [joint] stays valid and means what it meant.
struct JointSection {
  JointSpec joint;
  std::vector<JointPairSpec> pairs;
};

JointSection read_joints(const Deck& deck, const JointDefaults& defaults, const std::vector<BlockSpec>& blocks) {
  JointSection out;
  const toml::node* node = deck.root().get("joint");
  if (!node || node->as_table()) {
    const TableReader r(deck, table_or_empty(deck, "joint"), "joint", kJointKeys);
    if (r.has("between"))
      r.fail("between", "belongs to a [[joint]] entry (write the default law as a [[joint]] without `between` "
                        "and each pair of groups as a [[joint]] with it)");
    out.joint = read_joint_keys(r, default_joint(defaults), defaults.shear_ratio, false);
    return out;
  }
  const auto tables = section_tables(deck, "joint");
  // The default first, wherever it stands: the pairs inherit from it.
  int default_index = -1;
  for (std::size_t i = 0; i < tables.size(); ++i) {
    if (tables[i]->get("between")) continue;
    if (default_index >= 0) {
      deck.fail(indexed("joint", i + 1), tables[i],
                "a second [[joint]] without `between` (the default law is joint[" + std::to_string(default_index + 1) +
                    "]); give this one `between = [\"GROUP\", \"GROUP\"]`");
    }
    default_index = static_cast<int>(i);
  }
  if (default_index >= 0) {
    const TableReader r(deck, *tables[static_cast<std::size_t>(default_index)],
                        indexed("joint", static_cast<std::size_t>(default_index) + 1), kJointKeys);
    out.joint = read_joint_keys(r, default_joint(defaults), defaults.shear_ratio, false);
  } else {
    out.joint = default_joint(defaults);
  }
  for (std::size_t i = 0; i < tables.size(); ++i) {
    if (static_cast<int>(i) == default_index) continue;
    const TableReader r(deck, *tables[i], indexed("joint", i + 1), kJointKeys);
    JointPairSpec p;
    p.deck_line = r.line();
    const toml::node* between = r.table().get("between");
    const auto* arr = between->as_array();
    if (!arr || arr->size() != 2 || !arr->get(0)->as_string() || !arr->get(1)->as_string())
      r.fail("between", "must be a pair of group names [\"A\", \"B\"] (the same name twice for the joints "
                        "inside a group) (got " + describe(*between) + ")");
    p.group_a = arr->get(0)->as_string()->get();
    p.group_b = arr->get(1)->as_string()->get();
    for (const std::string* g : {&p.group_a, &p.group_b}) {
      if (std::none_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) { return b.group == *g; }))
        r.fail("between", "no block is in group " + in_quotes(*g) + " ([[block]] group, or a generator's groups)");
    }
    for (const JointPairSpec& q : out.pairs) {
      if ((q.group_a == p.group_a && q.group_b == p.group_b) || (q.group_a == p.group_b && q.group_b == p.group_a))
        r.fail("between", "the pair " + in_quotes(p.group_a) + ", " + in_quotes(p.group_b) +
                              " already has a law (the [[joint]] at line " + std::to_string(q.deck_line) + ")");
    }
    p.joint = read_joint_keys(r, out.joint, defaults.shear_ratio, true);
    out.pairs.push_back(std::move(p));
  }
  return out;
}

// R = Rz·Ry·Rx, angles in degrees.
Mat3 rotation_from_degrees(const std::vector<double>& deg) {
  const double k = std::numbers::pi / 180.0;
  return (Eigen::AngleAxisd(deg[2] * k, Vec3::UnitZ()) * Eigen::AngleAxisd(deg[1] * k, Vec3::UnitY()) *
          Eigen::AngleAxisd(deg[0] * k, Vec3::UnitX()))
      .toRotationMatrix();
}

// A listed hull vertex that the hull does not keep as a corner means the
// listed points are not in convex position: the block would silently differ
// from what the deck describes, so it is an error.
void check_convex_position(const TableReader& r, const std::vector<Vec3>& points, const Polyhedron& hull) {
  Eigen::AlignedBox3d box;
  for (const auto& p : points) box.extend(p);
  const double tol = 1e-9 * box.diagonal().norm();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool corner = std::any_of(hull.vertices.begin(), hull.vertices.end(),
                                    [&](const Vec3& v) { return (v - points[i]).norm() <= tol; });
    if (!corner) {
      const Vec3& p = points[i];
      r.fail("vertices", "not convex: vertex " + std::to_string(i + 1) + " [" + format_number(p.x()) + ", " +
                             format_number(p.y()) + ", " + format_number(p.z()) +
                             "] lies inside the convex hull of the others (or on one of its faces or edges); "
                             "list only the corners of a convex block");
    }
  }
}

Polyhedron read_shape(const TableReader& r) {
  const std::string shape = [&] {
    const auto s = r.string("shape");
    if (!s) r.missing("shape", "every block needs shape = \"box\", \"prism\" or \"hull\"");
    if (*s != "box" && *s != "prism" && *s != "hull")
      r.fail("shape", "must be one of \"box\", \"prism\", \"hull\" (got " + in_quotes(*s) + ")");
    return *s;
  }();
  const std::vector<std::string_view> own = shape == "box"     ? std::vector<std::string_view>{"size", "center"}
                                            : shape == "prism" ? std::vector<std::string_view>{"polygon", "z"}
                                                               : std::vector<std::string_view>{"vertices"};
  for (const auto& key : kShapeKeys) {
    if (r.has(key) && !contains(own, key))
      r.fail(key, "not used by shape " + in_quotes(shape) + " (it takes " + join(own) + ")");
  }

  std::string_view geometry_key;
  try {
    if (shape == "box") {
      geometry_key = "size";
      const auto size = r.vec3("size");
      if (!size) r.missing("size", "shape \"box\" needs size = [x, y, z] (m)");
      if (!(size->minCoeff() > 0))
        r.fail("size", "must be > 0 in every component (got [" + format_number(size->x()) + ", " +
                           format_number(size->y()) + ", " + format_number(size->z()) + "])");
      return make_box(*size, r.vec3("center").value_or(Vec3::Zero()));
    }
    if (shape == "prism") {
      geometry_key = "polygon";
      const auto poly = r.points("polygon", 2, "[x, y]");
      if (!poly) r.missing("polygon", "shape \"prism\" needs polygon = [[x, y], ...] (m)");
      if (poly->size() < 3)
        r.fail("polygon", "needs at least 3 points (got " + std::to_string(poly->size()) + ")");
      const auto z = r.numbers("z", 2, "[z0, z1]");
      if (!z) r.missing("z", "shape \"prism\" needs z = [z0, z1] (m)");
      if (!((*z)[1] > (*z)[0]))
        r.fail("z", "must have z1 > z0 (got [" + format_number((*z)[0]) + ", " + format_number((*z)[1]) + "])");
      std::vector<Vec2> polygon;
      for (const auto& p : *poly) polygon.emplace_back(p[0], p[1]);
      return make_prism(polygon, (*z)[0], (*z)[1]);
    }
    geometry_key = "vertices";
    const auto pts = r.points("vertices", 3, "[x, y, z]");
    if (!pts) r.missing("vertices", "shape \"hull\" needs vertices = [[x, y, z], ...] (m)");
    if (pts->size() < 4) r.fail("vertices", "needs at least 4 points (got " + std::to_string(pts->size()) + ")");
    std::vector<Vec3> points;
    for (const auto& p : *pts) points.emplace_back(p[0], p[1], p[2]);
    Polyhedron hull = convex_hull(points);
    check_convex_position(r, points, hull);
    return hull;
  } catch (const GeometryError& e) {
    r.fail(geometry_key, "invalid " + shape + ": " + e.what());
  }
}

BlockSpec read_block(const Deck& deck, const toml::table& t, std::size_t number) {
  const std::string path = indexed("block", number);
  const TableReader r(deck, t, path, kBlockKeys);
  BlockSpec b;
  b.deck_line = r.line();
  b.name = r.string("name").value_or("block" + std::to_string(number));
  if (b.name.empty()) r.fail("name", "must not be empty");

  Polyhedron shape = read_shape(r);
  const auto rotation = r.numbers("rotation", 3, "[rx, ry, rz] (degrees)");
  const Vec3 offset = r.vec3("offset").value_or(Vec3::Zero());
  if (rotation || r.has("offset")) {
    const Mat3 R = rotation ? rotation_from_degrees(*rotation) : Mat3::Identity();
    const Vec3 c = mass_properties(shape).centroid;
    // x -> R (x - c) + c + offset
    try {
      shape = transformed(shape, R, c - R * c + offset);
    } catch (const GeometryError& e) {
      r.fail(rotation ? "rotation" : "offset", std::string("invalid block after rotation/offset: ") + e.what());
    }
  }
  b.shape = std::move(shape);

  b.density = r.number("density", b.density, Range::positive);
  b.motion = r.choice<BlockMotion>(
      "motion", {{"free", BlockMotion::free}, {"fixed", BlockMotion::fixed}, {"kinematic", BlockMotion::kinematic}},
      b.motion);
  b.velocity = r.vec3("velocity").value_or(b.velocity);
  b.angular_velocity = r.vec3("angular_velocity").value_or(b.angular_velocity);
  if (const auto c = r.integer("course")) {
    if (*c < 0 || *c > 1000000) r.fail("course", "must be in [0, 1000000] (got " + std::to_string(*c) + ")");
    b.course = static_cast<int>(*c);
  }
  if (const auto g = r.string("group")) {
    if (g->empty()) r.fail("group", "must not be empty (leave the key out for no group)");
    b.group = *g;
  }
  return b;
}

std::vector<BlockSpec> read_blocks(const Deck& deck, bool generated) {
  const auto tables = section_tables(deck, "block");
  if (tables.empty() && !generated)
    deck.fail("block", &deck.root(), "missing: a deck needs at least one [[block]] (or a generator: [spire], [[wall]], [[tower]])");
  std::vector<BlockSpec> blocks;
  for (std::size_t i = 0; i < tables.size(); ++i) {
    BlockSpec b = read_block(deck, *tables[i], i + 1);
    for (std::size_t j = 0; j < blocks.size(); ++j) {
      if (blocks[j].name == b.name) {
        const toml::node* at = tables[i]->get("name");
        deck.fail(indexed("block", i + 1) + ".name", at ? at : tables[i],
                  "duplicate block name " + in_quotes(b.name) + " (already used by block[" + std::to_string(j + 1) +
                      "] at line " + std::to_string(blocks[j].deck_line) + ")");
      }
    }
    blocks.push_back(std::move(b));
  }
  return blocks;
}

// acceleration (SI) or acceleration_g (in g), not both; nullopt if neither.
std::optional<double> si_or_g(const TableReader& r, std::string_view si_key, std::string_view g_key) {
  const auto si = r.number(si_key);
  const auto g = r.number(g_key);
  if (si && g)
    r.fail(g_key, "give either '" + std::string(si_key) + "' or '" + std::string(g_key) + "', not both");
  if (g) return *g * kGravity;
  return si;
}

// The keys a motion component has: the section's own and each
// [[ground_motion.component]]'s (kind, direction, start time, amplitude or
// rate, period, rise time, record and scale).
void read_motion_keys(const Deck& deck, const TableReader& r, GroundMotionSpec& g) {
  g.kind = r.choice<GroundMotionKind>("kind",
                                      {{"none", GroundMotionKind::none},
                                       {"constant", GroundMotionKind::constant},
                                       {"ramp", GroundMotionKind::ramp},
                                       {"sine_pulse", GroundMotionKind::sine_pulse},
                                       {"record", GroundMotionKind::record}},
                                      g.kind);
  if (const auto d = r.vec3("direction")) {
    if (!(d->norm() > 0)) r.fail("direction", "must not be the zero vector");
    g.direction = d->normalized();
  }
  g.start_time = r.number("start_time", g.start_time, Range::non_negative);
  const auto acceleration = si_or_g(r, "acceleration", "acceleration_g");
  const auto rate = si_or_g(r, "rate", "rate_g");
  g.acceleration = acceleration.value_or(g.acceleration);
  g.rate = rate.value_or(g.rate);
  g.period = r.number("period", g.period, Range::positive);
  g.rise_time = r.number("rise_time", g.rise_time, Range::non_negative);
  g.scale = r.number("scale", g.scale, Range::any);
  const auto record = r.string("record");

  const std::string kind = "kind " + in_quotes(r.string("kind").value_or("none"));
  switch (g.kind) {
    case GroundMotionKind::none:
      break;
    case GroundMotionKind::constant:
      if (!acceleration) r.missing("acceleration", kind + " needs acceleration (m/s²) or acceleration_g (g)");
      break;
    case GroundMotionKind::ramp:
      if (!rate) r.missing("rate", kind + " needs rate (m/s³) or rate_g (g/s)");
      break;
    case GroundMotionKind::sine_pulse:
      if (!acceleration) r.missing("acceleration", kind + " needs acceleration (m/s²) or acceleration_g (g)");
      if (!r.has("period")) r.missing("period", kind + " needs period (s)");
      break;
    case GroundMotionKind::record:
      if (!record) r.missing("record", kind + " needs record = \"path\" (PEER .AT2, ESM .ASC or two-column CSV)");
      break;
  }
  if (record) {
    if (record->empty()) r.fail("record", "must not be empty");
    std::filesystem::path p(*record);
    if (p.is_relative()) p = std::filesystem::path(deck.file()).parent_path() / p;
    g.record_path = p.lexically_normal().string();
    std::error_code ec;
    if (g.kind == GroundMotionKind::record && !std::filesystem::is_regular_file(g.record_path, ec))
      r.fail("record", "file not found: " + g.record_path + " (relative paths are relative to the deck's directory)");
  }
  // The record is read with the deck, so that a run never opens a file (its
  // errors name the record's own file and line).
  // Baseline correction and time scaling (io/record_processing.hpp) apply
  // to the record as read, before `scale`.
  const auto baseline_order = r.integer("baseline_order");
  const double length_scale = r.number("length_scale", 1.0, Range::positive);
  for (const std::string_view key : {"baseline_order", "length_scale"})
    if (r.has(key) && g.kind != GroundMotionKind::record) r.fail(key, "applies to kind = \"record\" only");
  if (baseline_order && (*baseline_order < 0 || *baseline_order > kMaxBaselineOrder))
    r.fail("baseline_order", "must be an integer in [0, " + std::to_string(kMaxBaselineOrder) + "] (got " +
                                 std::to_string(*baseline_order) + ")");
  if (g.kind == GroundMotionKind::record) {
    GroundMotionRecord rec = read_record(g.record_path, 1.0);
    if (r.has("length_scale")) scale_record_time(rec.time, length_scale);
    if (baseline_order) {
      try {
        correct_baseline(rec.time, rec.acceleration, static_cast<int>(*baseline_order));
      } catch (const std::invalid_argument& e) {
        r.fail("baseline_order", e.what());
      }
    }
    g.record_time = std::move(rec.time);
    g.record_acceleration = std::move(rec.acceleration);
  }
}

GroundMotionSpec read_ground_motion(const Deck& deck) {
  const TableReader r(deck, table_or_empty(deck, "ground_motion"), "ground_motion", kGroundMotionKeys);
  GroundMotionSpec g;
  g.deck_line = r.line();
  g.applied_as = r.choice<GroundMotionApplication>(
      "applied_as",
      {{"body_force", GroundMotionApplication::body_force}, {"kinematic", GroundMotionApplication::kinematic}},
      g.applied_as);
  g.tower_frequency = r.number("tower_frequency", g.tower_frequency, Range::non_negative);
  g.tower_damping = r.number("tower_damping", g.tower_damping, Range::non_negative);
  read_motion_keys(deck, r, g);
  // [[ground_motion.component]]: further components, each its own keys.
  if (const toml::node* n = r.table().get("component")) {
    const auto* arr = n->as_array();
    if (!arr) r.fail("component", "must be an array of tables: write [[ground_motion.component]] (got " + describe(*n) + ")");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const std::string path = indexed("ground_motion.component", i + 1);
      const auto* t = arr->get(i)->as_table();
      if (!t) deck.fail(path, arr->get(i), "must be a table: write [[ground_motion.component]]");
      const TableReader c(deck, *t, path, kGroundMotionComponentKeys);
      GroundMotionSpec m;
      m.deck_line = c.line();
      m.applied_as = g.applied_as;
      if (!c.has("kind")) c.missing("kind", "every component needs kind (\"constant\", \"ramp\", \"sine_pulse\" or \"record\")");
      read_motion_keys(deck, c, m);
      g.components.push_back(std::move(m));
    }
  }
  return g;
}

// A selection of blocks: `blocks` (names) and/or `groups` (group names),
// each name known; at least one block in all.
void read_selection(const TableReader& r, const std::vector<BlockSpec>& blocks, std::vector<std::string>& names,
                    std::vector<std::string>& groups) {
  const auto strings = [&](std::string_view key, std::vector<std::string>& out) {
    const toml::node* n = r.table().get(key);
    if (!n) return;
    const auto* arr = n->as_array();
    if (!arr) r.fail(key, "must be an array of names [\"...\", ...] (got " + describe(*n) + ")");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const auto* str = arr->get(i)->as_string();
      if (!str) r.deck().fail(indexed(r.key_path(key), i + 1), arr->get(i), "must be a name (got " + describe(*arr->get(i)) + ")");
      out.push_back(str->get());
    }
  };
  strings("blocks", names);
  strings("groups", groups);
  for (const auto& name : names)
    if (std::none_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) { return b.name == name; }))
      r.fail("blocks", "no block named " + in_quotes(name));
  for (const auto& g : groups)
    if (std::none_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) { return b.group == g; }))
      r.fail("groups", "no block is in group " + in_quotes(g));
  if (names.empty() && groups.empty()) r.missing("blocks", "select the blocks by blocks = [...] and/or groups = [...]");
}

// table = [[t, ...], ...]: rows of 1 + `width` numbers, times increasing.
TimeTable read_time_table(const TableReader& r, std::size_t width, std::string_view form,
                          std::string_view key = "table") {
  TimeTable t;
  const auto rows = r.points(key, 1 + width, form);
  if (!rows) return t;
  if (rows->empty()) r.fail(key, "must have at least one row " + std::string(form));
  for (std::size_t k = 0; k < rows->size(); ++k) {
    const auto& row = (*rows)[k];
    if (k > 0 && !(row[0] > t.time.back()))
      r.fail(key, "times must increase (row " + std::to_string(k + 1) + ": t = " + format_number(row[0]) +
                          " after " + format_number(t.time.back()) + ")");
    t.time.push_back(row[0]);
    t.value.emplace_back(row[1], width > 1 ? row[2] : 0.0, width > 2 ? row[3] : 0.0);
  }
  return t;
}

std::vector<GroupSpec> read_groups(const Deck& deck, std::vector<BlockSpec>& blocks) {
  std::vector<GroupSpec> out;
  const auto tables = section_tables(deck, "group");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const TableReader r(deck, *tables[i], indexed("group", i + 1), kGroupKeys);
    GroupSpec g;
    g.deck_line = r.line();
    const auto name = r.string("name");
    if (!name) r.missing("name", "every [[group]] needs the name of a group of blocks");
    g.name = *name;
    if (std::none_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) { return b.group == g.name; }))
      r.fail("name", "no block is in group " + in_quotes(g.name));
    for (const GroupSpec& o : out)
      if (o.name == g.name)
        r.fail("name", "group " + in_quotes(g.name) + " already has a [[group]] (line " + std::to_string(o.deck_line) + ")");
    g.density = r.number("density", 0.0, Range::positive);
    if (g.density > 0)
      for (BlockSpec& b : blocks)
        if (b.group == g.name) b.density = g.density;
    out.push_back(std::move(g));
  }
  return out;
}

std::vector<LoadSpec> read_loads(const Deck& deck, const std::vector<BlockSpec>& blocks) {
  std::vector<LoadSpec> out;
  const auto tables = section_tables(deck, "load");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const TableReader r(deck, *tables[i], indexed("load", i + 1), kLoadKeys);
    LoadSpec l;
    l.deck_line = r.line();
    read_selection(r, blocks, l.blocks, l.groups);
    const auto force = r.vec3("force");
    const auto moment = r.vec3("moment");
    if (!force && !moment) r.missing("force", "a [[load]] needs force = [x, y, z] (N) and/or moment = [x, y, z] (N·m)");
    l.force = force.value_or(Vec3::Zero());
    l.moment = moment.value_or(Vec3::Zero());
    if (const auto point = r.vec3("point")) {
      l.at_point = true;
      l.point = *point;
    }
    l.factor = read_time_table(r, 1, "[t, factor]");
    out.push_back(std::move(l));
  }
  return out;
}

std::vector<PrescribeSpec> read_prescribed(const Deck& deck, const std::vector<BlockSpec>& blocks) {
  std::vector<PrescribeSpec> out;
  const auto tables = section_tables(deck, "prescribe");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const TableReader r(deck, *tables[i], indexed("prescribe", i + 1), kPrescribeKeys);
    PrescribeSpec p;
    p.deck_line = r.line();
    read_selection(r, blocks, p.blocks, p.groups);
    if (r.has("velocity") && r.has("table"))
      r.fail("table", "give either velocity = [vx, vy, vz] or table = [[t, vx, vy, vz], ...], not both");
    p.velocity = r.vec3("velocity").value_or(Vec3::Zero());
    p.angular_velocity = r.vec3("angular_velocity").value_or(Vec3::Zero());
    p.velocity_table = read_time_table(r, 3, "[t, vx, vy, vz]");
    p.displacement_table = read_time_table(r, 3, "[t, ux, uy, uz]", "displacement_table");
    if (!p.displacement_table.empty()) {
      if (r.has("velocity") || r.has("table"))
        r.fail("displacement_table", "give one of velocity, table (velocities) and displacement_table, not two");
      const Vec3 u0 = table_value(p.displacement_table, 0.0);
      if (!u0.isZero(0.0))
        r.fail("displacement_table", "the displacement at t = 0 must be zero (it is measured from where the block "
                                     "starts; got [" + format_number(u0.x()) + ", " + format_number(u0.y()) + ", " +
                                     format_number(u0.z()) + "])");
    }
    out.push_back(std::move(p));
  }
  return out;
}

OutputSpec read_output(const Deck& deck, const std::vector<BlockSpec>& blocks) {
  const TableReader r(deck, table_or_empty(deck, "output"), "output", kOutputKeys);
  OutputSpec o;
  o.history_interval = r.number("history_interval", o.history_interval, Range::non_negative);
  o.energies = r.boolean("energies").value_or(o.energies);
  o.walking = r.boolean("walking").value_or(o.walking);
  o.snapshot_interval = r.number("snapshot_interval", o.snapshot_interval, Range::non_negative);
  o.snapshot_joints = r.boolean("snapshot_joints").value_or(o.snapshot_joints);
  o.checkpoint_interval = r.number("checkpoint_interval", o.checkpoint_interval, Range::non_negative);
  if (const toml::node* n = r.table().get("histories")) {
    const auto* arr = n->as_array();
    if (!arr) r.fail("histories", "must be an array of \"BLOCK.QUANTITY\" strings (got " + describe(*n) + ")");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const toml::node& e = *arr->get(i);
      const std::string path = indexed(r.key_path("histories"), i + 1);
      const auto* s = e.as_string();
      if (!s) deck.fail(path, &e, "must be a \"BLOCK.QUANTITY\" string (got " + describe(e) + ")");
      const std::string& text = s->get();
      const auto dot = text.rfind('.');
      if (dot == std::string::npos || dot == 0)
        deck.fail(path, &e, "must be \"BLOCK.QUANTITY\" (got " + in_quotes(text) + ")");
      HistorySpec h{text.substr(0, dot), text.substr(dot + 1)};
      if (h.block.rfind(kGroupPrefix, 0) == 0) {  // "group:NAME.QUANTITY"
        const std::string group = h.block.substr(kGroupPrefix.size());
        if (!contains(kGroupHistoryQuantities, h.quantity))
          deck.fail(path, &e, "a group's quantity must be one of " + join_quoted(kGroupHistoryQuantities) + " (got " +
                                  in_quotes(h.quantity) + ")");
        if (std::none_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) { return b.group == group; }))
          deck.fail(path, &e, "no block is in group " + in_quotes(group));
        o.histories.push_back(std::move(h));
        continue;
      }
      if (!contains(kHistoryQuantities, h.quantity))
        deck.fail(path, &e, "quantity must be one of " + join_quoted(kHistoryQuantities) + " (got " +
                                in_quotes(h.quantity) + ")");
      if (std::none_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) { return b.name == h.block; }))
        deck.fail(path, &e, "no block named " + in_quotes(h.block));
      o.histories.push_back(std::move(h));
    }
  }
  return o;
}

AssessmentSpec read_assessment(const Deck& deck, const std::vector<BlockSpec>& blocks) {
  const TableReader r(deck, table_or_empty(deck, "assessment"), "assessment", kAssessmentKeys);
  AssessmentSpec a;
  a.damage_displacement = r.number("damage_displacement", a.damage_displacement, Range::positive);
  a.collapse_displacement = r.number("collapse_displacement", a.collapse_displacement, Range::positive);
  if (a.collapse_displacement <= a.damage_displacement)
    r.fail("collapse_displacement", "must be larger than damage_displacement (" +
                                        std::to_string(a.damage_displacement) + " m)");
  a.stop_on_collapse = r.boolean("stop_on_collapse").value_or(a.stop_on_collapse);
  a.collapse_mass_fraction = r.number("collapse_mass_fraction", a.collapse_mass_fraction, Range::non_negative);
  if (a.collapse_mass_fraction > 1.0)
    r.fail("collapse_mass_fraction", "must be in [0, 1] (got " + format_number(a.collapse_mass_fraction) + ")");
  a.monitor_block = r.string("monitor_block").value_or("");
  if (!a.monitor_block.empty() &&
      std::none_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) { return b.name == a.monitor_block; }))
    r.fail("monitor_block", "no block named " + in_quotes(a.monitor_block));
  a.monitor_group = r.string("monitor_group").value_or("");
  if (!a.monitor_group.empty()) {
    if (!a.monitor_block.empty()) r.fail("monitor_group", "give monitor_block or monitor_group, not both");
    if (std::none_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) {
          return b.group == a.monitor_group && b.motion == BlockMotion::free;
        }))
      r.fail("monitor_group", "no free block is in group " + in_quotes(a.monitor_group));
  }
  return a;
}

std::vector<CheckSpec> read_checks(const Deck& deck, const std::vector<BlockSpec>& blocks) {
  std::vector<CheckSpec> checks;
  const auto tables = section_tables(deck, "check");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const TableReader r(deck, *tables[i], indexed("check", i + 1), kCheckKeys);
    CheckSpec c;
    c.deck_line = r.line();
    const auto kind = r.string("kind");
    if (!kind) r.missing("kind", "every [[check]] needs kind, one of " + join_quoted(kCheckKinds));
    if (!contains(kCheckKinds, *kind))
      r.fail("kind", "must be one of " + join_quoted(kCheckKinds) + " (got " + in_quotes(*kind) + ")");
    c.kind = *kind;
    c.block = r.string("block").value_or("");
    if (r.has("block") &&
        std::none_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) { return b.name == c.block; }))
      r.fail("block", "no block named " + in_quotes(c.block));
    c.expected = r.number("expected").value_or(c.expected);
    c.tolerance = r.number("tolerance", c.tolerance, Range::positive);
    checks.push_back(std::move(c));
  }
  return checks;
}

EquilibriumSpec read_equilibrium(const Deck& deck, const SimulationSpec& sim) {
  EquilibriumSpec e;
  if (!deck.root().get("equilibrium")) return e;
  const TableReader r(deck, table_or_empty(deck, "equilibrium"), "equilibrium", kEquilibriumKeys);
  e.deck_line = r.line();
  e.enabled = r.boolean("enabled").value_or(true);
  e.ratio = r.number("ratio", e.ratio, Range::positive);
  if (const auto n = r.integer("max_steps")) {
    if (*n < 1 || *n > 1000000000) r.fail("max_steps", "must be in [1, 1e9] (got " + std::to_string(*n) + ")");
    e.max_steps = static_cast<long>(*n);
  }
  e.local_damping = r.number("local_damping", e.local_damping, Range::positive);
  if (e.local_damping >= 1.0)
    r.fail("local_damping", "must be in (0, 1) (got " + format_number(e.local_damping) + ")");
  e.density_scaling = r.boolean("density_scaling").value_or(e.density_scaling);
  if (e.enabled && sim.gravity_rise_time > 0)
    r.fail("enabled", "the static stage and simulation.gravity_rise_time both bring gravity on gently: give one "
                      "(the dynamic stage after the static one starts under the full weight)");
  return e;
}

// [ensemble]: the sizes of the perturbations and which replica this run is
// (studies/ensemble.hpp). Replica k > 0 is drawn and applied here, so that
// every command and the Python module run the same replica of a deck.
EnsembleSpec read_ensemble(const Deck& deck, const SceneSpec& scene) {
  EnsembleSpec e;
  if (!deck.root().get("ensemble")) return e;
  const TableReader r(deck, table_or_empty(deck, "ensemble"), "ensemble", kEnsembleKeys);
  e.given = true;
  e.deck_line = r.line();
  if (const auto k = r.integer("replica")) {
    if (*k < 0 || *k > 1000000000) r.fail("replica", "must be in [0, 1e9] (got " + std::to_string(*k) + ")");
    e.replica = static_cast<long>(*k);
  }
  if (const auto k = r.integer("seed")) {
    if (*k < 0) r.fail("seed", "must be >= 0 (got " + std::to_string(*k) + ")");
    e.seed = static_cast<std::uint64_t>(*k);
  }
  const auto within = [&](std::string_view key, double value, double low, double high, const char* unit) {
    const double v = r.number(key, value, Range::non_negative);
    if (v < low || v > high)
      r.fail(key, "must be in [" + format_number(low) + ", " + format_number(high) + "]" + unit + " (got " +
                      format_number(v) + ")");
    return v;
  };
  e.friction_angle = within("friction_angle", e.friction_angle, 0.0, 5.0, " degrees");
  e.stiffness = within("stiffness", e.stiffness, 0.0, 0.5, "");
  e.velocity = r.number("velocity", e.velocity, Range::non_negative);
  const double settle = scene.simulation.settle_velocity;
  if (settle > 0 && e.velocity >= settle)
    r.fail("velocity", "must be below simulation.settle_velocity (" + format_number(settle) + " m/s) (got " +
                           format_number(e.velocity) + ")");
  e.time_shift = within("time_shift", e.time_shift, 0.0, 1.0, "");
  e.sample_step = r.number("sample_step", e.sample_step, Range::positive);
  return e;
}

// "FILE:LINE: key 'KEY': what", the form of the errors (built by appends:
// GCC 12 warns falsely on long chains of string +).
std::string deck_warning(const Deck& deck, const std::string& key, const toml::node* at, const std::string& what) {
  std::ostringstream w;
  w << deck.file();
  const long line = at ? static_cast<long>(at->source().begin.line) : 0;
  if (line > 0 && !(at->source().path && *at->source().path == kOverrideSource)) w << ":" << line;
  w << ": key '" << key << "': " << what;
  return w.str();
}

// A deck that is valid but probably not what was meant.
std::vector<std::string> deck_warnings(const Deck& deck, const SceneSpec& s) {
  std::vector<std::string> warnings;
  const bool free_block = std::any_of(s.blocks.begin(), s.blocks.end(),
                                      [](const BlockSpec& b) { return b.motion == BlockMotion::free; });
  // Sudden gravity on undamped frictional joints: every joint is struck by
  // twice its static load and unloads to zero every period; blocks on a
  // slope ratchet (docs/equilibrium.md).
  if (free_block && s.simulation.gravity.norm() > 0 && s.simulation.gravity_rise_time == 0 &&
      !s.equilibrium.enabled && s.joint.damping == 0 && s.joint.friction_angle > 0) {
    const toml::node* joint = deck.root().get("joint");
    const toml::node* at = joint && joint->as_table() ? joint->as_table()->get("damping") : nullptr;
    if (joint && joint->as_array()) joint = nullptr;  // [[joint]]: the warning names the key alone
    warnings.push_back(deck_warning(
        deck, "joint.damping", at ? at : joint,
        "gravity is applied in full at t = 0 to frictional joints with no damping: the joints unload every "
        "period and blocks can ratchet down a slope; bring the scene to equilibrium first ([equilibrium]) or "
        "let gravity rise (simulation.gravity_rise_time)"));
  }
  return warnings;
}

void check_sections(const Deck& deck) {
  std::vector<std::string_view> names;
  for (const auto& s : kSections) names.push_back(s.name);
  for (const auto& g : generator_sections()) names.push_back(g.name);
  names.push_back("cut");
  for (auto&& [k, v] : deck.root()) {
    if (!contains(names, k.str()))
      deck.fail(std::string(k.str()), &v, "unknown section (a deck has: " + join(names) + ")");
  }
}

// ------------------------------------------------------------- 5. overrides

[[noreturn]] void override_error(const std::string& file, const std::string& what) {
  throw DeckError(file + ": --set " + what);
}

// One step of an override key path: a table key, or a 1-based array index.
struct PathStep {
  std::string name;
  std::size_t index = 0;  // > 0: array element
};

// "block[1].density" or "block.1.density" -> steps; throws on bad syntax.
std::vector<PathStep> parse_key_path(const std::string& file, const std::string& key) {
  std::vector<PathStep> steps;
  const auto bad = [&](const std::string& why) { override_error(file, "'" + key + "': " + why); };
  const auto is_digits = [](std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  const auto push_index = [&](std::string_view digits) {
    if (!is_digits(digits)) bad("array index must be a positive integer (got '" + std::string(digits) + "')");
    std::size_t idx = 0;
    std::from_chars(digits.data(), digits.data() + digits.size(), idx);
    if (idx == 0) bad("array indices are 1-based");
    steps.push_back({"", idx});
  };
  std::size_t pos = 0;
  while (true) {
    const std::size_t dot = key.find('.', pos);
    std::string_view seg = std::string_view(key).substr(pos, dot == std::string::npos ? std::string::npos : dot - pos);
    if (seg.empty()) bad("empty key in path");
    if (is_digits(seg)) {
      if (steps.empty()) bad("a path cannot start with an index");
      push_index(seg);
    } else {
      const std::size_t bracket = seg.find('[');
      const std::string_view name = seg.substr(0, bracket);
      if (name.empty()) bad("empty key in path");
      const bool valid = std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
      });
      if (!valid) bad("bad key name '" + std::string(name) + "'");
      steps.push_back({std::string(name), 0});
      std::string_view rest = bracket == std::string_view::npos ? std::string_view{} : seg.substr(bracket);
      while (!rest.empty()) {
        const std::size_t close = rest.find(']');
        if (rest.front() != '[' || close == std::string_view::npos) bad("unbalanced [ ]");
        push_index(rest.substr(1, close - 1));
        rest.remove_prefix(close + 1);
      }
    }
    if (dot == std::string::npos) break;
    pos = dot + 1;
  }
  return steps;
}

// Applies "key.path=value" to `root`; returns the canonical key path
// ("block[1].density") for locating later errors.
std::string apply_override(toml::table& root, const std::string& file, const std::string& spec) {
  const std::size_t eq = spec.find('=');
  if (eq == std::string::npos) override_error(file, "'" + spec + "': expected key.path=value");
  const auto trim = [](std::string s) {
    const auto first = s.find_first_not_of(" \t");
    const auto last = s.find_last_not_of(" \t");
    return first == std::string::npos ? std::string{} : s.substr(first, last - first + 1);
  };
  const std::string key = trim(spec.substr(0, eq));
  const std::string text = trim(spec.substr(eq + 1));
  if (key.empty()) override_error(file, "'" + spec + "': expected key.path=value");
  const std::vector<PathStep> steps = parse_key_path(file, key);

  // The value: TOML if it parses as one value, else the text as a string.
  toml::table holder;
  try {
    holder = toml::parse(std::string_view("v = " + text + "\n"), kOverrideSource);
    if (holder.size() != 1 || !holder.contains("v")) throw std::runtime_error("not one value");
  } catch (const std::exception&) {
    holder = toml::table{{"v", text}};
  }
  toml::node& value = *holder.get("v");

  toml::node* cur = &root;
  std::string canon;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const PathStep& step = steps[i];
    const bool last = i + 1 == steps.size();
    if (step.index == 0) {
      auto* table = cur->as_table();
      if (!table) {
        const auto* array = cur->as_array();
        if (array && !array->empty() && array->is_array_of_tables()) {
          std::string msg = "key '";
          msg.append(canon).append("' is an array of tables (a [[").append(canon).append("]] list of ");
          msg.append(std::to_string(array->size())).append("): choose one, e.g. '").append(canon).append("[1].");
          msg.append(step.name).append("' for the first");
          if (canon == "joint") msg.append(" (the default joint; the others apply between groups)");
          override_error(file, msg);
        }
        override_error(file, "key '" + canon + "': is not a table, cannot set '" + step.name + "' in it");
      }
      canon += (canon.empty() ? "" : ".") + step.name;
      if (last) {
        value.visit([&](auto&& v) { table->insert_or_assign(step.name, std::move(v)); });
      } else {
        if (!table->contains(step.name)) table->insert(step.name, toml::table{});
        cur = table->get(step.name);
      }
    } else {
      auto* array = cur->as_array();
      if (!array) override_error(file, "key '" + canon + "': is not an array, cannot index it");
      if (step.index > array->size())
        override_error(file, "key '" + indexed(canon, step.index) + "': no such element ('" + canon + "' has " +
                                 std::to_string(array->size()) + ")");
      canon = indexed(canon, step.index);
      if (last) {
        value.visit([&](auto&& v) { array->replace(array->cbegin() + static_cast<long>(step.index - 1), std::move(v)); });
      } else {
        cur = array->get(step.index - 1);
      }
    }
  }
  return canon;
}

}  // namespace

// ----------------------------------------------------------- 6. entry points

SceneSpec parse_deck(const std::string& text, const std::string& path_for_messages,
                     const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(std::string_view(text), std::string_view(path_for_messages));
  } catch (const toml::parse_error& e) {
    throw DeckError(path_for_messages + ":" + std::to_string(e.source().begin.line) +
                    ": TOML syntax error: " + std::string(e.description()));
  }
  std::vector<std::string> overridden;
  for (const auto& o : overrides) overridden.push_back(apply_override(root, path_for_messages, o));

  const Deck deck(path_for_messages, root, std::move(overridden));
  check_sections(deck);
  SceneSpec scene;
  scene.deck_path = path_for_messages;
  scene.deck_text = text;
  scene.simulation = read_simulation(deck);
  // Generators ([spire], ...) first: they may set the joints' defaults
  // (from their materials) and they stand in for [[block]] tables.
  const Generated generated = read_generators(deck, scene);
  scene.generators = std::make_shared<const GeneratorSpecs>(generated.specs);
  scene.blocks = read_blocks(deck, !generated.parts.empty());
  append_generated_blocks(deck, generated, scene.blocks);
  // [[cut]]s next: they cut whatever the tables and generators made; joints,
  // groups, loads and prescribed motions then see the pieces.
  apply_cuts(deck, scene.blocks);
  JointSection joints = read_joints(deck, generated.joint.value_or(JointDefaults{}), scene.blocks);
  scene.joint = joints.joint;
  scene.joint_pairs = std::move(joints.pairs);
  if (scene.simulation.joint_model == JointModel::overlap)
    refuse_bonds(deck, scene, "simulation.joint_model = \"overlap\"", "\"subcontacts\"");
  if (scene.simulation.damping_scheme == DampingScheme::split) refuse_total_friction_for_split(deck, scene);
  scene.groups = read_groups(deck, scene.blocks);
  scene.loads = read_loads(deck, scene.blocks);
  scene.prescribed = read_prescribed(deck, scene.blocks);
  scene.ground_motion = read_ground_motion(deck);
  scene.output = read_output(deck, scene.blocks);
  scene.assessment = read_assessment(deck, scene.blocks);
  scene.checks = read_checks(deck, scene.blocks);
  scene.equilibrium = read_equilibrium(deck, scene.simulation);
  scene.ensemble = read_ensemble(deck, scene);
  if (scene.ensemble.replica > 0) {
    apply_perturbation(scene, draw_perturbation(scene, scene.ensemble.replica, scene.ensemble.seed));
    // The checks hold the deck as written against its theory (a pulse from
    // t = 0, the friction as given): a perturbed replica is not checked.
    scene.checks.clear();
  }
  scene.warnings = deck_warnings(deck, scene);
  return scene;
}

SceneSpec read_deck(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DeckError(path + ": cannot open deck file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw DeckError(path + ": cannot read deck file");
  return parse_deck(text.str(), path, overrides);
}

int deck_line_of(const std::string& text, const std::string& key) {
  const std::string last = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    if (line.compare(first, last.size(), last) == 0) {
      const auto rest = line.find_first_not_of(" \t", first + last.size());
      if (rest != std::string::npos && line[rest] == '=') return n;
    }
  }
  return 0;
}

std::string locate_scene_error(const SceneError& e, const SceneSpec& spec) {
  const int line = e.deck_line > 0 ? e.deck_line : deck_line_of(spec.deck_text, e.key);
  return spec.deck_path + (line > 0 ? ":" + std::to_string(line) + ": " : std::string(": --set ")) + e.what();
}

std::vector<std::string> deck_keys() {
  std::vector<std::string> keys;
  for (const auto& section : kSections) {
    for (const auto& key : section.keys) keys.push_back(std::string(section.name) + "." + std::string(key));
  }
  for (const auto& section : generator_sections()) {
    for (const auto& key : section.keys) keys.push_back(std::string(section.name) + "." + std::string(key));
  }
  for (const auto& key : cut_keys()) keys.push_back("cut." + std::string(key));
  for (const auto& key : kGroundMotionComponentKeys) keys.push_back("ground_motion.component." + std::string(key));
  return keys;
}

}  // namespace polydem
