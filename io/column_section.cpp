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

struct ColumnSection {
  using Spec = ColumnSpec;

  static constexpr GeneratorRules rules{.section = "column",
                                        .keys = kColumnKeys,
                                        .order = 50,
                                        .single = false,
                                        .naming = Naming::prefix,
                                        .motion_key = "base_motion",
                                        .grouping = Grouping::kind,
                                        .group_by = {},
                                        .max_blocks = 20000};

  static ColumnSpec read(GeneratorTable& table, std::vector<ColumnSpec>&) {
    const TableReader& r = table.reader();
    ColumnSpec s;
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
    if (const toml::node* n = r.table().get("drum_heights")) {
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
          r.deck().fail(p, &e, "must be a number (got " + describe(e) + ")");
        if (!(std::isfinite(v) && v > 0)) r.deck().fail(p, &e, "must be > 0 (got " + format_number(v) + ")");
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
    return s;
  }

  static ColumnModel build(const ColumnSpec& s) { return build_column(s); }
};

// All the [[column]] tables of a deck together build at most 20000 blocks:
// a short deck cannot ask for millions.
const RegisteredSection registered(generator_section<ColumnSection>());

}  // namespace

}  // namespace polydem
