#include "io/vtk.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "tests/test_util.hpp"

namespace polydem {
namespace {

// ---- a minimal XML reader: enough to check the files are well formed and to
// pull out attributes and DataArray contents.
struct XmlNode {
  std::string name;
  std::map<std::string, std::string> attrs;
  std::string text;
  std::vector<std::unique_ptr<XmlNode>> children;

  const XmlNode* child(const std::string& n) const {
    for (const auto& c : children)
      if (c->name == n) return c.get();
    return nullptr;
  }
  std::vector<const XmlNode*> all(const std::string& n) const {
    std::vector<const XmlNode*> out;
    for (const auto& c : children)
      if (c->name == n) out.push_back(c.get());
    return out;
  }
};

std::string unescape(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '&') {
      out += s[i];
      continue;
    }
    const auto semi = s.find(';', i);
    const std::string ent = s.substr(i + 1, semi - i - 1);
    const std::map<std::string, char> table = {{"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
    const auto it = table.find(ent);
    if (semi == std::string::npos || it == table.end()) throw std::runtime_error("bad entity &" + ent);
    out += it->second;
    i = semi;
  }
  return out;
}

// Throws std::runtime_error on anything not well formed.
std::unique_ptr<XmlNode> parse_xml(const std::string& xml) {
  std::size_t i = 0;
  if (xml.rfind("<?xml", 0) == 0) i = xml.find("?>") + 2;
  auto root = std::make_unique<XmlNode>();
  root->name = "#document";
  std::vector<XmlNode*> stack = {root.get()};
  const auto is_space = [](char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; };
  while (i < xml.size()) {
    const auto lt = xml.find('<', i);
    stack.back()->text += xml.substr(i, lt == std::string::npos ? std::string::npos : lt - i);
    if (lt == std::string::npos) break;
    const auto gt = xml.find('>', lt);
    if (gt == std::string::npos) throw std::runtime_error("unterminated tag");
    std::string tag = xml.substr(lt + 1, gt - lt - 1);
    i = gt + 1;
    if (tag.empty()) throw std::runtime_error("empty tag");
    if (tag[0] == '/') {
      if (stack.size() < 2 || stack.back()->name != tag.substr(1))
        throw std::runtime_error("mismatched closing tag </" + tag.substr(1) + ">");
      stack.pop_back();
      continue;
    }
    const bool self_closing = tag.back() == '/';
    if (self_closing) tag.pop_back();
    auto node = std::make_unique<XmlNode>();
    std::size_t p = 0;
    while (p < tag.size() && !is_space(tag[p])) ++p;
    node->name = tag.substr(0, p);
    while (true) {
      while (p < tag.size() && is_space(tag[p])) ++p;
      if (p >= tag.size()) break;
      const auto eq = tag.find('=', p);
      if (eq == std::string::npos || eq + 1 >= tag.size() || tag[eq + 1] != '"')
        throw std::runtime_error("bad attribute in <" + node->name + ">");
      const auto close = tag.find('"', eq + 2);
      if (close == std::string::npos) throw std::runtime_error("unterminated attribute");
      const std::string key = tag.substr(p, eq - p);
      if (!node->attrs.emplace(key, unescape(tag.substr(eq + 2, close - eq - 2))).second)
        throw std::runtime_error("duplicate attribute " + key);
      p = close + 1;
    }
    XmlNode* raw = node.get();
    stack.back()->children.push_back(std::move(node));
    if (!self_closing) stack.push_back(raw);
  }
  if (stack.size() != 1) throw std::runtime_error("unclosed <" + stack.back()->name + ">");
  if (root->children.size() != 1) throw std::runtime_error("expected one root element");
  return root;
}

std::vector<double> numbers(const XmlNode& n) {
  std::istringstream in(n.text);
  std::vector<double> out;
  double x;
  while (in >> x) out.push_back(x);
  if (!in.eof()) throw std::runtime_error("non-numeric text in DataArray " + n.attrs.at("Name"));
  return out;
}

const XmlNode& array_named(const XmlNode& parent, const std::string& name) {
  for (const XmlNode* a : parent.all("DataArray"))
    if (a->attrs.at("Name") == name) return *a;
  throw std::runtime_error("no DataArray " + name);
}

Polyhedron cube(const Vec3& c, double h) {
  Polyhedron p;
  for (int k = 0; k < 8; ++k)
    p.vertices.push_back(c + h * Vec3((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1));
  // CCW from outside.
  p.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return p;
}

Polyhedron tetrahedron(const Vec3& o) {
  Polyhedron p;
  p.vertices = {o, o + Vec3(1, 0, 0), o + Vec3(0, 1, 0), o + Vec3(0, 0, 1)};
  p.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return p;
}

TEST(Vtk, VtuIsWellFormedWithConsistentPolyhedronCells) {
  test::ScratchDir dir("vtk");
  const std::vector<Polyhedron> blocks = {cube(Vec3(0, 0, 0.5), 0.5), tetrahedron(Vec3(2, 0, 0)),
                                          cube(Vec3(0.1, -0.2, 1.5), 0.25)};
  VtkCellData data;
  data.add_scalars("kinetic_energy", {1.5, 0.0, 1e-300})
      .add_vectors("velocity", {Vec3(1, 2, 3), Vec3::Zero(), Vec3(-0.1, 0.2, 1.0 / 3.0)})
      .add_ints("block_id", {0, 7, 2});
  const std::string file = dir.path("step_000001.vtu");
  write_vtu(file, blocks, data);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"step_000001.vtu"});

