// [[import]]: blocks from a mesh file (io/block_files.hpp: OBJ, PLY, VTU),
// placed (scale, rotation about the file's origin, offset), given their
// density, motion and group, and checked: every part a closed convex solid,
// no two parts overlapping by more than simulation.overlap_tolerance.
//
// The section's reference in docs/deck.md is the comment below
// (scripts/doc_tables.py copies it there).
/* docs/deck.md
## `[[import]]`

Blocks from a mesh file (`io/block_files.hpp`), one block per closed convex
part. The blocks of each `[[import]]` are appended after the `[[block]]`
tables and the generators' blocks, in the file's order, before any
`[[cut]]`. The format is taken from the extension:

| Extension | Format | What is a part |
|---|---|---|
| .obj | Wavefront OBJ (text): `v x y z`, `f a b c …` (also `a/t/n`, `a//n`; negative indices count back), `o`/`g` names; `vt`, `vn`, `vp`, `s`, `usemtl`, `mtllib`, `l`, `p` are skipped, any other statement is an error | a connected set of faces (sharing vertices) within one object: `o` objects if the file has any (a `g` inside one, e.g. a material group, stays in it), else `g` groups; its name is the object's (`NAME_1`, `NAME_2`, … if the object holds several solids); faces of different objects are never joined |
| .ply | Stanford PLY, ASCII or binary (either byte order): `vertex` (x, y, z) and `face` (`vertex_indices` list); other elements and properties are skipped | a connected set of faces (PLY has no objects or names) |
| .vtu | VTK XML unstructured grid, ASCII data arrays, polyhedral cells (`VTK_POLYHEDRON` = 42, `faces`/`faceoffsets`): what polydem writes (`polydem mesh`'s `blocks.vtu`, a run's snapshots); binary, appended or compressed arrays and VTK 9.4's `face_connectivity` layout are not read | one cell; polydem's cell data `course` and `motion` (written by `polydem mesh`) come with it |

Each part must be closed (every edge shared by exactly two faces),
orientable (faces are turned to agree with their neighbours; a part whose
faces all point inward is turned outside in) and convex (no corner more than
1e-6 of the part's size in front of a face's plane). When the part's faces
already make a valid block (planar, no two neighbours coplanar: what polydem
writes) the block keeps them, and the vertices, in the file's order;
otherwise (faces split into triangles, as many tools write them) the block
is the CGAL hull of its corners, numbered canonically like every hull. So a
file written with shortest round-trip coordinates (`polydem mesh` writes
`blocks.obj` and `blocks.vtu` so) gives back the deck's very blocks, bit for
bit, and the same run (`examples/verification/imported_wall.toml`). A
`.vtu` has no block names: its parts are `part1`, `part2`, ….
No two parts of a file may overlap by more than
`simulation.overlap_tolerance` (penetration depth); overlaps with other
blocks are found when the run is set up. A snapshot of a loaded model has
its joints closed by their elastic overlap (weight over kn·area, about
1 µm for 4 m of rock at 98 GPa/m): raise `overlap_tolerance` (e.g. 1e-5)
to import it. Anything else is an error naming
the deck's line and key, the file, the part (number from 1, and name) and
why: `blocks.obj: part 3 "s7": not convex: vertex 12 lies 0.0032 m outside
the face at line 57`, `open: edge (3,7) belongs to one face (at line 40)`,
`part 6 overlaps part 5 by 0.012 m (penetration depth; shared volume
0.0012 m³ …)`; a malformed file (a bad count, an index out of range) is a
clear error with the file's line.

Vertices are used as written: faces that are coplanar only to the file's
precision (6 digits from many tools) stay separate, slightly folded faces
of the block. Names are `name_prefix` + the part's name, or `partN` (N from
1) for unnamed parts; a name another block has is an error.

| Key | Type | Unit | Default | Meaning |
|---|---|---|---|---|
| `file` | string | – | **required** | Path of the `.obj`, `.ply` or `.vtu` file, relative to the deck's directory. |
| `scale` | float | – | `1` | Every coordinate is multiplied by this first (e.g. `0.001` for a file in mm). Must be > 0. |
| `rotation` | [rx, ry, rz] | degrees | none | Then rotated about the file's origin: R = Rz·Ry·Rx, as a `[[block]]`'s. |
| `offset` | [x, y, z] | m | `[0, 0, 0]` | Then translated: x → R·(scale·x) + offset. |
| `density` | float | kg/m³ | `2600` | Every part's density. Must be > 0. |
| `motion` | string | – | `"free"` (or the `.vtu`'s `motion`) | `"free"`, `"fixed"` or `"kinematic"`, for every part not fixed below. |
| `fixed_below` | float | m | none | Every part whose highest corner is at or below this z (after the placement) is fixed: the base. At least one part must be. |
| `fixed` | [string or integer, ...] | – | `[]` | Parts fixed by name (as in the file) or number (from 1). |
| `group` | string | – | none | Every part's group. |
| `name_prefix` | string | – | `""` | Put before every part's name. |
*/
#include "io/generators.hpp"

