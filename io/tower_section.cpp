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

constexpr std::pair<std::string_view, Grouping> kTowerGroupings[] = {
    {"course", Grouping::course}, {"face", Grouping::face}, {"kind", Grouping::kind}, {"tower", Grouping::section}};

struct TowerSection {
  using Spec = TowerSpec;

  static constexpr GeneratorRules rules{.section = "tower",
                                        .keys = kTowerKeys,
                                        .order = 30,
                                        .single = false,
                                        .naming = Naming::owned,
                                        .motion_key = "",
                                        .grouping = Grouping::course,
                                        .group_by = kTowerGroupings,
                                        .max_blocks = 0};

  static TowerSpec read(GeneratorTable& table, std::vector<TowerSpec>&) {
    const TableReader& r = table.reader();
    TowerSpec s;
    s.name = table.name;
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
    open_openings(rules, table);
    for (std::size_t i = 1; i < table.readers.size(); ++i) {
      const TableReader& o = table.readers[i];
      TowerOpening op;
      for (const char* k : {"faces", "width", "height"})
        if (!o.has(k)) o.missing(k, "an opening needs faces, width and height");
      const toml::node* fn = o.table().get("faces");
      const auto* arr = fn->as_array();
      if (!arr) o.fail("faces", "must be an array of face indices (got " + describe(*fn) + ")");
      for (std::size_t j = 0; j < arr->size(); ++j) {
        const toml::node& e = *arr->get(j);
        const auto* v = e.as_integer();
        const std::string path = indexed(o.key_path("faces"), j + 1);
        if (!v) r.deck().fail(path, &e, "must be an integer face index (got " + describe(e) + ")");
        if (v->get() < 0 || v->get() >= s.sides)
          r.deck().fail(path, &e,
                        "face indices are 0.." + std::to_string(s.sides - 1) + ", face 0 facing +x (got " +
                            std::to_string(v->get()) + ")");
        op.faces.push_back(static_cast<int>(v->get()));
      }
      read_opening(o, op);
      s.openings.push_back(op);
    }
    return s;
  }

  static TowerModel build(const TowerSpec& s) { return build_tower(s); }

  static std::string key_of(const GeneratorTable&, const GeneratorSpecError& e) {
    return e.field == "sides" ? "shape" : e.field;
  }
};

const RegisteredSection registered(generator_section<TowerSection>());

}  // namespace

}  // namespace polydem
