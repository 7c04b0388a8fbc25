// [[tower]]: hollow square or octagonal masonry towers
// (structures/tower.hpp), one per table, each with its openings as
// [[tower.opening]] tables. Block names start with the tower's name; groups
// come from what each block is (group_by) with an optional prefix.
#include "io/generators.hpp"

#include "structures/tower.hpp"

#include <algorithm>

namespace polydem {

namespace {

using namespace deck_reader;

// The [[tower]] keys, then its [[tower.opening]] keys as "opening.KEY".
constexpr std::string_view kTowerKeys[] = {
    "name",          "shape",          "origin",       "outer_apothem",     "wall_thickness", "height",
    "course_height", "stones_per_face", "density",     "group_by",          "group",          "opening",
    "opening.faces", "opening.sill",   "opening.width", "opening.height",   "opening.head",   "opening.bearing",
    "opening.voussoirs", "opening.ring"};

std::vector<std::string_view> keys_with_prefix(std::string_view prefix) {
  std::vector<std::string_view> out;
  for (std::string_view k : kTowerKeys) {
    if (prefix.empty() && k.find('.') == std::string_view::npos) out.push_back(k);
    if (!prefix.empty() && k.rfind(prefix, 0) == 0) out.push_back(k.substr(prefix.size()));
  }
  return out;
}

enum class GroupBy { course, face, kind, tower };

struct TowerSection {
  TowerSpec spec;
  TowerModel model;
  double density = 2600.0;
  GroupBy group_by = GroupBy::course;
  std::string group_prefix;
  int line = 0;
  const toml::table* table = nullptr;
};

std::string two_digits(int v) {
  std::string s = std::to_string(v);
  if (s.size() < 2) s.insert(s.begin(), '0');
  return s;
}

TowerSection read_tower(const Deck& deck, const toml::table& t, std::size_t index) {
  const std::string path = indexed("tower", index + 1);
  const std::vector<std::string_view> keys = keys_with_prefix("");
  const TableReader r(deck, t, path, keys);
  TowerSection out;
  out.line = r.line();
  out.table = &t;
  TowerSpec& s = out.spec;
  s.name = r.string("name").value_or("tower" + std::to_string(index + 1));
  if (s.name.empty() || s.name.find_first_of(" \t\n\"") != std::string::npos)
    r.fail("name", "must be a non-empty name without spaces or quotes (it starts every block's name)");
  s.sides = r.choice<int>("shape", {{"square", 4}, {"octagonal", 8}}, s.sides);
  s.origin = r.vec3("origin").value_or(s.origin);
  s.outer_apothem = r.number("outer_apothem", s.outer_apothem, Range::positive);
  s.wall_thickness = r.number("wall_thickness", s.wall_thickness, Range::positive);
  s.height = r.number("height", s.height, Range::positive);
  s.course_height = r.number("course_height", s.course_height, Range::positive);
  if (const auto n = r.integer("stones_per_face")) {
    if (*n < 1 || *n > 32) r.fail("stones_per_face", "must be in [1, 32] (got " + std::to_string(*n) + ")");
    s.stones_per_face = static_cast<int>(*n);
  }
  out.density = r.number("density", out.density, Range::positive);
  out.group_by = r.choice<GroupBy>(
      "group_by", {{"course", GroupBy::course}, {"face", GroupBy::face}, {"kind", GroupBy::kind}, {"tower", GroupBy::tower}},
      out.group_by);
  out.group_prefix = r.string("group").value_or("");

  std::vector<const toml::table*> opening_tables;
  if (const toml::node* n = t.get("opening")) {
    const auto* arr = n->as_array();
    if (!arr)
      r.fail("opening", "must be an array of tables: write [[tower.opening]] under its [[tower]] (got " + describe(*n) + ")");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const auto* ot = arr->get(i)->as_table();
      if (!ot)
        deck.fail(indexed(r.key_path("opening"), i + 1), arr->get(i),
                  "must be a table: write [[tower.opening]] (got " + describe(*arr->get(i)) + ")");
      opening_tables.push_back(ot);
    }
  }
  const std::vector<std::string_view> okeys = keys_with_prefix("opening.");
  std::vector<TableReader> readers;
  for (std::size_t i = 0; i < opening_tables.size(); ++i) {
    readers.emplace_back(deck, *opening_tables[i], indexed(r.key_path("opening"), i + 1), okeys);
    const TableReader& o = readers.back();
    TowerOpening op;
    for (const char* k : {"faces", "width", "height"})
      if (!o.has(k)) o.missing(k, "an opening needs faces, width and height");
    const toml::node* fn = opening_tables[i]->get("faces");
    const auto* arr = fn->as_array();
    if (!arr) o.fail("faces", "must be an array of face indices (got " + describe(*fn) + ")");
    for (std::size_t j = 0; j < arr->size(); ++j) {
      const toml::node& e = *arr->get(j);
      const auto* v = e.as_integer();
      if (!v) deck.fail(indexed(o.key_path("faces"), j + 1), &e, "must be an integer face index (got " + describe(e) + ")");
      if (v->get() < 0 || v->get() >= s.sides)
        deck.fail(indexed(o.key_path("faces"), j + 1), &e,
                  "face indices are 0.." + std::to_string(s.sides - 1) + ", face 0 facing +x (got " +
                      std::to_string(v->get()) + ")");
      op.faces.push_back(static_cast<int>(v->get()));
    }
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

  try {
    out.model = build_tower(s);
  } catch (const TowerSpecError& e) {
    std::string key = e.field == "sides" ? "shape" : e.field;
    if (e.opening >= 0) readers[static_cast<std::size_t>(e.opening)].fail(key, e.detail);
    r.fail(key, e.detail);
  } catch (const GeometryError& e) {
    deck.fail(path, &t, std::string("cannot build the tower: ") + e.what());
  }
  return out;
}

std::string group_of(const TowerSection& w, const GeneratedBlock& b) {
  std::string g = w.group_prefix;
  switch (w.group_by) {
    case GroupBy::course: g.append("course").append(two_digits(b.course)); break;
    case GroupBy::face: g.append("face").append(std::to_string(b.face)); break;
    case GroupBy::kind: g.append(to_string(b.kind)); break;
    case GroupBy::tower: g.append(w.spec.name); break;
  }
  return g;
}

void read_tower_sections(const Deck& deck, Generated& out, SceneSpec&) {
  const std::vector<const toml::table*> tables = section_tables(deck, "tower");
  std::vector<TowerSection> towers;
  for (std::size_t i = 0; i < tables.size(); ++i) {
    TowerSection w = read_tower(deck, *tables[i], i);
    require_new_section_name(deck, "tower", *tables[i], i, w.spec.name, towers);
    towers.push_back(std::move(w));
  }
  for (std::size_t i = 0; i < towers.size(); ++i) {
    const TowerSection& w = towers[i];
    out.parts.push_back(generated_part(indexed("tower", i + 1), w.table, w.line, w.density, w.model.blocks,
                                       [&](const GeneratedBlock& tb) {
                                         BlockSpec b;
                                         b.name = tb.name;
                                         b.shape = tb.shape;
                                         b.course = tb.course;
                                         b.group = group_of(w, tb);
                                         return b;
                                       }));
  }
}

}  // namespace

const GeneratorSection kTowerSection{"tower", kTowerKeys, read_tower_sections};

}  // namespace polydem
