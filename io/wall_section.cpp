// [[wall]]: straight walls of brick or stone units (structures/wall.hpp), one
// per table, each with its openings as [[wall.opening]] tables. Block names
// start with the wall's name, so several walls live in one deck; groups
// come from what each block is (group_by) with an optional prefix.
#include "io/generators.hpp"

#include "structures/wall.hpp"

#include <cmath>
#include <numbers>

namespace polydem {

namespace {

using namespace deck_reader;

// The [[wall]] keys, then its [[wall.opening]] keys as "opening.KEY" (so
// that deck_keys() lists them as wall.opening.KEY, as docs/deck.md does).
constexpr std::string_view kWallKeys[] = {
    "name",    "origin",        "direction",      "start",           "end",          "length",
    "height",  "courses",       "unit_size",      "bond",            "leaves",       "through_every",
    "density", "group_by",      "group",  "gable_height", "corner_with", "corner_at", "turn",          "opening",         "opening.position", "opening.sill",
    "opening.width", "opening.height", "opening.head", "opening.bearing", "opening.voussoirs", "opening.ring"};

std::vector<std::string_view> table_keys() {
  std::vector<std::string_view> out;
  for (std::string_view k : kWallKeys)
    if (k.find('.') == std::string_view::npos) out.push_back(k);
  return out;
}

std::vector<std::string_view> opening_keys() {
  std::vector<std::string_view> out;
  for (std::string_view k : kWallKeys)
    if (k.rfind("opening.", 0) == 0) out.push_back(k.substr(8));
  return out;
}

enum class GroupBy { course, leaf, kind, wall };

struct WallSection {
  WallSpec spec;
  WallModel model;
  double density = 2600.0;
  GroupBy group_by = GroupBy::course;
  std::string group_prefix;
  int line = 0;
  const toml::table* table = nullptr;
  std::string path;                  // "wall[2]"
  std::vector<TableReader> readers;  // [0]: the wall's, then its openings'
  // A corner with an earlier wall: its name, at its end or start, turning left or right.
  std::string corner_with;
  bool corner_at_end = true;
  bool turn_left = true;
};

std::string two_digits(int v) {
  std::string s = std::to_string(v);
  if (s.size() < 2) s.insert(s.begin(), '0');
  return s;
}

WallSection read_wall(const Deck& deck, const toml::table& t, std::size_t index) {
  const std::string path = indexed("wall", index + 1);
  static const std::vector<std::string_view> keys = table_keys();
  WallSection out;
  out.path = path;
  // The openings' readers go after the wall's: room for all of them first,
  // so that `r` below stays valid.
  const toml::node* openings_node = t.get("opening");
  const auto* openings_array = openings_node ? openings_node->as_array() : nullptr;
  out.readers.reserve(1 + (openings_array ? openings_array->size() : 0));
  out.readers.emplace_back(deck, t, path, keys);
  const TableReader& r = out.readers.front();
  out.line = r.line();
  out.table = &t;
  WallSpec& s = out.spec;
  s.name = r.string("name").value_or("wall" + std::to_string(index + 1));
  if (s.name.empty() || s.name.find_first_of(" \t\n\"") != std::string::npos)
    r.fail("name", "must be a non-empty name without spaces or quotes (it starts every block's name)");

  // Where the wall stands: origin + direction + length, start + end, or at
  // a corner of an earlier wall (placed by read_wall_sections).
  if (r.has("corner_with")) {
    for (const char* k : {"origin", "direction", "start", "end"})
      if (r.has(k)) r.fail(k, "a wall at a corner (corner_with) is placed by the wall it meets: give only its length");
    out.corner_with = *r.string("corner_with");
    out.corner_at_end = r.choice<bool>("corner_at", {{"end", true}, {"start", false}}, true);
    out.turn_left = r.choice<bool>("turn", {{"left", true}, {"right", false}}, true);
    s.length = r.number("length", s.length, Range::positive);
  } else if (r.has("corner_at") || r.has("turn")) {
    r.fail(r.has("corner_at") ? "corner_at" : "turn", "applies with corner_with only");
  } else if (r.has("start") || r.has("end")) {
    for (const char* k : {"origin", "direction", "length"})
      if (r.has(k)) r.fail(k, "give either start and end, or origin, direction and length");
    if (!r.has("start")) r.missing("start", "end is given: the wall runs from start to end");
    if (!r.has("end")) r.missing("end", "start is given: the wall runs from start to end");
    const Vec3 a = *r.vec3("start"), b = *r.vec3("end");
    if (std::abs(a.z() - b.z()) > 1e-12 * (1 + std::abs(a.z())))
      r.fail("end", "must be at the height of start (z = " + format_number(a.z()) + "): walls stand on a level bed");
    const Vec3 d = b - a;
    if (!(d.norm() > 0)) r.fail("end", "must differ from start");
    s.origin = a;
    s.length = d.norm();
    s.direction = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
  } else {
    s.origin = r.vec3("origin").value_or(s.origin);
    s.direction = r.number("direction", s.direction, Range::any);
    s.length = r.number("length", s.length, Range::positive);
  }
  s.height = r.number("height", s.height, Range::positive);
  if (const auto n = r.integer("courses")) {
    if (*n < 1 || *n > 2000) r.fail("courses", "must be in [1, 2000] (got " + std::to_string(*n) + ")");
    if (r.has("height")) r.fail("courses", "give height or courses (height = courses × unit height), not both");
    s.courses = static_cast<int>(*n);
  }
  if (const auto u = r.numbers("unit_size", 3, "[length, height, width]")) {
    for (std::size_t i = 0; i < 3; ++i)
      if (!((*u)[i] > 0)) r.fail("unit_size", "every size must be > 0 (got " + format_number((*u)[i]) + ")");
    s.unit_length = (*u)[0];
    s.unit_height = (*u)[1];
    s.unit_width = (*u)[2];
  }
  if (s.courses > 0) s.height = s.courses * s.unit_height;
  s.bond = r.choice<WallBond>("bond",
                              {{"stretcher", WallBond::stretcher},
                               {"running", WallBond::stretcher},
                               {"header", WallBond::header},
                               {"english", WallBond::english},
                               {"flemish", WallBond::flemish}},
                              s.bond);
  if (const auto n = r.integer("leaves")) {
    if (*n < 1 || *n > 16) r.fail("leaves", "must be in [1, 16] (got " + std::to_string(*n) + ")");
    s.leaves = static_cast<int>(*n);
  }
  if (const auto n = r.integer("through_every")) {
    if (*n < 0 || *n > 1000) r.fail("through_every", "must be in [0, 1000] (got " + std::to_string(*n) + ")");
    s.through_every = static_cast<int>(*n);
  }
  s.gable_height = r.number("gable_height", s.gable_height, Range::non_negative);
  out.density = r.number("density", out.density, Range::positive);
  out.group_by = r.choice<GroupBy>(
      "group_by", {{"course", GroupBy::course}, {"leaf", GroupBy::leaf}, {"kind", GroupBy::kind}, {"wall", GroupBy::wall}},
      out.group_by);
  out.group_prefix = r.string("group").value_or("");

  // [[wall.opening]] tables.
  std::vector<const toml::table*> opening_tables;
  if (const toml::node* n = t.get("opening")) {
    const auto* arr = n->as_array();
    if (!arr) r.fail("opening", "must be an array of tables: write [[wall.opening]] under its [[wall]] (got " + describe(*n) + ")");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const auto* ot = arr->get(i)->as_table();
      if (!ot)
        deck.fail(indexed(r.key_path("opening"), i + 1), arr->get(i),
                  "must be a table: write [[wall.opening]] (got " + describe(*arr->get(i)) + ")");
      opening_tables.push_back(ot);
    }
  }
  static const std::vector<std::string_view> okeys = opening_keys();
  const std::string opening_path = r.key_path("opening");
  for (std::size_t i = 0; i < opening_tables.size(); ++i) {
    out.readers.emplace_back(deck, *opening_tables[i], indexed(opening_path, i + 1), okeys);
    const TableReader& o = out.readers.back();
    WallOpening op;
    for (const char* k : {"position", "width", "height"})
      if (!o.has(k)) o.missing(k, "an opening needs position, width and height");
    op.position = o.number("position", 0.0, Range::any);
    op.sill = o.number("sill", 0.0, Range::non_negative);
    op.width = o.number("width", 0.0, Range::positive);
    op.height = o.number("height", 0.0, Range::positive);
    op.head = o.choice<OpeningHead>("head", {{"lintel", OpeningHead::lintel}, {"arch", OpeningHead::arch}}, op.head);
    if (op.head == OpeningHead::lintel) {
      for (const char* k : {"voussoirs", "ring"})
        if (o.has(k)) o.fail(k, "applies to head = \"arch\" only");
      op.bearing = o.number("bearing", 0.0, Range::positive);
    } else {
      if (o.has("bearing")) o.fail("bearing", "applies to head = \"lintel\" only");
      if (const auto n = o.integer("voussoirs")) {
        if (*n < 3 || *n > 64) o.fail("voussoirs", "must be in [3, 64] (got " + std::to_string(*n) + ")");
        op.voussoirs = static_cast<int>(*n);
      }
      op.ring = o.number("ring", 0.0, Range::positive);
    }
    s.openings.push_back(op);
  }