#include "geometry/cut.hpp"
#include "io/block_files.hpp"

#include <limits>
#include <algorithm>
#include <filesystem>
#include <numbers>
#include <set>

namespace polydem {

namespace {

using namespace deck_reader;

constexpr std::string_view kImportKeys[] = {"file",    "scale",  "rotation", "offset",      "density", "motion",
                                            "group",   "name_prefix", "fixed_below", "fixed"};

Mat3 rotation_degrees(const std::vector<double>& deg) {
  const double k = std::numbers::pi / 180.0;
  return (Eigen::AngleAxisd(deg[2] * k, Vec3::UnitZ()) * Eigen::AngleAxisd(deg[1] * k, Vec3::UnitY()) *
          Eigen::AngleAxisd(deg[0] * k, Vec3::UnitX()))
      .toRotationMatrix();
}

std::string part_number_text(std::size_t i) { return std::to_string(i + 1); }

void read_import(const Deck& deck, const toml::table& t, std::size_t number, Generated& out, SceneSpec& scene) {
  const std::string path = indexed("import", number);
  const TableReader r(deck, t, path, kImportKeys);
  const auto file = r.string("file");
  if (!file) r.missing("file", "an [[import]] needs file = \"blocks.obj\" (.obj, .ply or .vtu)");
  if (file->empty()) r.fail("file", "must not be empty");
  std::filesystem::path p(*file);
  if (p.is_relative()) p = std::filesystem::path(deck.file()).parent_path() / p;
  const std::string resolved = p.lexically_normal().string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(resolved, ec))
    r.fail("file", "file not found: " + resolved + " (relative paths are relative to the deck's directory)");

  const double scale = r.number("scale", 1.0, Range::positive);
  const auto rotation = r.numbers("rotation", 3, "[rx, ry, rz] (degrees)");
  const auto offset = r.vec3("offset");
  const double density = r.number("density", 2600.0, Range::positive);
  // The deck's motion, else the file's (a polydem mesh .vtu), else free.
  const bool deck_motion = r.has("motion");
  const BlockMotion motion = r.choice<BlockMotion>(
      "motion", {{"free", BlockMotion::free}, {"fixed", BlockMotion::fixed}, {"kinematic", BlockMotion::kinematic}},
      BlockMotion::free);
  const auto group = r.string("group");
  if (group && group->empty()) r.fail("group", "must not be empty (leave the key out for no group)");
  const std::string prefix = r.string("name_prefix").value_or("");
  const auto fixed_below = r.number("fixed_below");

  BlockFile bf;
  try {
    bf = read_block_file(resolved);
  } catch (const BlockFileError& e) {
    r.fail("file", e.what());
  }

  // fixed = ["name", 3, ...]: parts by their name in the file or number (from 1).
  std::vector<char> fixed(bf.parts.size(), 0);
  if (const toml::node* n = t.get("fixed")) {
    const auto* arr = n->as_array();
    if (!arr) r.fail("fixed", "must be an array of part names or numbers (got " + describe(*n) + ")");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const toml::node& e = *arr->get(i);
      const std::string at = indexed(r.key_path("fixed"), i + 1);
      if (const auto* k = e.as_integer()) {
        if (k->get() < 1 || k->get() > static_cast<long long>(bf.parts.size()))
          deck.fail(at, &e, "part " + std::to_string(k->get()) + " does not exist (the file has " +
                                std::to_string(bf.parts.size()) + " parts, numbered from 1)");
        fixed[static_cast<std::size_t>(k->get() - 1)] = 1;
      } else if (const auto* s = e.as_string()) {
        bool found = false;
        for (std::size_t j = 0; j < bf.parts.size(); ++j)
          if (bf.parts[j].name == s->get()) fixed[j] = 1, found = true;
        if (!found) deck.fail(at, &e, "no part named " + in_quotes(s->get()) + " in " + resolved);
      } else {
        deck.fail(at, &e, "must be a part name or number (got " + describe(e) + ")");
      }
    }
  }

