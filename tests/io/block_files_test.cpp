// Mesh files to blocks: OBJ, PLY (ASCII and binary) and polydem's own .vtu
// give back the blocks written, bit for bit; parts are split as documented;
// an open, non-convex or non-orientable part is refused naming the file's
// own numbers; a malformed file (every truncation of a good one included) is
// a BlockFileError, never a crash.
#include "io/block_files.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "io/vtk.hpp"

namespace polydem {
namespace {

Polyhedron octagonal_prism(double r, const Vec3& shift) {
  std::vector<Vec3> pts;
  for (int k = 0; k < 8; ++k) {
    const double a = 0.3 + 2 * std::numbers::pi * k / 8;
    for (double z : {0.0, 0.7}) pts.push_back(Vec3(r * std::cos(a), r * std::sin(a), z) + shift);
  }
  return convex_hull(pts);
}

std::vector<Polyhedron> some_blocks() {
  return {octagonal_prism(0.4, Vec3(0.1, 0.2, 0.3)), convex_hull({Vec3(1, 0, 0), Vec3(2, 0.1, 0), Vec3(1.3, 1, 0),
                                                                 Vec3(1.5, 0.4, 0.9), Vec3(1.9, 0.8, 0.5)})};
}

void expect_same(const Polyhedron& a, const Polyhedron& b) {
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.offsets, b.offsets);
}

void expect_message(const std::function<void()>& f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "accepted; expected an error with: " << fragment;
  } catch (const BlockFileError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << "message: " << e.what()
                                                                      << "\nexpected: " << fragment;
  }
}

// A unit box as 12 triangles, OBJ syntax with texture/normal references.
const std::string kTriangulatedBox = R"(# a box, triangulated, as many tools write it
o box
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vn 0 0 1
f 1/1/1 3/1/1 2/1/1
f 1//1 4//1 3//1
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 2 3 7
f 2 7 6
f 3 4 8
f 3 8 7
f -4 -8 -5
f -4 -5 -1
)";

TEST(BlockFiles, ObjRoundTripIsBitForBit) {
  const auto blocks = some_blocks();
  const std::string text = obj_document(blocks, {"prism", "lump"});
  const BlockFile f = parse_obj(text, "two.obj");
  ASSERT_EQ(f.parts.size(), 2u);
  EXPECT_EQ(f.parts[0].name, "prism");
  EXPECT_EQ(f.parts[1].name, "lump");
  for (std::size_t i = 0; i < 2; ++i) expect_same(part_block(f, i), blocks[i]);
  // Blocks that are not hulls (make_box numbers its corners its own way)
  // come back as written too.
  const std::vector<Polyhedron> boxes = {make_box(Vec3(0.3, 0.2, 0.1), Vec3(1, 2, 3)),
                                         make_prism({Vec2(0, 0), Vec2(1, 0), Vec2(0.2, 0.7)}, 0.5, 0.9)};
  const BlockFile g = parse_obj(obj_document(boxes, {"box", "prism"}), "boxes.obj");
  for (std::size_t i = 0; i < 2; ++i) expect_same(part_block(g, i), boxes[i]);
}

TEST(BlockFiles, TriangulatedObjBoxBecomesASixFacedBlock) {
  const BlockFile f = parse_obj(kTriangulatedBox, "box.obj");
  ASSERT_EQ(f.parts.size(), 1u);
  const Polyhedron b = part_block(f, 0);
  EXPECT_EQ(b.faces.size(), 6u);
  EXPECT_EQ(mass_properties(b).volume, 1.0);
  expect_same(b, convex_hull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 0, 1),
                              Vec3(1, 1, 1), Vec3(0, 1, 1)}));
}