  return out;
}

void build_section(const Deck& deck, WallSection& w) {
  const TableReader& r = w.readers.front();
  try {
    w.model = build_wall(w.spec);
  } catch (const WallSpecError& e) {
    std::string key = e.field;
    if (key == "unit_length" || key == "unit_height" || key == "unit_width") key = "unit_size";
    if ((key == "corners" || key == "course_shift") && r.has("corner_with")) key = "corner_with";
    if (e.opening >= 0) w.readers[static_cast<std::size_t>(e.opening) + 1].fail(key, e.detail);
    if (key == "length" && !r.has("length") && r.has("end")) key = "end";
    if (key == "height" && !r.has("height") && r.has("courses")) key = "courses";
    r.fail(key, e.detail);
  } catch (const GeometryError& e) {
    deck.fail(w.path, w.table, std::string("cannot build the wall: ") + e.what());
  }
}

// Wall b at a corner of the earlier wall a: b's frame from a's, and the
// corner's cuts on both (structures/wall.hpp, WallCorner).
void place_at_corner(WallSection& b, WallSection& a) {
  const TableReader& r = b.readers.front();
  WallSpec& A = a.spec;
  WallSpec& B = b.spec;
  const bool a_running = A.bond == WallBond::stretcher, b_running = B.bond == WallBond::stretcher;
  if (a_running != b_running)
    r.fail("corner_with", "bonds that cannot close a corner: a stretcher bond wall turns a corner with another "
                          "stretcher bond wall, and English, Flemish and header bond walls with one another (" +
                              in_quotes(A.name) + " and this one)");
  if (!a_running) {
    // Quoin headers and queen closers: the units must be the same, two
    // headers side by side a unit length (both walls a unit length thick).
    const auto same = [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y)); };
    if (!same(A.unit_length, B.unit_length) || !same(A.unit_width, B.unit_width))
      r.fail("unit_size", "bonds that cannot close a corner: the quoin headers and closers interlock only between "
                          "units of the same length and width (" + format_number(B.unit_length) + " x " +
                              format_number(B.unit_width) + " m here, " + format_number(A.unit_length) + " x " +
                              format_number(A.unit_width) + " m in " + in_quotes(A.name) + ")");
    if (!same(2 * B.unit_width, B.unit_length))
      r.fail("unit_size", "bonds that cannot close a corner: a quoin header and queen closer fit only when two "
                          "headers side by side make a unit length (unit width = unit length / 2)");
  }
  const int na = A.courses > 0 ? A.courses : std::max(1, static_cast<int>(std::lround(A.height / A.unit_height)));
  const int nb = B.courses > 0 ? B.courses : std::max(1, static_cast<int>(std::lround(B.height / B.unit_height)));
  const double cha = A.height / na, chb = B.height / nb;
  if (std::abs(cha - chb) > 1e-9 * cha)
    r.fail("corner_with", "the courses cannot interlock: course height " + format_number(chb) + " m here, " +
                              format_number(cha) + " m in " + in_quotes(A.name));
  for (const WallCorner& k : A.corners)
    if (k.at_end == b.corner_at_end)
      r.fail("corner_at", std::string("wall ") + in_quotes(A.name) + " already has a corner at its " +
                              (b.corner_at_end ? "end" : "start"));
  const double ta = wall_thickness(A), tb = wall_thickness(B);
  const double th = A.direction * std::numbers::pi / 180.0;
  const Vec3 eu(std::cos(th), std::sin(th), 0), ev(-std::sin(th), std::cos(th), 0);
  const double along = b.corner_at_end ? A.length - 0.5 * tb : 0.5 * tb;
  B.origin = A.origin + along * eu + (b.turn_left ? -0.5 : 0.5) * ta * ev;
  B.direction = A.direction + (b.turn_left ? 90.0 : -90.0);
  const int shared = std::min(na, nb);
  if (a_running) {
    // a's units run through the corner in even courses, b's in odd ones.
    A.corners.push_back({b.corner_at_end, tb, 1, shared});
    B.corners.push_back({false, ta, 0, shared});
    return;
  }
  // Each wall owns the corner square in the courses of its quoin parity
  // (quoin header and closer there) and stops at it in the others: b's
  // bond is turned by a course if that parity would be a's.
  B.course_shift = 0;
  if (quoin_parity(B) == quoin_parity(A)) B.course_shift = 1;
  A.corners.push_back({b.corner_at_end, tb, 1 - quoin_parity(A), shared});
  B.corners.push_back({false, ta, 1 - quoin_parity(B), shared});
}
std::string group_of(const WallSection& w, const GeneratedBlock& b) {
  std::string g = w.group_prefix;
  switch (w.group_by) {
    case GroupBy::course: g.append("course").append(two_digits(b.course)); break;
    case GroupBy::leaf: g.append(b.leaf >= 0 ? "leaf" + std::to_string(b.leaf) : std::string("through")); break;
    case GroupBy::kind: g.append(to_string(b.kind)); break;
    case GroupBy::wall: g.append(w.spec.name); break;
  }
  return g;
}

