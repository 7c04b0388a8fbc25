// Mesh files to parts, parts to blocks (io/block_files.hpp). Every count and
// index read from a file is checked before it is used: sizes against what
// is left of the file, indices against what was declared, so that a broken
// or hostile file is a BlockFileError and never a crash or a huge
// allocation (fuzz/fuzz_block_file.cpp holds the readers to that).
#include "io/block_files.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>

#include "core/number_text.hpp"
#include "io/atomic_file.hpp"

namespace polydem {

namespace {

[[noreturn]] void fail_at(const std::string& path, long long line, const std::string& what) {
  std::string m = path;
  if (line > 0) m.append(":").append(std::to_string(line));
  m.append(": ").append(what);
  throw BlockFileError(m);
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

// Whitespace-separated words of one line.
std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::optional<double> to_double(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

std::optional<long long> to_integer(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  long long v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

std::string quote_word(std::string_view s) {
  std::string q = "'";
  q.append(s.substr(0, 40));
  if (s.size() > 40) q.append("...");
  q.append("'");
  return q;
}

// ------------------------------------------------------------------ parts

// A face as read: global vertex indices (0-based) and where it is.
struct RawFace {
  std::vector<long long> v;
  std::string where;
};

// Splits the faces of one object into connected parts (faces sharing a
// vertex), each with its vertices renumbered in file order.
void add_parts(BlockFile& out, const std::string& name, const std::vector<RawFace>& faces,
               const std::vector<Vec3>& vertices, long long id_base) {
  if (faces.empty()) return;
  // Union-find over faces through their vertices.
  std::vector<std::size_t> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::map<long long, std::size_t> first_face;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (long long v : faces[f].v) {
      const auto [it, inserted] = first_face.emplace(v, f);
      if (!inserted) {
        const std::size_t a = find(it->second), b = find(f);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
    }
  std::map<std::size_t, std::vector<std::size_t>> groups;  // root -> faces, roots in order of first face
  for (std::size_t f = 0; f < faces.size(); ++f) groups[find(f)].push_back(f);
  int k = 0;
  for (const auto& [root, members] : groups) {
    FilePart p;
    p.name = name;
    if (groups.size() > 1 && !name.empty()) p.name.append("_").append(std::to_string(++k));
    std::vector<long long> ids;
    for (std::size_t f : members) ids.insert(ids.end(), faces[f].v.begin(), faces[f].v.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::map<long long, int> local;
    for (long long id : ids) {
      local[id] = static_cast<int>(p.vertices.size());
      p.vertices.push_back(vertices[static_cast<std::size_t>(id)]);
      p.vertex_ids.push_back(id + id_base);
    }
    for (std::size_t f : members) {
      std::vector<int> loop;
      for (long long v : faces[f].v) loop.push_back(local[v]);
      p.faces.push_back(std::move(loop));
      p.face_where.push_back(faces[f].where);
    }
    out.parts.push_back(std::move(p));
  }
}

// ------------------------------------------------------------------- OBJ

}  // namespace

BlockFile parse_obj(std::string_view text, const std::string& path) {
  BlockFile out;
  out.path = path;
  out.format = "OBJ";
  std::vector<Vec3> vertices;
  struct Object {
    std::string name;
    std::vector<RawFace> faces;
    bool by_o = false;  // started by `o` (else by `g`, or the file's start)
  };
  std::vector<Object> objects(1);
  bool any_o = false;
  long long line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    const auto w = words(line);
    if (w.empty()) continue;
    const std::string_view key = w[0];
    if (key == "v") {
      if (w.size() < 4 || w.size() > 7)
        fail_at(path, line_no, "a vertex needs x y z (got " + std::to_string(w.size() - 1) + " numbers)");
      Vec3 x;
      for (int i = 0; i < 3; ++i) {
        const auto v = to_double(w[1 + i]);
        if (!v) fail_at(path, line_no, "vertex coordinate " + quote_word(w[1 + i]) + " is not a number");
        if (!std::isfinite(*v)) fail_at(path, line_no, "vertex coordinate " + quote_word(w[1 + i]) + " is not finite");
        x[i] = *v;
      }
      vertices.push_back(x);
    } else if (key == "f") {
      if (w.size() < 4) fail_at(path, line_no, "a face needs at least 3 vertices (got " + std::to_string(w.size() - 1) + ")");
      RawFace f;
      f.where = "line " + std::to_string(line_no);
      for (std::size_t i = 1; i < w.size(); ++i) {
        const std::string_view ref = w[i].substr(0, w[i].find('/'));
        const auto idx = to_integer(ref);
        if (!idx) fail_at(path, line_no, "face vertex " + quote_word(w[i]) + " is not an index");
        const long long n = static_cast<long long>(vertices.size());
        long long v = *idx > 0 ? *idx - 1 : n + *idx;  // negative: counted back from the last vertex so far
        if (*idx == 0 || v < 0 || v >= n)
          fail_at(path, line_no,
                  "face refers to vertex " + std::to_string(*idx) + ", but " + std::to_string(n) +
                      " vertices are defined before this line (OBJ counts from 1)");
        f.v.push_back(v);
      }
      objects.back().faces.push_back(std::move(f));
    } else if (key == "o" || key == "g") {
      std::string name;
      for (std::size_t i = 1; i < w.size(); ++i) {
        if (i > 1) name += ' ';
        name.append(w[i]);
      }
      objects.push_back({name, {}, key == "o"});
      any_o = any_o || key == "o";
    } else if (key == "vt" || key == "vn" || key == "vp" || key == "s" || key == "usemtl" || key == "mtllib" ||
               key == "l" || key == "p") {
      // texture, normals, smoothing, materials, lines, points: not geometry of a solid
    } else {
      fail_at(path, line_no,
              "unsupported OBJ statement " + quote_word(key) +
                  " (polydem reads v, f, o, g and skips vt, vn, vp, s, usemtl, mtllib, l, p)");
    }
  }
  // With `o` objects in the file, a `g` inside one is a group of its faces
  // (a material, a smoothing set), not a new solid: its faces go to the
  // object. Without any `o`, each `g` is an object. Objects of the same name
  // stay separate objects.
  std::vector<Object> solids;
  for (Object& o : objects) {
    if (any_o && !o.by_o && !solids.empty()) {
      auto& into = solids.back().faces;
      into.insert(into.end(), o.faces.begin(), o.faces.end());
    } else {
      solids.push_back(std::move(o));
    }
  }
  for (const Object& o : solids) add_parts(out, o.name, o.faces, vertices, 1);
  if (out.parts.empty()) fail_at(path, 0, "no faces: an OBJ of blocks needs f lines");
  return out;
}

// ------------------------------------------------------------------- PLY

namespace {

enum class PlyType { i8, u8, i16, u16, i32, u32, f32, f64 };

std::optional<PlyType> ply_type(std::string_view s) {
  if (s == "char" || s == "int8") return PlyType::i8;
  if (s == "uchar" || s == "uint8") return PlyType::u8;
  if (s == "short" || s == "int16") return PlyType::i16;
  if (s == "ushort" || s == "uint16") return PlyType::u16;
  if (s == "int" || s == "int32") return PlyType::i32;
  if (s == "uint" || s == "uint32") return PlyType::u32;
  if (s == "float" || s == "float32") return PlyType::f32;
  if (s == "double" || s == "float64") return PlyType::f64;
  return std::nullopt;
}

std::size_t ply_size(PlyType t) {
  switch (t) {
    case PlyType::i8: case PlyType::u8: return 1;
    case PlyType::i16: case PlyType::u16: return 2;
    case PlyType::i32: case PlyType::u32: case PlyType::f32: return 4;
    case PlyType::f64: return 8;
  }
  return 1;
}

struct PlyProperty {
  std::string name;
  bool list = false;
  PlyType count_type = PlyType::u8;
  PlyType type = PlyType::f32;
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

// Reads values one by one from the body, ASCII or binary.
class PlyBody {
 public:
  PlyBody(std::string_view body, int encoding, const std::string& path, long long header_lines)
      : body_(body), encoding_(encoding), path_(path), line_(header_lines + 1) {}

  double value(PlyType t) {
    if (encoding_ == 0) {
      const std::string_view w = word();
      if (t == PlyType::f32 || t == PlyType::f64) {
        const auto v = to_double(w);
        if (!v) fail("expected a number, got " + quote_word(w));
        return *v;
      }
      const auto v = to_integer(w);
      if (!v) fail("expected an integer, got " + quote_word(w));
      return static_cast<double>(*v);
    }
    const std::size_t n = ply_size(t);
    if (pos_ + n > body_.size()) fail("the file ends inside the data (declared counts exceed it)");
    unsigned char b[8];
    std::memcpy(b, body_.data() + pos_, n);
    pos_ += n;
    const bool swap = (encoding_ == 1) != (std::endian::native == std::endian::little);
    if (swap) std::reverse(b, b + n);
    switch (t) {
      case PlyType::i8: { std::int8_t x; std::memcpy(&x, b, 1); return x; }
      case PlyType::u8: { std::uint8_t x; std::memcpy(&x, b, 1); return x; }
      case PlyType::i16: { std::int16_t x; std::memcpy(&x, b, 2); return x; }
      case PlyType::u16: { std::uint16_t x; std::memcpy(&x, b, 2); return x; }
      case PlyType::i32: { std::int32_t x; std::memcpy(&x, b, 4); return x; }
      case PlyType::u32: { std::uint32_t x; std::memcpy(&x, b, 4); return x; }
      case PlyType::f32: { float x; std::memcpy(&x, b, 4); return x; }
      case PlyType::f64: { double x; std::memcpy(&x, b, 8); return x; }
    }
    return 0;
  }

  // At most how many more values of the smallest size the body can hold.
  std::size_t left() const { return body_.size() - std::min(pos_, body_.size()); }
  long long line() const { return encoding_ == 0 ? line_ : 0; }
  [[noreturn]] void fail(const std::string& what) const {
    fail_at(path_, line(), encoding_ == 0 ? what : what + " (at byte " + std::to_string(pos_) + " of the data)");
  }

 private:
  std::string_view word() {
    while (pos_ < body_.size() && is_space(body_[pos_])) {
      if (body_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= body_.size()) fail("the file ends inside the data (declared counts exceed it)");
    const std::size_t start = pos_;
    while (pos_ < body_.size() && !is_space(body_[pos_])) ++pos_;
    return body_.substr(start, pos_ - start);
  }

  std::string_view body_;
  int encoding_;  // 0 ascii, 1 little endian, 2 big endian
  const std::string& path_;
  std::size_t pos_ = 0;
  long long line_;
};

}  // namespace

BlockFile parse_ply(std::string_view bytes, const std::string& path) {
  BlockFile out;
  out.path = path;
  out.format = "PLY";
  std::vector<PlyElement> elements;
  int encoding = -1;
  long long line_no = 0;
  std::size_t pos = 0;
  bool ended = false;
  while (pos < bytes.size()) {
    const std::size_t end = std::min(bytes.find('\n', pos), bytes.size());
    const std::string_view line = bytes.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    const auto w = words(line);
    if (line_no == 1) {
      if (w.size() != 1 || w[0] != "ply") fail_at(path, 1, "not a PLY file (the first line must be 'ply')");
      continue;
    }
    if (w.empty()) continue;
    if (w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "format") {
      if (w.size() != 3) fail_at(path, line_no, "format line must be 'format ENCODING 1.0'");
      if (w[1] == "ascii") encoding = 0;
      else if (w[1] == "binary_little_endian") encoding = 1;
      else if (w[1] == "binary_big_endian") encoding = 2;
      else fail_at(path, line_no, "unknown PLY format " + quote_word(w[1]));
    } else if (w[0] == "element") {
      if (w.size() != 3) fail_at(path, line_no, "element line must be 'element NAME COUNT'");
      const auto n = to_integer(w[2]);
      if (!n || *n < 0) fail_at(path, line_no, "element count " + quote_word(w[2]) + " is not a count");
      elements.push_back({std::string(w[1]), *n, {}});
    } else if (w[0] == "property") {
      if (elements.empty()) fail_at(path, line_no, "property before any element");
      PlyProperty p;
      if (w.size() == 5 && w[1] == "list") {
        const auto ct = ply_type(w[2]), t = ply_type(w[3]);
        if (!ct || !t) fail_at(path, line_no, "unknown property type in " + quote_word(line));
        if (*ct == PlyType::f32 || *ct == PlyType::f64) fail_at(path, line_no, "a list count must be an integer type");
        p = {std::string(w[4]), true, *ct, *t};
      } else if (w.size() == 3) {
        const auto t = ply_type(w[1]);
        if (!t) fail_at(path, line_no, "unknown property type " + quote_word(w[1]));
        p = {std::string(w[2]), false, PlyType::u8, *t};
      } else {
        fail_at(path, line_no, "property line must be 'property TYPE NAME' or 'property list CTYPE TYPE NAME'");
      }
      elements.back().properties.push_back(p);
    } else if (w[0] == "end_header") {
      ended = true;
      break;
    } else {
      fail_at(path, line_no, "unknown PLY header line " + quote_word(line));
    }
  }
  if (line_no == 0) fail_at(path, 0, "empty file");
  if (!ended) fail_at(path, line_no, "no end_header");
  if (encoding < 0) fail_at(path, line_no, "no format line in the header");

  PlyBody body(bytes.substr(std::min(pos, bytes.size())), encoding, path, line_no);
  std::vector<Vec3> vertices;
  std::vector<RawFace> faces;
  bool have_vertices = false, have_faces = false;
  for (const PlyElement& e : elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    int ix = -1, iy = -1, iz = -1, ilist = -1;
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const auto& p = e.properties[i];
      if (is_vertex && !p.list && p.name == "x") ix = static_cast<int>(i);
      if (is_vertex && !p.list && p.name == "y") iy = static_cast<int>(i);
      if (is_vertex && !p.list && p.name == "z") iz = static_cast<int>(i);
      if (is_face && p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) ilist = static_cast<int>(i);
    }
    if (is_vertex && (ix < 0 || iy < 0 || iz < 0)) fail_at(path, 0, "the vertex element has no x, y, z properties");
    if (is_face && ilist < 0) fail_at(path, 0, "the face element has no vertex_indices list");
    // Every instance takes at least one byte (binary) or two (ASCII) — if
    // it has a property: an element without any would let a header line ask
    // for any number of empty instances (a hostile file's endless loop).
    if (e.properties.empty() && e.count > 0)
      fail_at(path, 0, "element '" + e.name + "' has " + std::to_string(e.count) + " entries but no properties");
    if (static_cast<unsigned long long>(e.count) > body.left())
      body.fail("element '" + e.name + "' declares " + std::to_string(e.count) + " entries, more than the data holds");
    have_vertices = have_vertices || is_vertex;
    have_faces = have_faces || is_face;
    for (long long k = 0; k < e.count; ++k) {
      Vec3 x = Vec3::Zero();
      RawFace f;
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const auto& p = e.properties[i];
        if (!p.list) {
          const double v = body.value(p.type);
          if (is_vertex && static_cast<int>(i) == ix) x.x() = v;
          if (is_vertex && static_cast<int>(i) == iy) x.y() = v;
          if (is_vertex && static_cast<int>(i) == iz) x.z() = v;
          continue;
        }
        const double n = body.value(p.count_type);
        if (n < 0 || n > static_cast<double>(body.left())) body.fail("a list length " + shortest_text(n) + " is impossible");
        const bool wanted = is_face && static_cast<int>(i) == ilist;
        if (wanted && n < 3) body.fail("face " + std::to_string(k) + " has " + shortest_text(n) + " vertices (need 3)");
        for (long long j = 0; j < static_cast<long long>(n); ++j) {
          const double v = body.value(p.type);
          if (wanted) {
            if (!(v >= 0 && v == std::floor(v) && v < 9e15)) body.fail("face " + std::to_string(k) + " has a bad vertex index " + shortest_text(v));
            f.v.push_back(static_cast<long long>(v));
          }
        }
      }
      if (is_vertex) {
        if (!x.allFinite()) body.fail("vertex " + std::to_string(k) + " is not finite");
        vertices.push_back(x);
      }
      if (is_face) {
        f.where = "face " + std::to_string(k);
        faces.push_back(std::move(f));
      }
    }
  }
  if (!have_vertices || !have_faces) fail_at(path, 0, "a PLY of blocks needs a vertex and a face element");
  for (std::size_t k = 0; k < faces.size(); ++k)
    for (long long v : faces[k].v)
      if (v >= static_cast<long long>(vertices.size()))
        fail_at(path, 0, "face " + std::to_string(k) + " refers to vertex " + std::to_string(v) + ", but the file has " +
                             std::to_string(vertices.size()) + " (PLY counts from 0)");
  add_parts(out, "", faces, vertices, 0);
  if (out.parts.empty()) fail_at(path, 0, "no faces");
  return out;
}

// ------------------------------------------------------------------- VTU

namespace {

// The value of attribute `name` in the tag text, or nullopt.
std::optional<std::string_view> attribute(std::string_view tag, std::string_view name) {
  std::size_t at = 0;
  while ((at = tag.find(name, at)) != std::string_view::npos) {
    const bool word_start = at > 0 && is_space(tag[at - 1]);
    std::size_t p = at + name.size();
    while (p < tag.size() && is_space(tag[p])) ++p;
    if (word_start && p < tag.size() && tag[p] == '=') {
      ++p;
      while (p < tag.size() && is_space(tag[p])) ++p;
      if (p < tag.size() && (tag[p] == '"' || tag[p] == '\'')) {
        const char q = tag[p];
        const std::size_t close = tag.find(q, p + 1);
        if (close == std::string_view::npos) return std::nullopt;
        return tag.substr(p + 1, close - p - 1);
      }
      return std::nullopt;
    }
    at += name.size();
  }
  return std::nullopt;
}

struct VtuArray {
  std::string name;
  std::string_view tag;
  std::string_view content;
  std::size_t offset = 0;  // in the file, for line numbers
};

long long line_of(std::string_view text, std::size_t offset) {
  return 1 + std::count(text.begin(), text.begin() + static_cast<long>(std::min(offset, text.size())), '\n');
}

std::vector<double> numbers_of(std::string_view text, const VtuArray& a, const std::string& path) {
  const auto fmt = attribute(a.tag, "format");
  if (fmt && *fmt != "ascii")
    fail_at(path, line_of(text, a.offset),
            "data array '" + a.name + "' is " + std::string(*fmt) +
                ": polydem reads ASCII .vtu data arrays (format=\"ascii\", as it writes them)");
  std::vector<double> out;
  std::size_t i = 0;
  const std::string_view c = a.content;
  while (i < c.size()) {
    while (i < c.size() && is_space(c[i])) ++i;
    const std::size_t start = i;
    while (i < c.size() && !is_space(c[i])) ++i;
    if (i == start) break;
    const auto v = to_double(c.substr(start, i - start));
    if (!v) fail_at(path, line_of(text, a.offset), "data array '" + a.name + "' holds " + quote_word(c.substr(start, i - start)));
    out.push_back(*v);
  }
  return out;
}

std::vector<long long> integers_of(std::string_view text, const VtuArray& a, const std::string& path) {
  std::vector<long long> out;
  for (double v : numbers_of(text, a, path)) {
    if (!(v == std::floor(v) && std::abs(v) < 9e15))
      fail_at(path, line_of(text, a.offset), "data array '" + a.name + "' holds " + shortest_text(v) + ", not an integer");
    out.push_back(static_cast<long long>(v));
  }
  return out;
}

}  // namespace

BlockFile parse_vtu(std::string_view text, const std::string& path) {
  BlockFile out;
  out.path = path;
  out.format = "VTU";
  if (text.find("<VTKFile") == std::string_view::npos || text.find("UnstructuredGrid") == std::string_view::npos)
    fail_at(path, 0, "not a VTK XML unstructured grid (.vtu): no <VTKFile type=\"UnstructuredGrid\">");
  if (text.find("<AppendedData") != std::string_view::npos)
    fail_at(path, line_of(text, text.find("<AppendedData")),
            "appended (binary) data: polydem reads ASCII .vtu data arrays (as it writes them)");
  const std::size_t piece = text.find("<Piece");
  if (piece == std::string_view::npos) fail_at(path, 0, "no <Piece>");
  if (text.find("<Piece", piece + 1) != std::string_view::npos)
    fail_at(path, line_of(text, text.find("<Piece", piece + 1)), "more than one <Piece>: polydem reads one");
  // Every DataArray, with the section (Points, Cells, CellData, ...) it is in.
  std::vector<VtuArray> points, cells, cell_data;
  std::size_t at = piece;
  while ((at = text.find("<DataArray", at)) != std::string_view::npos) {
    const std::size_t tag_end = text.find('>', at);
    if (tag_end == std::string_view::npos) fail_at(path, line_of(text, at), "unterminated <DataArray");
    VtuArray a;
    a.tag = text.substr(at, tag_end - at);
    a.offset = at;
    a.name = std::string(attribute(a.tag, "Name").value_or(""));
    if (a.tag.back() == '/') {
      a.content = {};
      at = tag_end + 1;
    } else {
      const std::size_t close = text.find("</DataArray>", tag_end);
      if (close == std::string_view::npos) fail_at(path, line_of(text, at), "no </DataArray> for '" + a.name + "'");
      a.content = text.substr(tag_end + 1, close - tag_end - 1);
      at = close;
    }
    const std::string_view before = text.substr(piece, a.offset - piece);
    const auto last = [&](std::string_view open, std::string_view close) {
      const std::size_t o = before.rfind(open);
      const std::size_t c = before.rfind(close);
      return o != std::string_view::npos && (c == std::string_view::npos || c < o);
    };
    if (last("<Points", "</Points>")) points.push_back(a);
    else if (last("<Cells", "</Cells>")) cells.push_back(a);
    else if (last("<CellData", "</CellData>")) cell_data.push_back(a);
  }
  if (points.size() != 1) fail_at(path, 0, "<Points> must hold one data array (got " + std::to_string(points.size()) + ")");
  const auto cell_array = [&](const std::string& name) -> const VtuArray* {
    for (const auto& a : cells)
      if (a.name == name) return &a;
    return nullptr;
  };
  for (const char* need : {"connectivity", "offsets", "types"})
    if (!cell_array(need)) fail_at(path, 0, std::string("<Cells> has no '") + need + "' array");
  if (!cell_array("faces") || !cell_array("faceoffsets"))
    fail_at(path, 0,
            "<Cells> has no 'faces' and 'faceoffsets' arrays: polydem reads polyhedral cells (VTK_POLYHEDRON, 42) "
            "in that layout (as it writes them; VTK 9.4's face_connectivity layout is not read)");

  const std::vector<double> xyz = numbers_of(text, points[0], path);
  if (const auto nc = attribute(points[0].tag, "NumberOfComponents"); !nc || *nc != "3")
    fail_at(path, line_of(text, points[0].offset), "points must have NumberOfComponents=\"3\"");
  if (xyz.size() % 3) fail_at(path, line_of(text, points[0].offset), "the points' coordinates are not a multiple of 3");
  std::vector<Vec3> vertices;
  for (std::size_t i = 0; i < xyz.size(); i += 3) {
    vertices.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
    if (!vertices.back().allFinite())
      fail_at(path, line_of(text, points[0].offset), "point " + std::to_string(i / 3) + " is not finite");
  }
  const auto types = integers_of(text, *cell_array("types"), path);
  const auto faces = integers_of(text, *cell_array("faces"), path);
  const auto faceoffsets = integers_of(text, *cell_array("faceoffsets"), path);
  const long long ncell = static_cast<long long>(types.size());
  if (static_cast<long long>(faceoffsets.size()) != ncell)
    fail_at(path, line_of(text, cell_array("faceoffsets")->offset),
            "'faceoffsets' has " + std::to_string(faceoffsets.size()) + " entries for " + std::to_string(ncell) + " cells");
  const long long np = static_cast<long long>(vertices.size());
  std::vector<std::vector<long long>> cell_ints(2);
  const char* data_names[2] = {"course", "motion"};
  for (int k = 0; k < 2; ++k)
    for (const auto& a : cell_data)
      if (a.name == data_names[k]) {
        cell_ints[k] = integers_of(text, a, path);
        if (static_cast<long long>(cell_ints[k].size()) != ncell)
          fail_at(path, line_of(text, a.offset), "cell data '" + a.name + "' has " + std::to_string(cell_ints[k].size()) +
                                                     " values for " + std::to_string(ncell) + " cells");
      }
  long long start = 0;
  for (long long c = 0; c < ncell; ++c) {
    const std::string cell = "cell " + std::to_string(c);
    if (types[c] != 42)
      fail_at(path, 0, cell + " has type " + std::to_string(types[c]) + ": only polyhedral cells (VTK_POLYHEDRON = 42) are read");
    const long long stop = faceoffsets[c];
    if (stop < start || stop > static_cast<long long>(faces.size()))
      fail_at(path, 0, cell + ": faceoffsets " + std::to_string(stop) + " out of order or past the faces array");
    long long i = start;
    const auto next = [&]() {
      if (i >= stop) fail_at(path, 0, cell + ": its face stream ends early (counts do not match faceoffsets)");
      return faces[static_cast<std::size_t>(i++)];
    };
    const long long nf = next();
    if (nf < 4 || nf > stop - start) fail_at(path, 0, cell + " declares " + std::to_string(nf) + " faces");
    std::vector<RawFace> raw;
    for (long long f = 0; f < nf; ++f) {
      RawFace face;
      face.where = cell + " face " + std::to_string(f);
      const long long n = next();
      if (n < 3 || n > stop - i) fail_at(path, 0, face.where + " declares " + std::to_string(n) + " points");
      for (long long k = 0; k < n; ++k) {
        const long long v = next();
        if (v < 0 || v >= np)
          fail_at(path, 0, face.where + " refers to point " + std::to_string(v) + ", but the file has " + std::to_string(np));
        face.v.push_back(v);
      }
      raw.push_back(std::move(face));
    }
    if (i != stop) fail_at(path, 0, cell + ": " + std::to_string(stop - i) + " values left over in its face stream");
    start = stop;
    // One cell, one part (not split by connectivity: a cell is one solid).
    BlockFile one;
    add_parts(one, "", raw, vertices, 0);
    if (one.parts.size() != 1) fail_at(path, 0, cell + ": its faces form " + std::to_string(one.parts.size()) + " separate surfaces");
    FilePart p = std::move(one.parts[0]);
    if (!cell_ints[0].empty()) p.course = static_cast<int>(std::clamp<long long>(cell_ints[0][c], -1, 1000000));
    if (!cell_ints[1].empty()) {
      if (cell_ints[1][c] < 0 || cell_ints[1][c] > 2)
        fail_at(path, 0, cell + ": cell data 'motion' is " + std::to_string(cell_ints[1][c]) + " (0 free, 1 fixed, 2 kinematic)");
      p.motion = static_cast<int>(cell_ints[1][c]);
    }
    out.parts.push_back(std::move(p));
  }
  if (out.parts.empty()) fail_at(path, 0, "no cells");
  return out;
}

BlockFile read_block_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".obj" && ext != ".ply" && ext != ".vtu")
    throw BlockFileError(path + ": unknown block file format " + quote_word(ext) + " (.obj, .ply or .vtu)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw BlockFileError(path + ": cannot open");
  std::ostringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  if (ext == ".obj") return parse_obj(text, path);
  if (ext == ".ply") return parse_ply(text, path);
  return parse_vtu(text, path);
}

std::string part_label(const BlockFile& file, std::size_t index) {
  std::string m = file.path;
  m.append(": part ").append(std::to_string(index + 1));
  if (!file.parts[index].name.empty()) m.append(" \"").append(file.parts[index].name).append("\"");
  return m;
}

// ----------------------------------------------------------- part checks

Polyhedron part_block(const BlockFile& file, std::size_t index, double convex_rel_tol) {
  const FilePart& part = file.parts[index];
  const auto fail = [&](const std::string& why) -> void {
    std::string m = part_label(file, index);
    m.append(": ").append(why);
    throw BlockFileError(m);
  };
  const auto vid = [&](int v) { return std::to_string(part.vertex_ids[static_cast<std::size_t>(v)]); };
  const std::size_t nf = part.faces.size();
  if (part.vertices.size() < 4 || nf < 4)
    fail("has " + std::to_string(part.vertices.size()) + " vertices and " + std::to_string(nf) +
         " faces: a closed solid needs at least 4 of each");
  for (std::size_t f = 0; f < nf; ++f) {
    // Sorted copy: a face of n corners costs n log n, not n² (a hostile file
    // may have one face of a million corners).
    std::vector<int> sorted = part.faces[f];
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if (twice != sorted.end()) fail("face at " + part.face_where[f] + " visits vertex " + vid(*twice) + " twice");
  }
  // Closed: every undirected edge in exactly two faces.
  std::map<std::pair<int, int>, std::vector<std::size_t>> edge_faces;
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& loop = part.faces[f];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  }
  for (const auto& [e, fs] : edge_faces) {
    const std::string edge = "edge (" + vid(e.first) + "," + vid(e.second) + ")";
    if (fs.size() == 1) fail("open: " + edge + " belongs to one face (at " + part.face_where[fs[0]] + ")");
    if (fs.size() > 2) fail("not a simple solid: " + edge + " belongs to " + std::to_string(fs.size()) + " faces");
    if (fs[0] == fs[1]) fail(edge + " appears twice in the face at " + part.face_where[fs[0]]);
  }
  // Orientable: turn faces to agree with the first, face by face across
  // edges (a neighbour must run a shared edge the other way).
  std::vector<std::vector<int>> faces = part.faces;
  std::vector<int> state(nf, 0);  // 0 unvisited, 1 kept, -1 flipped
  const auto runs = [&](std::size_t f, int a, int b) {
    const auto& loop = faces[f];
    for (std::size_t k = 0; k < loop.size(); ++k)
      if (loop[k] == a && loop[(k + 1) % loop.size()] == b) return true;
    return false;
  };
  std::vector<std::size_t> stack{0};
  state[0] = 1;
  std::size_t reached = 1;
  while (!stack.empty()) {
    const std::size_t f = stack.back();
    stack.pop_back();
    const auto loop = faces[f];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      const auto& fs = edge_faces[{std::min(a, b), std::max(a, b)}];
      const std::size_t g = fs[0] == f ? fs[1] : fs[0];
      if (state[g] == 0) {
        if (runs(g, a, b)) std::reverse(faces[g].begin(), faces[g].end());
        state[g] = 1;
        ++reached;
        stack.push_back(g);
      } else if (runs(g, a, b)) {
        fail("not orientable: the faces at " + part.face_where[f] + " and " + part.face_where[g] +
             " cannot agree on the direction of edge (" + vid(a) + "," + vid(b) + ")");
      }
    }
  }
  if (reached != nf) fail("its faces form more than one closed surface");
  // Outward: the signed volume (divergence theorem, fan triangles) positive.
  double volume6 = 0;
  for (const auto& loop : faces)
    for (std::size_t k = 1; k + 1 < loop.size(); ++k)
      volume6 += part.vertices[loop[0]].dot(part.vertices[loop[k]].cross(part.vertices[loop[k + 1]]));
  if (volume6 < 0)
    for (auto& loop : faces) std::reverse(loop.begin(), loop.end());
  const double size = bounding_box_diagonal(part.vertices);
  if (!(std::abs(volume6) / 6 > 1e-12 * size * size * size)) fail("encloses no volume (flat)");
  // Convex: no vertex in front of a face's plane; faces planar.
  const double tol = convex_rel_tol * size;
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& loop = faces[f];
    Vec3 n = Vec3::Zero();
    for (std::size_t k = 0; k < loop.size(); ++k)
      n += part.vertices[loop[k]].cross(part.vertices[loop[(k + 1) % loop.size()]]);
    if (!(n.norm() > 0)) fail("the face at " + part.face_where[f] + " has no area");
    n.normalize();
    double d = 0;
    for (int v : loop) d += n.dot(part.vertices[v]);
    d /= static_cast<double>(loop.size());
    for (int v : loop)
      if (std::abs(n.dot(part.vertices[v]) - d) > tol)
        fail("the face at " + part.face_where[f] + " is not planar: vertex " + vid(v) + " lies " +
             shortest_text(std::abs(n.dot(part.vertices[v]) - d)) + " m off its plane");
    for (std::size_t v = 0; v < part.vertices.size(); ++v) {
      const double out = n.dot(part.vertices[v]) - d;
      if (out > tol)
        fail("not convex: vertex " + vid(static_cast<int>(v)) + " lies " + shortest_text(out) +
             " m outside the face at " + part.face_where[f]);
    }
  }
  // As written, when the faces already make a valid block (planar, maximal
  // faces: what polydem writes): the same vertices and faces in the same
  // order, so the same block bit for bit, whatever built it.
  try {
    return make_polyhedron(part.vertices, faces);
  } catch (const GeometryError&) {
    // e.g. triangulated faces (coplanar neighbours): the hull merges them
  }
  Polyhedron block;
  try {
    block = convex_hull(part.vertices);
  } catch (const GeometryError& e) {
    fail(std::string("cannot be a block: ") + e.what());
  }
  const double hull_volume = mass_properties(block).volume;
  if (std::abs(hull_volume - std::abs(volume6) / 6) > 1e-6 * hull_volume)
    fail("its faces enclose " + shortest_text(std::abs(volume6) / 6) + " m³ but its corners' hull " +
         shortest_text(hull_volume) + " m³: not one convex solid");
  return block;
}

// ------------------------------------------------------------------ write

std::string obj_document(const std::vector<Polyhedron>& blocks, const std::vector<std::string>& names) {
  if (names.size() != blocks.size()) throw std::invalid_argument("obj_document: one name per block");
  std::string out = "# polydem blocks: one object per block, faces counter-clockwise from outside\n";
  long long first = 1;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    out.append("o ").append(names[b]).append("\n");
    for (const Vec3& v : blocks[b].vertices) {
      out.append("v ").append(shortest_text(v.x())).append(" ").append(shortest_text(v.y()));
      out.append(" ").append(shortest_text(v.z())).append("\n");
    }
    for (const auto& loop : blocks[b].faces) {
      out.append("f");
      for (int v : loop) out.append(" ").append(std::to_string(first + v));
      out.append("\n");
    }
    first += static_cast<long long>(blocks[b].vertices.size());
  }
  return out;
}

void write_obj(const std::string& path, const std::vector<Polyhedron>& blocks, const std::vector<std::string>& names) {
  write_file_atomic(path, obj_document(blocks, names));
}

}  // namespace polydem
