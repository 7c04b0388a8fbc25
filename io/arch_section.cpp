// [[arch]]: arches, barrel vaults and arcades of structures/arch.hpp, one per
// table. Each table's `name` prefixes its blocks' names ("nave_voussoir03"),
// so several arches in one deck stay apart; the blocks' groups say what they
// are ("voussoir", "pier", "abutment", "base") and the voussoirs' and piers'
// `course` their ring or course.
#include "io/generators.hpp"

#include "structures/arch.hpp"

namespace polydem {

namespace {

using namespace deck_reader;

constexpr std::string_view kArchKeys[] = {
    "name",        "shape",       "span",         "radius",        "embrace",      "rise",
    "pointedness", "voussoirs",   "thickness",    "depth",         "rings",        "spans",
    "supports",    "pier_width",  "pier_height",  "pier_courses",  "base_thickness", "support_motion",
    "origin",      "direction",   "density"};

// A key that the chosen shape or supports do not use is an error, not a
// silent no-op.
void refuse(const TableReader& r, std::string_view key, const std::string& why) {
  if (r.has(key)) r.fail(key, why);
}

int small_integer(const TableReader& r, std::string_view key, int fallback, int lo, int hi) {
  const auto n = r.integer(key);
  if (!n) return fallback;
  if (*n < lo || *n > hi)
    r.fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " + std::to_string(*n) + ")");
  return static_cast<int>(*n);
}

struct ArchSection {
  using Spec = ArchSpec;

  static constexpr GeneratorRules rules{.section = "arch",
                                        .keys = kArchKeys,
                                        .order = 40,
                                        .single = false,
                                        .naming = Naming::prefix,
                                        .motion_key = "support_motion",
                                        .grouping = Grouping::kind,
                                        .group_by = {},
                                        .max_blocks = 20000};

  static ArchSpec read(GeneratorTable& table, std::vector<ArchSpec>&) {
    const TableReader& r = table.reader();
    ArchSpec s;
    s.shape = r.choice<ArchShape>("shape",
                                  {{"circular", ArchShape::circular},
                                   {"segmental", ArchShape::segmental},
                                   {"pointed", ArchShape::pointed}},
                                  s.shape);
    const std::string shape_name = r.string("shape").value_or("circular");
    const std::string not_for = "is not used by shape = \"" + shape_name + "\"";
    switch (s.shape) {
      case ArchShape::circular:
        refuse(r, "rise", not_for + " (a segmental arch: shape = \"segmental\")");
        refuse(r, "pointedness", not_for + " (shape = \"pointed\")");
        if (r.has("span") && r.has("radius"))
          r.fail("radius", "give span or radius, not both (span = 2 radius sin(embrace/2))");
        s.radius = r.number("radius", 0.0, Range::positive);
        s.span = r.number("span", r.has("radius") ? 0.0 : 2.0, Range::positive);
        s.embrace = r.number("embrace", s.embrace, Range::positive);
        break;
      case ArchShape::segmental:
        refuse(r, "radius", not_for + ": a segmental arch is given by span and rise");
        refuse(r, "embrace", not_for + ": a segmental arch is given by span and rise");
        refuse(r, "pointedness", not_for);
        s.span = r.number("span", 2.0, Range::positive);
        if (!r.has("rise")) r.missing("rise", "a segmental arch needs its rise (intrados, springing line to crown)");
        s.rise = r.number("rise", 0.0, Range::positive);
        break;
      case ArchShape::pointed:
        refuse(r, "radius", not_for + ": a pointed arch is given by span and pointedness");
        refuse(r, "embrace", not_for);
        refuse(r, "rise", not_for);
        s.span = r.number("span", 2.0, Range::positive);
        s.pointedness = r.number("pointedness", s.pointedness, Range::positive);
        break;
    }
    s.voussoirs = small_integer(r, "voussoirs", s.voussoirs, 3, 1000);
    s.thickness = r.number("thickness", s.thickness, Range::positive);
    s.depth = r.number("depth", s.depth, Range::positive);
    s.rings = small_integer(r, "rings", s.rings, 1, 200);
    s.spans = small_integer(r, "spans", s.spans, 1, 50);
    s.supports = r.choice<ArchSupports>("supports",
                                        {{"abutments", ArchSupports::abutments},
                                         {"piers", ArchSupports::piers},
                                         {"base", ArchSupports::base}},
                                        s.supports);
    if (s.supports != ArchSupports::piers)
      refuse(r, "pier_courses", "only piers have courses (supports = \"piers\")");
    if (s.supports == ArchSupports::base)
      refuse(r, "pier_height", "there are no piers on a fixed base (supports = \"base\")");
    if (s.supports == ArchSupports::abutments)
      refuse(r, "base_thickness", "abutments stand on nothing: there is no base slab (supports = \"abutments\")");
    s.pier_width = r.number("pier_width", 0.0, Range::positive);
    s.pier_height = r.number("pier_height", 0.0, Range::positive);
    s.pier_courses = small_integer(r, "pier_courses", s.pier_courses, 1, 100);
    s.base_thickness = r.number("base_thickness", 0.0, Range::positive);
    s.origin = r.vec3("origin").value_or(s.origin);
    s.direction = r.vec3("direction").value_or(s.direction);
    return s;
  }

  static ArchModel build(const ArchSpec& s) { return build_arch(s); }
};

// All the [[arch]] tables of a deck together build at most 20000 blocks
// (each at most 5000): a short deck cannot ask for millions.
const RegisteredSection registered(generator_section<ArchSection>());

}  // namespace

}  // namespace polydem