  const auto doc = parse_xml(test::read_text(file));
  const XmlNode& vtk = *doc->children.front();
  ASSERT_EQ(vtk.name, "VTKFile");
  EXPECT_EQ(vtk.attrs.at("type"), "UnstructuredGrid");
  const XmlNode* piece = vtk.child("UnstructuredGrid")->child("Piece");
  ASSERT_NE(piece, nullptr);
  EXPECT_EQ(piece->attrs.at("NumberOfPoints"), "20");
  EXPECT_EQ(piece->attrs.at("NumberOfCells"), "3");

  const auto points = numbers(array_named(*piece->child("Points"), "Points"));
  ASSERT_EQ(points.size(), 60u);
  std::size_t k = 0;
  for (const auto& b : blocks)
    for (const Vec3& v : b.vertices) {
      EXPECT_EQ(points[k], v.x());
      EXPECT_EQ(points[k + 1], v.y());
      EXPECT_EQ(points[k + 2], v.z());
      k += 3;
    }

  const XmlNode& cells = *piece->child("Cells");
  const auto conn = numbers(array_named(cells, "connectivity"));
  const auto offsets = numbers(array_named(cells, "offsets"));
  const auto types = numbers(array_named(cells, "types"));
  const auto faces = numbers(array_named(cells, "faces"));
  const auto faceoffsets = numbers(array_named(cells, "faceoffsets"));
  EXPECT_EQ(offsets, (std::vector<double>{8, 12, 20}));
  EXPECT_EQ(types, (std::vector<double>{42, 42, 42}));
  ASSERT_EQ(conn.size(), 20u);
  ASSERT_EQ(faceoffsets.size(), 3u);
  EXPECT_EQ(faceoffsets.back(), static_cast<double>(faces.size()));

  // Walk each cell's face stream and compare with the input faces.
  std::size_t pos = 0, first_point = 0;
  for (std::size_t c = 0; c < blocks.size(); ++c) {
    const auto& b = blocks[c];
    ASSERT_EQ(faces[pos++], static_cast<double>(b.faces.size()));
    for (const auto& f : b.faces) {
      ASSERT_EQ(faces[pos++], static_cast<double>(f.size()));
      for (int v : f) EXPECT_EQ(faces[pos++], static_cast<double>(first_point + static_cast<std::size_t>(v)));
    }
    EXPECT_EQ(static_cast<double>(pos), faceoffsets[c]) << "cell " << c;
    const std::size_t begin = c == 0 ? 0 : static_cast<std::size_t>(offsets[c - 1]);
    for (std::size_t i = begin; i < static_cast<std::size_t>(offsets[c]); ++i)
      EXPECT_EQ(conn[i], static_cast<double>(first_point + (i - begin)));
    first_point += b.vertices.size();
  }

