// Blocks in mesh files: the readers behind [[import]] and the OBJ writer
// behind `polydem mesh`.
//
//   .obj  Wavefront OBJ (text): `v x y z`, `f a b c ...` (a, a/t, a/t/n, a//n;
//         negative indices count back from the last vertex), `o`/`g` names.
//         A part is a connected set of faces (sharing vertices) within one
//         object: `o` objects if the file has any (a `g` inside one is only
//         a group of its faces, e.g. a material), else `g` groups. An object
//         holding two separate solids is two parts (named NAME_1, NAME_2);
//         faces of different objects are never joined, even if they share
//         vertex indices.
//   .ply  Stanford PLY, ASCII or binary (either byte order): the `vertex`
//         element's x, y, z and the `face` element's vertex_indices (or
//         vertex_index) list; other elements and properties are skipped.
//         PLY has no objects: parts are the connected sets of faces.
//   .vtu  VTK XML unstructured grid with polyhedral cells (VTK_POLYHEDRON,
//         type 42) in the `faces`/`faceoffsets` layout, ASCII data arrays:
//         what polydem writes (snapshots, `polydem mesh`). One cell is one
//         part; the cell data `course` and `motion` (polydem's) come along.
//
// A part becomes a block only if it is closed (every edge shared by exactly
// two faces), orientable (faces turned to agree with their neighbours; a
// part whose faces all point inward is turned outside in), and convex (no
// corner in front of a face's plane by more than the tolerance). The block
// keeps the part's vertices and faces as written (vertices in file order)
// when they already make a valid polydem block (planar faces, no two
// neighbours coplanar: what polydem writes), so a file written with
// round-trip coordinates gives back the very blocks, bit for bit, in the
// same vertex and face order; otherwise (e.g. faces split into triangles)
// the block is the CGAL hull of its corners, numbered canonically like
// every hull (geometry/convex_hull.cpp). Errors are
// BlockFileError: "FILE:LINE: what" for syntax, "FILE: part N "NAME": why"
// for geometry; a malformed file is an error, never a crash.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/polyhedron.hpp"

namespace polydem {

struct BlockFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct FilePart {
  std::string name;                     // from the file (OBJ o/g); empty if none
  std::vector<Vec3> vertices;           // the part's own vertices, in file order
  std::vector<long long> vertex_ids;    // each one's number in the file (OBJ from 1, PLY and VTU from 0)
  std::vector<std::vector<int>> faces;  // loops of indices into `vertices`
  std::vector<std::string> face_where;  // where each face is in the file: "line 57", "face 12", "cell 3 face 2"
  int course = -1;                      // polydem .vtu cell data `course` (-1: none)
  int motion = -1;                      // polydem mesh .vtu cell data `motion`: 0 free, 1 fixed, 2 kinematic
};

struct BlockFile {
  std::string path;
  std::string format;  // "OBJ", "PLY", "VTU"
  std::vector<FilePart> parts;
};

BlockFile parse_obj(std::string_view text, const std::string& path);
BlockFile parse_ply(std::string_view bytes, const std::string& path);
BlockFile parse_vtu(std::string_view text, const std::string& path);

// Reads the file and parses it by its extension (.obj, .ply, .vtu; any case).
BlockFile read_block_file(const std::string& path);

// "FILE: part N "NAME"" (N from 1), the start of every message about a part.
std::string part_label(const BlockFile& file, std::size_t index);

// The part as a block (the checks above); `convex_rel_tol` times the part's
// bounding-box diagonal is how far a corner may lie in front of a face.
// Throws BlockFileError naming the part and the file's own vertex numbers.
Polyhedron part_block(const BlockFile& file, std::size_t index, double convex_rel_tol = 1e-6);

// OBJ of the blocks: one `o NAME` per block, its vertices (shortest
// round-trip text) and its faces (CCW from outside).
std::string obj_document(const std::vector<Polyhedron>& blocks, const std::vector<std::string>& names);
void write_obj(const std::string& path, const std::vector<Polyhedron>& blocks, const std::vector<std::string>& names);

}  // namespace polydem