  const Mat3 R = rotation ? rotation_degrees(*rotation) : Mat3::Identity();
  const bool moved = r.has("scale") || rotation || offset;
  std::set<std::string> taken;
  for (const Generated::Part& other : out.parts)
    for (const BlockSpec& b : other.blocks) taken.insert(b.name);

  Generated::Part part;
  part.section = path;
  part.at = &t;
  part.deck_line = r.line();
  for (std::size_t i = 0; i < bf.parts.size(); ++i) {
    if (moved)
      for (Vec3& v : bf.parts[i].vertices) v = R * (scale * v) + offset.value_or(Vec3::Zero());
    BlockSpec b;
    try {
      b.shape = part_block(bf, i);
    } catch (const BlockFileError& e) {
      r.fail("file", e.what());
    }
    const FilePart& fp = bf.parts[i];
    b.name = prefix + (fp.name.empty() ? "part" + part_number_text(i) : fp.name);
    if (!taken.insert(b.name).second)
      r.fail(r.has("name_prefix") ? "name_prefix" : "file",
             part_label(bf, i) + " would be block " + in_quotes(b.name) +
                 ", a name another block already has (give a name_prefix)");
    b.density = density;
    b.motion = deck_motion       ? motion
               : fp.motion == 1 ? BlockMotion::fixed
               : fp.motion == 2 ? BlockMotion::kinematic
                                : BlockMotion::free;
    double top = -std::numeric_limits<double>::infinity();
    for (const Vec3& v : b.shape.vertices) top = std::max(top, v.z());
    if (fixed[i] || (fixed_below && top <= *fixed_below)) b.motion = BlockMotion::fixed;
    b.course = fp.course;
    if (group) b.group = *group;
    b.deck_line = part.deck_line;
    part.blocks.push_back(std::move(b));
  }
  if (fixed_below && std::none_of(part.blocks.begin(), part.blocks.end(),
                                  [](const BlockSpec& b) { return b.motion == BlockMotion::fixed; }))
    r.fail("fixed_below", "no part lies wholly below z = " + format_number(*fixed_below) + " (no block is fixed)");

  // No two parts overlap (more than the run would accept at the start).
  const double tol = scene.simulation.overlap_tolerance;
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const BlockSpec& b : part.blocks) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : b.shape.vertices) box.extend(v);
    boxes.push_back(box);
  }
  // Candidate pairs by sort and sweep along x (a file of many thousand
  // parts is not checked pair by pair), then in file order.
  std::vector<std::size_t> by_x(boxes.size());
  for (std::size_t i = 0; i < by_x.size(); ++i) by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].min().x() != boxes[b].min().x() ? boxes[a].min().x() < boxes[b].min().x() : a < b;
  });
  std::vector<std::pair<std::size_t, std::size_t>> candidates;  // (later part, earlier part)
  for (std::size_t k = 0; k < by_x.size(); ++k)
    for (std::size_t l = k + 1; l < by_x.size() && boxes[by_x[l]].min().x() < boxes[by_x[k]].max().x() - tol; ++l) {
      const std::size_t a = by_x[k], b = by_x[l];
      const Eigen::AlignedBox3d common = boxes[a].intersection(boxes[b]);
      if (common.isEmpty() || (common.sizes().array() <= tol).any()) continue;
      candidates.emplace_back(std::max(a, b), std::min(a, b));
    }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& [i, j] : candidates) {
    const double depth = penetration_depth(part.blocks[i].shape, part.blocks[j].shape);
    if (depth <= tol) continue;
    std::string what = part_label(bf, i);
    what.append(" overlaps part ").append(part_number_text(j));
    if (!bf.parts[j].name.empty()) what.append(" \"").append(bf.parts[j].name).append("\"");
    what.append(" by ").append(format_number(depth)).append(" m (penetration depth");
    if (const auto v = overlap_volume(part.blocks[i].shape, part.blocks[j].shape))
      what.append("; shared volume ").append(format_number(*v)).append(" m³");
    what.append("; tolerance simulation.overlap_tolerance = ").append(format_number(tol));
    what.append(" m; raise it if this is a joint's elastic closure, as in a snapshot of a loaded model)");
    r.fail("file", what);
  }
  out.parts.push_back(std::move(part));
}

void read_import_sections(const Deck& deck, Generated& out, SceneSpec& scene) {
  const auto tables = section_tables(deck, "import");
  for (std::size_t i = 0; i < tables.size(); ++i) read_import(deck, *tables[i], i + 1, out, scene);
}

// Read after the generators of structures/: its parts' names are checked against their blocks'.
const RegisteredSection registered(
    {.name = "import", .keys = kImportKeys, .order = 90, .read = read_import_sections});

}  // namespace

}  // namespace polydem
