// [spire]: the octagonal spire of structures/spire.hpp (CGAL, exact), the
// materials its joints are made of (their series stiffness sets the joint
// defaults) and how its base block moves.
#include "io/generators.hpp"

#include "core/materials.hpp"
#include "structures/spire.hpp"

namespace polydem {

namespace {

using namespace deck_reader;

constexpr std::string_view kSpireKeys[] = {
    "height",           "base_inradius",         "wall_thickness",      "wall_thickness_top",
    "course_height",    "tip_height",            "stones_per_face",     "joint_pattern",
    "window_faces",     "window_sill",           "window_width",        "window_head",
    "window_head_shape", "window_arch_segments", "base_thickness",      "base_apothem",        "base_motion",
    "density",          "stone_youngs_modulus",  "mortar_youngs_modulus", "mortar_thickness",
    "shear_stiffness_ratio", "origin"};

struct SpireSection {
  struct Spec {
    SpireSpec spire;
    Vec3 origin = Vec3::Zero();  // where the spire's frame origin (the axis at the bed of course 0) stands
  };

  static constexpr GeneratorRules rules{.section = "spire",
                                        .keys = kSpireKeys,
                                        .order = 10,
                                        .single = true,
                                        .naming = Naming::none,
                                        .motion_key = "base_motion",
                                        .grouping = Grouping::course,
                                        .group_by = {},
                                        .max_blocks = 0};

  static Spec read(GeneratorTable& table, std::vector<Spec>&) {
    const TableReader& r = table.reader();
    const Deck& deck = r.deck();
    Spec out;
    SpireSpec& s = out.spire;
    s.height = r.number("height", s.height, Range::positive);
    s.base_inradius = r.number("base_inradius", s.base_inradius, Range::positive);
    s.wall_thickness = r.number("wall_thickness", s.wall_thickness, Range::positive);
    s.wall_thickness_top = r.number("wall_thickness_top", s.wall_thickness_top, Range::positive);
    s.course_height = r.number("course_height", s.course_height, Range::positive);
    s.tip_height = r.number("tip_height", s.tip_height, Range::positive);
    if (const auto n = r.integer("stones_per_face")) {
      if (*n < 1 || *n > 64) r.fail("stones_per_face", "must be in [1, 64] (got " + std::to_string(*n) + ")");
      s.stones_per_face = static_cast<int>(*n);
    }
    s.joint_pattern = r.choice<SpireJointPattern>("joint_pattern",
                                                  {{"staggered", SpireJointPattern::staggered},
                                                   {"aligned", SpireJointPattern::aligned},
                                                   {"aligned_above_windows", SpireJointPattern::aligned_above_windows}},
                                                  s.joint_pattern);
    if (const toml::node* n = r.table().get("window_faces")) {
      const auto* arr = n->as_array();
      if (!arr) r.fail("window_faces", "must be an array of face indices 0..7 (got " + describe(*n) + ")");
      s.window_faces.clear();
      for (std::size_t i = 0; i < arr->size(); ++i) {
        const toml::node& e = *arr->get(i);
        const auto* v = e.as_integer();
        const std::string path = indexed(r.key_path("window_faces"), i + 1);
        if (!v) deck.fail(path, &e, "must be an integer face index 0..7 (got " + describe(e) + ")");
        if (v->get() < 0 || v->get() > 7)
          deck.fail(path, &e, "face indices are 0..7, face 0 facing +x (got " + std::to_string(v->get()) + ")");
        if (std::find(s.window_faces.begin(), s.window_faces.end(), v->get()) != s.window_faces.end())
          deck.fail(path, &e, "face " + std::to_string(v->get()) + " is listed twice (one window per face)");
        s.window_faces.push_back(static_cast<int>(v->get()));
      }
    }
    s.window_sill = r.number("window_sill", s.window_sill, Range::non_negative);
    s.window_width = r.number("window_width", s.window_width, Range::positive);
    s.window_head = r.number("window_head", s.window_head, Range::positive);
    s.window_head_shape = r.choice<WindowHead>("window_head_shape",
                                               {{"pointed", WindowHead::pointed}, {"flat", WindowHead::flat}},
                                               s.window_head_shape);
    if (const auto n = r.integer("window_arch_segments")) {
      if (*n < 1 || *n > 64) r.fail("window_arch_segments", "must be in [1, 64] (got " + std::to_string(*n) + ")");
      s.window_arch_segments = static_cast<int>(*n);
    }
    s.base_thickness = r.number("base_thickness", s.base_thickness, Range::non_negative);
    s.base_apothem = r.number("base_apothem", s.base_apothem, Range::non_negative);
    if (r.has("base_apothem") && s.base_thickness == 0)
      r.fail("base_apothem", "there is no base block (base_thickness = 0)");
    if (r.has("base_motion") && s.base_thickness == 0)
      r.fail("base_motion", "there is no base block (base_thickness = 0)");
    out.origin = r.vec3("origin").value_or(out.origin);
    return out;
  }

  static SpireModel build(const Spec& s) { return build_spire(s.spire); }

  // The spire stands at `origin`; its materials set the joints' defaults.
  static void finish(const GeneratorTable& table, const Spec& s, SpireModel& model, Generated& out) {
    const TableReader& r = table.reader();
    if (!s.origin.isZero())
      for (GeneratedBlock& b : model.blocks) b.shape = transformed(b.shape, Mat3::Identity(), s.origin);
    // Table 1: E_stone 30 GPa, E_mortar 10 GPa; section 3.1: 1 cm of mortar.
    const double e_stone = r.number("stone_youngs_modulus", 30e9, Range::positive);
    const double e_mortar = r.number("mortar_youngs_modulus", 10e9, Range::positive);
    const double mortar = r.number("mortar_thickness", 0.01, Range::non_negative);
    if (!(mortar < model.course_height))
      r.fail("mortar_thickness", "must be less than the course pitch " + format_number(model.course_height) +
                                     " m (got " + format_number(mortar) + ")");
    JointDefaults joint;
    joint.normal_stiffness = series_joint_normal_stiffness(model.course_height, mortar, e_stone, e_mortar);
    joint.shear_ratio = r.number("shear_stiffness_ratio", joint.shear_ratio, Range::positive);
    out.joint = joint;
    out.specs.spire = s.spire;
  }
};

const RegisteredSection registered(generator_section<SpireSection>());

}  // namespace

}  // namespace polydem
