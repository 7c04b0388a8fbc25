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
#include "io/deck_reader.hpp"
#include "io/generators.hpp"
#include "io/ground_motion_record.hpp"
#include "core/materials.hpp"
#include "core/units.hpp"

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
#include <string_view>
#include <utility>

namespace polydem {
namespace {

using namespace deck_reader;

// ---------------------------------------------------------------- 1. schema


constexpr std::string_view kSimulationKeys[] = {
    "end_time",          "time_step",       "safety_factor", "gravity",    "contact_margin", "threads",
    "overlap_tolerance", "settle_velocity", "settle_time",   "gravity_rise_time"};
constexpr std::string_view kJointKeys[] = {"normal_stiffness", "shear_stiffness",  "friction_angle",
                                           "cohesion",         "tensile_strength", "damping"};
constexpr std::string_view kBlockKeys[] = {"name",     "shape",    "size",   "center",   "polygon",
                                           "z",        "vertices", "rotation", "offset", "density",
                                           "motion",   "velocity", "angular_velocity", "course", "group"};
constexpr std::string_view kGroundMotionKeys[] = {"kind",           "applied_as", "direction", "start_time",
                                                  "acceleration",   "acceleration_g", "rate",  "rate_g",
                                                  "period",         "record",         "scale",
                                                  "rise_time",      "tower_frequency", "tower_damping"};
constexpr std::string_view kOutputKeys[] = {"history_interval",  "histories",       "energies",
                                            "walking",           "snapshot_interval", "snapshot_joints",
                                            "checkpoint_interval"};
constexpr std::string_view kAssessmentKeys[] = {"damage_displacement", "collapse_displacement", "stop_on_collapse",
                                                "monitor_block", "collapse_mass_fraction"};
constexpr std::string_view kCheckKeys[] = {"kind", "block", "expected", "tolerance"};
constexpr std::string_view kEquilibriumKeys[] = {"enabled", "ratio", "max_steps", "local_damping"};

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
};

// Keys that define a block's shape, by shape.
constexpr std::string_view kShapeKeys[] = {"size", "center", "polygon", "z", "vertices"};

constexpr std::string_view kHistoryQuantities[] = {"position", "velocity", "rotation", "angular_velocity",
                                                   "contact_force"};
constexpr std::string_view kCheckKinds[] = {"resting_weight",      "no_drift",
                                            "slide_acceleration",  "stick",
                                            "rocking_onset",       "housner_restitution",
                                            "rocking_first_impact", "energy_conservation",
                                            "energy_no_growth",    "pulse_peak_rotation"};

// ------------------------------------------------------ 4. section readers


SimulationSpec read_simulation(const Deck& deck) {
  const TableReader r(deck, table_or_empty(deck, "simulation"), "simulation", kSimulationKeys);
  SimulationSpec s;
  s.end_time = r.number("end_time", s.end_time, Range::positive);
  s.time_step = r.number("time_step", s.time_step, Range::non_negative);
  s.safety_factor = r.number("safety_factor", s.safety_factor, Range::positive);
  if (s.safety_factor > 1.0)
    r.fail("safety_factor", "must be in (0, 1] (got " + format_number(s.safety_factor) + ")");
  s.gravity = r.vec3("gravity").value_or(s.gravity);
  s.contact_margin = r.number("contact_margin", s.contact_margin, Range::non_negative);
  if (const auto t = r.integer("threads")) {
    if (*t < 0 || *t > 4096) r.fail("threads", "must be in [0, 4096], 0 = OpenMP default (got " + std::to_string(*t) + ")");
    s.threads = static_cast<int>(*t);
  }
  s.overlap_tolerance = r.number("overlap_tolerance", s.overlap_tolerance, Range::non_negative);
  s.settle_velocity = r.number("settle_velocity", s.settle_velocity, Range::non_negative);
  s.settle_time = r.number("settle_time", s.settle_time, Range::non_negative);
  s.gravity_rise_time = r.number("gravity_rise_time", s.gravity_rise_time, Range::non_negative);
  return s;
}


JointSpec read_joint(const Deck& deck, const JointDefaults& defaults) {
  const TableReader r(deck, table_or_empty(deck, "joint"), "joint", kJointKeys);
  JointSpec j;
  j.normal_stiffness = r.number("normal_stiffness", defaults.normal_stiffness, Range::positive);
  j.shear_stiffness = r.number("shear_stiffness", joint_shear_stiffness(j.normal_stiffness, defaults.shear_ratio), Range::positive);
  j.friction_angle = r.number("friction_angle", j.friction_angle, Range::non_negative);
  if (j.friction_angle >= 90.0)
    r.fail("friction_angle", "must be in [0, 90) degrees (got " + format_number(j.friction_angle) + ")");
  j.cohesion = r.number("cohesion", j.cohesion, Range::non_negative);
  j.tensile_strength = r.number("tensile_strength", j.tensile_strength, Range::non_negative);
  j.damping = r.number("damping", j.damping, Range::non_negative);
  return j;
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

GroundMotionSpec read_ground_motion(const Deck& deck) {
  const TableReader r(deck, table_or_empty(deck, "ground_motion"), "ground_motion", kGroundMotionKeys);
  GroundMotionSpec g;
  g.deck_line = r.line();
  g.kind = r.choice<GroundMotionKind>("kind",
                                      {{"none", GroundMotionKind::none},
                                       {"constant", GroundMotionKind::constant},
                                       {"ramp", GroundMotionKind::ramp},
                                       {"sine_pulse", GroundMotionKind::sine_pulse},
                                       {"record", GroundMotionKind::record}},
                                      g.kind);
  g.applied_as = r.choice<GroundMotionApplication>(
      "applied_as",
      {{"body_force", GroundMotionApplication::body_force}, {"kinematic", GroundMotionApplication::kinematic}},
      g.applied_as);
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
  g.tower_frequency = r.number("tower_frequency", g.tower_frequency, Range::non_negative);
  g.tower_damping = r.number("tower_damping", g.tower_damping, Range::non_negative);
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
      if (!record) r.missing("record", kind + " needs record = \"path\" (PEER .AT2 or two-column CSV)");
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
  if (g.kind == GroundMotionKind::record) {
    GroundMotionRecord rec = read_record(g.record_path, 1.0);
    g.record_time = std::move(rec.time);
    g.record_acceleration = std::move(rec.acceleration);
  }
  return g;
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
  if (e.enabled && sim.gravity_rise_time > 0)
    r.fail("enabled", "the static stage and simulation.gravity_rise_time both bring gravity on gently: give one "
                      "(the dynamic stage after the static one starts under the full weight)");
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
      if (!table) override_error(file, "key '" + canon + "': is not a table, cannot set '" + step.name + "' in it");
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
  scene.joint = read_joint(deck, generated.joint.value_or(JointDefaults{}));
  scene.blocks = read_blocks(deck, !generated.parts.empty());
  append_generated_blocks(deck, generated, scene.blocks);
  scene.ground_motion = read_ground_motion(deck);
  scene.output = read_output(deck, scene.blocks);
  scene.assessment = read_assessment(deck, scene.blocks);
  scene.checks = read_checks(deck, scene.blocks);
  scene.equilibrium = read_equilibrium(deck, scene.simulation);
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
  return keys;
}

}  // namespace polydem