TEST(BlockFiles, PartsAreObjectsSplitByConnectivity) {
  // Two boxes in one unnamed object: two parts; in two objects sharing
  // vertex indices... each object its own part.
  const auto blocks = some_blocks();
  std::string text = obj_document(blocks, {"a", "b"});
  std::string unnamed;
  for (std::size_t p = 0, q; p < text.size(); p = q + 1) {
    q = text.find('\n', p);
    const std::string line = text.substr(p, q - p);
    if (line.rfind("o ", 0) != 0) unnamed += line + "\n";
  }
  const BlockFile one = parse_obj(unnamed, "one.obj");
  ASSERT_EQ(one.parts.size(), 2u);
  EXPECT_EQ(one.parts[0].name, "");
  expect_same(part_block(one, 1), blocks[1]);
  const BlockFile named = parse_obj("o pair\n" + unnamed, "pair.obj");
  ASSERT_EQ(named.parts.size(), 2u);
  EXPECT_EQ(named.parts[0].name, "pair_1");
  EXPECT_EQ(named.parts[1].name, "pair_2");
  EXPECT_EQ(named.parts[0].vertex_ids.front(), 1);  // the file's own numbering (OBJ from 1)
  // A material group inside an `o` object is not a new solid.
  std::string grouped = kTriangulatedBox;
  grouped.replace(grouped.find("f 5 6 7"), 0, "g box_stone_material\nusemtl stone\n");
  const BlockFile g = parse_obj(grouped, "grouped.obj");
  ASSERT_EQ(g.parts.size(), 1u);
  EXPECT_EQ(g.parts[0].name, "box");
  EXPECT_EQ(mass_properties(part_block(g, 0)).volume, 1.0);
  // Without `o`, each `g` is an object.
  const std::string tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -4 -2 -3\nf -4 -3 -1\nf -4 -1 -2\nf -3 -2 -1\n";
  const BlockFile two = parse_obj("g a\n" + tet + "g b\n" + tet, "g.obj");
  ASSERT_EQ(two.parts.size(), 2u);
  EXPECT_EQ(two.parts[0].name, "a");
  EXPECT_EQ(two.parts[1].name, "b");
  EXPECT_NEAR(mass_properties(part_block(two, 1)).volume, 1.0 / 6, 1e-16);
}

TEST(BlockFiles, OrientationIsRepaired) {
  // Every face reversed: inward; turned outside in.
  std::string inward = kTriangulatedBox;
  const BlockFile f = parse_obj(kTriangulatedBox, "box.obj");
  std::string flipped = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
  const char* faces[] = {"1 2 3 4", "8 7 6 5", "5 6 2 1", "6 7 3 2", "7 8 4 3", "8 5 1 4"};  // inward quads
  for (const char* q : faces) flipped += std::string("f ") + q + "\n";
  EXPECT_EQ(mass_properties(part_block(parse_obj(flipped, "in.obj"), 0)).volume, 1.0);
  // One face the wrong way round among right ones.
  std::string mixed = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                      "f 4 3 2 1\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 7 8 4 3\nf 4 1 5 8\n";
  // (f 7 8 4 3 runs the wrong way.) The block keeps the file's order.
  const std::vector<Vec3> corners = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                                     Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  expect_same(part_block(parse_obj(mixed, "mixed.obj"), 0),
              make_polyhedron(corners, {{3, 2, 1, 0}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}));
  // Triangulated, the same box is the hull of its corners.
  expect_same(part_block(f, 0), convex_hull(corners));
}