void read_wall_sections(const Deck& deck, Generated& out, SceneSpec&) {
  const std::vector<const toml::table*> tables = section_tables(deck, "wall");
  std::vector<WallSection> walls;
  for (std::size_t i = 0; i < tables.size(); ++i) {
    WallSection w = read_wall(deck, *tables[i], i);
    if (!w.corner_with.empty()) {
      std::size_t j = 0;
      while (j < walls.size() && walls[j].spec.name != w.corner_with) ++j;
      if (j == walls.size())
        w.readers.front().fail("corner_with", "no [[wall]] above this one is named " + in_quotes(w.corner_with));
      place_at_corner(w, walls[j]);
    }
    require_new_section_name(deck, "wall", *tables[i], i, w.spec.name, walls);
    walls.push_back(std::move(w));
  }
  for (WallSection& w : walls) build_section(deck, w);
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const WallSection& w = walls[i];
    out.parts.push_back(generated_part(indexed("wall", i + 1), w.table, w.line, w.density, w.model.blocks,
                                       [&](const GeneratedBlock& wb) {
                                         BlockSpec b;
                                         b.name = wb.name;
                                         b.shape = wb.shape;
                                         b.course = wb.course;
                                         b.group = group_of(w, wb);
                                         return b;
                                       }));
  }
}

}  // namespace

const GeneratorSection kWallSection{"wall", kWallKeys, read_wall_sections};

}  // namespace polydem
