// [[column]]: columns of drums of structures/column.hpp, one per table. Each
// table's `name` prefixes its blocks' names ("portico1_drum03"); the groups
// are "base", "plinth", "drum" and "capital", and a drum's `course` is its
// index from the bottom.
#include "io/generators.hpp"

#include "structures/column.hpp"

namespace polydem {

namespace {

using namespace deck_reader;

constexpr std::string_view kColumnKeys[] = {
    "name",          "drums",        "radius",         "sides",          "height",
    "drum_heights",  "plinth_width", "plinth_height",  "capital",        "capital_width",
    "capital_height", "base_width",  "base_thickness", "base_motion",    "origin",
    "density"};

void read_one_column(const Deck& deck, const toml::table& t, std::size_t number, std::size_t count,
                     Generated& out) {
  const std::string path = indexed("column", number);
  const TableReader r(deck, t, path, kColumnKeys);
  ColumnSpec s;
  std::string name = count > 1 ? "column" + std::to_string(number) : "column";
  if (const auto n = r.string("name")) {
    if (n->empty()) r.fail("name", "must not be empty (it prefixes the blocks' names)");
    name = *n;
  }
  if (const auto n = r.integer("drums")) {
    if (*n < 1 || *n > 1000) r.fail("drums", "must be in [1, 1000] (got " + std::to_string(*n) + ")");
    s.drums = static_cast<int>(*n);
  }
  s.radius = r.number("radius", s.radius, Range::positive);
  if (const auto n = r.integer("sides")) {
    if (*n < 4 || *n > 128) r.fail("sides", "must be in [4, 128] (got " + std::to_string(*n) + ")");
    s.sides = static_cast<int>(*n);
  }
  if (r.has("height") && r.has("drum_heights"))
    r.fail("drum_heights", "give height (equal drums) or drum_heights, not both");
  s.height = r.number("height", s.height, Range::positive);
  if (const toml::node* n = t.get("drum_heights")) {
    const auto* arr = n->as_array();
    if (!arr) r.fail("drum_heights", "must be an array of heights, one per drum, bottom up (got " + describe(*n) + ")");
    if (arr->empty()) r.fail("drum_heights", "must list at least one drum's height (or give height)");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const toml::node& e = *arr->get(i);
      const std::string p = indexed(r.key_path("drum_heights"), i + 1);
      double v = 0;
      if (const auto* f = e.as_floating_point())
        v = f->get();
      else if (const auto* k = e.as_integer())
        v = static_cast<double>(k->get());
      else
        deck.fail(p, &e, "must be a number (got " + describe(e) + ")");
      if (!(std::isfinite(v) && v > 0)) deck.fail(p, &e, "must be > 0 (got " + format_number(v) + ")");
      s.drum_heights.push_back(v);
    }
    if (!r.has("drums")) s.drums = static_cast<int>(s.drum_heights.size());
  }
  s.plinth_height = r.number("plinth_height", s.plinth_height, Range::positive);
  s.plinth_width = r.number("plinth_width", s.plinth_width, Range::positive);
  s.capital = r.choice<ColumnCapital>("capital",
                                      {{"none", ColumnCapital::none},
                                       {"abacus", ColumnCapital::abacus},
                                       {"frustum", ColumnCapital::frustum}},
                                      s.capital);
  s.capital_width = r.number("capital_width", s.capital_width, Range::positive);
  s.capital_height = r.number("capital_height", s.capital_height, Range::positive);
  s.base_width = r.number("base_width", s.base_width, Range::positive);
  s.base_thickness = r.number("base_thickness", s.base_thickness, Range::positive);
  s.origin = r.vec3("origin").value_or(s.origin);
  const double density = r.number("density", 2600.0, Range::positive);
  const BlockMotion base_motion = r.choice<BlockMotion>(
      "base_motion", {{"fixed", BlockMotion::fixed}, {"kinematic", BlockMotion::kinematic}}, BlockMotion::fixed);

  ColumnModel model;
  try {
    model = build_column(s);
  } catch (const ColumnSpecError& e) {
    r.fail(e.field, e.detail);
  } catch (const GeometryError& e) {
    deck.fail(path, &t, std::string("cannot build the column: ") + e.what());
  }

  out.parts.push_back(generated_part(path, &t, r.line(), density, model.blocks, [&](const GeneratedBlock& cb) {
    BlockSpec b;
    b.name = name;
    b.name.append("_").append(cb.name);
    b.shape = cb.shape;
    b.motion = cb.kind == BlockKind::base ? base_motion : BlockMotion::free;
    b.course = cb.index;
    b.group = to_string(cb.kind);
    return b;
  }));
}

// All the [[column]] tables of a deck together build at most this many
// blocks: a short deck cannot ask for millions.
constexpr std::size_t kMaxColumnBlocks = 20000;

void read_column_sections(const Deck& deck, Generated& out, SceneSpec&) {
  const auto tables = section_tables(deck, "column");
  std::size_t total = 0;
  for (std::size_t i = 0; i < tables.size(); ++i) {
    read_one_column(deck, *tables[i], i + 1, tables.size(), out);
    total += out.parts.back().blocks.size();
    if (total > kMaxColumnBlocks)
      deck.fail(indexed("column", i + 1), tables[i],
                "the [[column]] tables up to this one build " + std::to_string(total) + " blocks (at most " +
                    std::to_string(kMaxColumnBlocks) + " in a deck)");
  }
}

}  // namespace

const GeneratorSection kColumnSection{"column", kColumnKeys, read_column_sections};

}  // namespace polydem