  const XmlNode& cd = *piece->child("CellData");
  EXPECT_EQ(numbers(array_named(cd, "kinetic_energy")), (std::vector<double>{1.5, 0.0, 1e-300}));
  const auto vel = numbers(array_named(cd, "velocity"));
  ASSERT_EQ(vel.size(), 9u);
  EXPECT_EQ(vel[8], 1.0 / 3.0);  // full precision survives the text
  EXPECT_EQ(array_named(cd, "velocity").attrs.at("NumberOfComponents"), "3");
  EXPECT_EQ(numbers(array_named(cd, "block_id")), (std::vector<double>{0, 7, 2}));
  EXPECT_EQ(array_named(cd, "block_id").attrs.at("type"), "Int32");
}

TEST(Vtk, EmptySceneAndNamesAreEscaped) {
  VtkCellData data;
  data.add_scalars("a<b & \"c\"", {});
  const auto doc = parse_xml(vtu_document({}, data));
  const XmlNode* piece = doc->children.front()->child("UnstructuredGrid")->child("Piece");
  EXPECT_EQ(piece->attrs.at("NumberOfCells"), "0");
  EXPECT_EQ(array_named(*piece->child("CellData"), "a<b & \"c\"").attrs.at("type"), "Float64");
}

TEST(Vtk, RejectsInconsistentInput) {
  const std::vector<Polyhedron> blocks = {tetrahedron(Vec3::Zero())};
  VtkCellData wrong;
  wrong.add_scalars("s", {1.0, 2.0});
  EXPECT_THROW((void)vtu_document(blocks, wrong), std::invalid_argument);
  Polyhedron bad = tetrahedron(Vec3::Zero());
  bad.faces[0][1] = 9;
  EXPECT_THROW((void)vtu_document({bad}, {}), std::invalid_argument);
  test::ScratchDir dir("vtk");
  EXPECT_THROW(write_vtu(dir.path("x.vtu"), blocks, wrong), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Vtk, PvdListsSnapshotsWithTimes) {
  test::ScratchDir dir("vtk");
  const std::vector<PvdEntry> entries = {{0.0, "vtk/step_000000.vtu"}, {0.1, "vtk/step_000100.vtu"},
                                         {1.0 / 3.0, "vtk/a&b.vtu"}};
  write_pvd(dir.path("run.pvd"), entries);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"run.pvd"});
  const auto doc = parse_xml(test::read_text(dir.path("run.pvd")));
  const XmlNode& vtk = *doc->children.front();
  EXPECT_EQ(vtk.attrs.at("type"), "Collection");
  const auto sets = vtk.child("Collection")->all("DataSet");
  ASSERT_EQ(sets.size(), 3u);
  for (std::size_t i = 0; i < sets.size(); ++i) {
    EXPECT_EQ(std::stod(sets[i]->attrs.at("timestep")), entries[i].time);
    EXPECT_EQ(sets[i]->attrs.at("file"), entries[i].file);
  }
}

// Optional cross-check with the real VTK reader when python3 has `vtk`.
TEST(Vtk, ReadableByVtkWhenAvailable) {
  if (std::system("python3 -c 'import vtk' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3 module 'vtk' not installed; the XML checks above cover the format";
  test::ScratchDir dir("vtk");
  const std::string file = dir.path("c.vtu");
  write_vtu(file, {cube(Vec3::Zero(), 1.0), tetrahedron(Vec3(3, 0, 0))});
  const std::string out = dir.path("out.txt");
  const std::string cmd = "python3 -c \"import vtk; r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName('" +
                          file + "'); r.Update(); g = r.GetOutput(); print(g.GetNumberOfCells(), "
                                 "g.GetNumberOfPoints(), g.GetCellType(0))\" > '" +
                          out + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(test::read_text(out), "2 12 42\n");
}

}  // namespace
}  // namespace polydem
