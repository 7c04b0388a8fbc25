// [[cut]] (io/cut_section.hpp): reads each joint set, selects the blocks,
// cuts them (geometry/cut.hpp) and puts the pieces in place of each block.
#include "io/cut_section.hpp"

#include "geometry/cut.hpp"

#include <cmath>
#include <limits>
#include <set>

namespace polydem {

namespace {

using namespace deck_reader;

constexpr std::size_t kMaxBlocks = 100000;

constexpr std::string_view kCutKeys[] = {"dip",    "dip_direction", "origin", "spacing", "count",
                                         "blocks", "groups",        "group",  "min_thickness"};

// An array of strings, each checked by `known` (its message if not).
template <class Known>
std::vector<std::string> names(const TableReader& r, std::string_view key, const char* what, Known known) {
  std::vector<std::string> out;
  const toml::node* n = r.table().get(key);
  if (!n) return out;
  const auto* arr = n->as_array();
  if (!arr) r.fail(key, std::string("must be an array of ") + what + " names (got " + describe(*n) + ")");
  if (arr->empty()) r.fail(key, std::string("is empty: no block selected (leave the key out to cut every free block)"));
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const toml::node& e = *arr->get(i);
    const std::string path = indexed(r.key_path(key), i + 1);
    const auto* s = e.as_string();
    if (!s) r.deck().fail(path, &e, std::string("must be a ") + what + " name (got " + describe(e) + ")");
    if (!known(s->get())) r.deck().fail(path, &e, std::string("unknown ") + what + " " + in_quotes(s->get()));
    out.push_back(s->get());
  }
  return out;
}

void apply_cut(const Deck& deck, const toml::table& t, std::size_t number, std::vector<BlockSpec>& blocks) {
  const TableReader r(deck, t, indexed("cut", number), kCutKeys);
  const auto dip = r.number("dip");
  if (!dip) r.missing("dip", "a joint set needs dip (degrees from horizontal, 0..90)");
  if (*dip < 0 || *dip > 90) r.fail("dip", "must be in [0, 90] degrees (got " + format_number(*dip) + ")");
  const double dip_direction = r.number("dip_direction", 0.0, Range::any);
  if (dip_direction < 0 || dip_direction > 360)
    r.fail("dip_direction", "must be in [0, 360] degrees clockwise from north, +y (got " +
                                format_number(dip_direction) + ")");
  JointSet set;
  set.normal = joint_set_normal(*dip, dip_direction);
  set.origin = r.vec3("origin").value_or(Vec3::Zero());
  if (const auto c = r.integer("count")) {
    if (*c < 1 || *c > 100000) r.fail("count", "must be in [1, 100000] (got " + std::to_string(*c) + ")");
    set.count = static_cast<int>(*c);
  }
  if (const auto s = r.number("spacing")) {
    r.check_range("spacing", *s, Range::positive);
    set.spacing = *s;
  } else if (set.count > 1) {
    r.missing("spacing", "count = " + std::to_string(set.count) + " planes need their spacing (m)");
  }
  set.min_thickness = r.number("min_thickness", 0.001, Range::non_negative);
  const auto group = r.string("group");
  if (group && group->empty()) r.fail("group", "must not be empty (leave the key out to keep each block's group)");

  const auto by_name = names(r, "blocks", "block", [&](const std::string& s) {
    return std::any_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) { return b.name == s; });
  });
  const auto by_group = names(r, "groups", "group", [&](const std::string& s) {
    return std::any_of(blocks.begin(), blocks.end(), [&](const BlockSpec& b) { return b.group == s; });
  });
  const bool everything = !r.has("blocks") && !r.has("groups");
  const auto selected = [&](const BlockSpec& b) {
    if (everything) return b.motion == BlockMotion::free;
    return std::find(by_name.begin(), by_name.end(), b.name) != by_name.end() ||
           std::find(by_group.begin(), by_group.end(), b.group) != by_group.end();
  };
  if (std::none_of(blocks.begin(), blocks.end(), selected))
    r.fail("blocks", "no block selected (the default, every free block, finds none: give blocks or groups)");

  // Parallel planes cut a convex block into (planes crossing it + 1)
  // pieces: count them first, so that a deck cannot ask for millions of
  // blocks by accident (a spacing in mm instead of m).
  std::size_t total = 0;
  for (const BlockSpec& b : blocks) {
    if (!selected(b)) {
      ++total;
      continue;
    }
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec3& v : b.shape.vertices) {
      lo = std::min(lo, set.normal.dot(v));
      hi = std::max(hi, set.normal.dot(v));
    }
    const double first = joint_plane_offset(set, 0), last = joint_plane_offset(set, set.count - 1);
    const double from = std::max(lo, first), to = std::min(hi, last);
    const double crossing = to >= from ? std::floor((to - from) / std::max(set.spacing, 1e-300)) + 1 : 0;
    total += 1 + static_cast<std::size_t>(std::min(crossing, 1e9));
  }
  if (total > kMaxBlocks)
    r.fail("spacing", "the joint set would make about " + std::to_string(total) + " blocks, more than " +
                          std::to_string(kMaxBlocks) + " (a spacing in mm instead of m?)");

  std::set<std::string> taken;
  for (const BlockSpec& b : blocks) taken.insert(b.name);
  std::vector<BlockSpec> out;
  bool any_cut = false;
  for (BlockSpec& b : blocks) {
    if (!selected(b)) {
      out.push_back(std::move(b));
      continue;
    }
    std::vector<Polyhedron> pieces;
    try {
      pieces = cut_by_joint_set(b.shape, set);
    } catch (const GeometryError& e) {
      r.fail("origin", "cannot cut block " + in_quotes(b.name) + ": " + e.what());
    }
    if (pieces.size() == 1) {
      out.push_back(std::move(b));
      continue;
    }
    any_cut = true;
    const Vec3 c = mass_properties(b.shape).centroid;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      BlockSpec p = b;
      p.name = b.name + "_cut" + std::to_string(k + 1);
      if (taken.count(p.name))
        r.fail("blocks", "the piece of " + in_quotes(b.name) + " would be named " + in_quotes(p.name) +
                             ", which another block has; rename that block");
      taken.insert(p.name);
      p.shape = std::move(pieces[k]);
      p.velocity = b.velocity + b.angular_velocity.cross(mass_properties(p.shape).centroid - c);
      if (group) p.group = *group;
      out.push_back(std::move(p));
    }
  }
  if (!any_cut) {
    std::string what = "no plane of the joint set crosses a selected block (planes n·x = ";
    what.append(format_number(joint_plane_offset(set, 0)));
    if (set.count > 1) what.append(" … ").append(format_number(joint_plane_offset(set, set.count - 1)));
    what.append(" m with n = [").append(format_number(set.normal.x())).append(", ");
    what.append(format_number(set.normal.y())).append(", ").append(format_number(set.normal.z()));
    what.append("], cutting off at least min_thickness = ").append(format_number(set.min_thickness));
    what.append(" m)");
    r.fail("origin", what);
  }
  blocks = std::move(out);
}

}  // namespace

std::span<const std::string_view> cut_keys() { return kCutKeys; }

void apply_cuts(const Deck& deck, std::vector<BlockSpec>& blocks) {
  const auto tables = section_tables(deck, "cut");
  for (std::size_t i = 0; i < tables.size(); ++i) apply_cut(deck, *tables[i], i + 1, blocks);
}

}  // namespace polydem