TEST(BlockFiles, OpenNonConvexAndNonManifoldPartsAreRefused) {
  const std::string box8 = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
  // Lid missing (line 9 would be the top).
  expect_message([&] { part_block(parse_obj(box8 + "f 4 3 2 1\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n", "open.obj"), 0); },
                 "open.obj: part 1: open: edge (5,6) belongs to one face (at line 10)");
  // A roof whose ridge dips into the block: vertex 9 below the top corners.
  const std::string dented = box8 + "v 0.5 0.5 0.8\n"
                                    "f 4 3 2 1\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
                                    "f 5 6 9\nf 6 7 9\nf 7 8 9\nf 8 5 9\n";
  expect_message([&] { part_block(parse_obj("o dent\n" + dented, "dent.obj"), 0); },
                 "dent.obj: part 1 \"dent\": not convex: vertex ");
  expect_message([&] { part_block(parse_obj("o dent\n" + dented, "dent.obj"), 0); }, "m outside the face at line");
  // A flat part.
  expect_message([&] { part_block(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 3 2 1\nf 2 4 3\nf 3 4 2\n", "flat.obj"), 0); },
                 "flat.obj: part 1: ");
}

TEST(BlockFiles, MalformedObjIsAClearError) {
  expect_message([] { parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "bad.obj"); },
                 "bad.obj:4: face refers to vertex 9, but 3 vertices");
  expect_message([] { parse_obj("v 0 0 0\nf 1 0 1\n", "bad.obj"); }, "bad.obj:2: face refers to vertex 0");
  expect_message([] { parse_obj("v 0 0 x\n", "bad.obj"); }, "bad.obj:1: vertex coordinate 'x' is not a number");
  expect_message([] { parse_obj("v 0 0 inf\n", "bad.obj"); }, "is not finite");
  expect_message([] { parse_obj("v 0 0\n", "bad.obj"); }, "bad.obj:1: a vertex needs x y z");
  expect_message([] { parse_obj("v 0 0 0\nf 1 1\n", "bad.obj"); }, "bad.obj:2: a face needs at least 3");
  expect_message([] { parse_obj("curv 0 1 2\n", "bad.obj"); }, "bad.obj:1: unsupported OBJ statement 'curv'");
  expect_message([] { parse_obj("v 0 0 0\n", "bad.obj"); }, "bad.obj: no faces");
}

std::string ply_box(const char* format, bool binary, bool big_endian) {
  const float v[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int f[6][4] = {{3, 2, 1, 0}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::string s = std::string("ply\nformat ") + format +
                  " 1.0\ncomment a unit box\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
                  "property uchar red\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n";
  const auto put = [&](const void* p, std::size_t n) {
    std::string b(static_cast<const char*>(p), n);
    if (big_endian) std::reverse(b.begin(), b.end());
    s += b;
  };
  for (const auto& x : v) {
    if (binary) {
      for (float c : x) put(&c, 4);
      const unsigned char red = 200;
      put(&red, 1);
    } else {
      s += std::to_string(x[0]) + " " + std::to_string(x[1]) + " " + std::to_string(x[2]) + " 200\n";
    }
  }
  for (const auto& q : f) {
    if (binary) {
      const unsigned char n = 4;
      put(&n, 1);
      for (int i : q) put(&i, 4);
    } else {
      s += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " +
           std::to_string(q[3]) + "\n";
    }
  }
  return s;
}

TEST(BlockFiles, PlyAsciiAndBinaryInBothByteOrders) {
  for (const auto& [format, binary, big] : {std::tuple{"ascii", false, false},
                                            std::tuple{"binary_little_endian", true, false},
                                            std::tuple{"binary_big_endian", true, true}}) {
    const BlockFile f = parse_ply(ply_box(format, binary, big), "box.ply");
    ASSERT_EQ(f.parts.size(), 1u) << format;
    const Polyhedron b = part_block(f, 0);
    EXPECT_EQ(mass_properties(b).volume, 1.0) << format;
    EXPECT_EQ(b.faces.size(), 6u);
  }
  expect_message([] { parse_ply("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n0\n", "bad.ply"); },
                 "the vertex element has no x, y, z");
  std::string many = ply_box("ascii", false, false);
  many.replace(many.find("element face 6"), 14, "element face 9000000000");
  expect_message([&] { parse_ply(many, "bad.ply"); }, "declares 9000000000 entries, more than the data holds");
  std::string out_of_range = ply_box("ascii", false, false);
  out_of_range.replace(out_of_range.rfind("4 3 0 4 7"), 9, "4 3 0 4 8");
  expect_message([&] { parse_ply(out_of_range, "bad.ply"); }, "face 5 refers to vertex 8, but the file has 8");
}

TEST(BlockFiles, PolydemVtuRoundTripIsBitForBit) {
  const auto blocks = some_blocks();
  VtkCellData data;
  data.add_ints("block_id", {0, 1}).add_ints("course", {3, -1}).add_ints("motion", {1, 0});
  const BlockFile f = parse_vtu(vtu_document(blocks, data), "blocks.vtu");
  ASSERT_EQ(f.parts.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) expect_same(part_block(f, i), blocks[i]);
  EXPECT_EQ(f.parts[0].course, 3);
  EXPECT_EQ(f.parts[0].motion, 1);
  EXPECT_EQ(f.parts[1].motion, 0);
  const std::string good = vtu_document(blocks);
  std::string bad = good;
  bad.replace(bad.find(">42 42<") == std::string::npos ? bad.find("42 42") : bad.find(">42 42<") + 1, 5, "42 10");
  expect_message([&] { parse_vtu(bad, "b.vtu"); }, "cell 1 has type 10: only polyhedral cells");
  std::string binary = good;
  binary.replace(binary.find("format=\"ascii\""), 14, "format=\"binary\"");
  expect_message([&] { parse_vtu(binary, "b.vtu"); }, "polydem reads ASCII .vtu data arrays");
}

// Prefixes of good files (several hundred lengths) are either read or refused
// with a BlockFileError: nothing else escapes, nothing crashes.
TEST(BlockFiles, EveryTruncationIsReadOrRefused) {
  const auto blocks = some_blocks();
  const std::string obj = obj_document(blocks, {"a", "b"});
  const std::string vtu = vtu_document(blocks);
  const std::string ply = ply_box("binary_little_endian", true, false);
  int refused = 0;
  for (const auto& [text, kind] : {std::pair{obj, 0}, std::pair{vtu, 1}, std::pair{ply, 2}}) {
    for (std::size_t n = 0; n < text.size(); n += 1 + n / 64) {
      const std::string cut = text.substr(0, n);
      try {
        const BlockFile f = kind == 0 ? parse_obj(cut, "t") : kind == 1 ? parse_vtu(cut, "t") : parse_ply(cut, "t");
        for (std::size_t i = 0; i < f.parts.size(); ++i) part_block(f, i);
      } catch (const BlockFileError&) {
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 100);
}

}  // namespace
}  // namespace polydem
