// VTK output for ParaView: one .vtu (XML unstructured grid, ASCII) per
// snapshot with every block as a VTK_POLYHEDRON cell, and a .pvd collection
// listing the snapshots with their times.
//
// Polyhedron cells (type 42) carry their own face lists: besides
// connectivity/offsets/types the Cells section has "faces" (per cell: number
// of faces, then for each face its number of points and global point ids, CCW
// from outside) and "faceoffsets" (per cell, the end of its stream in
// "faces"). Points are the block vertices in world coordinates, block after
// block, so block b's vertex v is point first_point(b) + v.
//
// Both files are written atomically (temporary file, rename).
#pragma once

#include <string>
#include <vector>

#include "geometry/polyhedron.hpp"

namespace polydem {

// Named per-cell (per-block) arrays. Each must have one entry per block.
struct VtkCellData {
  struct Scalars {
    std::string name;
    std::vector<double> values;
  };
  struct Vectors {
    std::string name;
    std::vector<Vec3> values;
  };
  struct Ints {
    std::string name;
    std::vector<int> values;
  };
  std::vector<Scalars> scalars;
  std::vector<Vectors> vectors;
  std::vector<Ints> ints;

  VtkCellData& add_scalars(std::string name, std::vector<double> values);
  VtkCellData& add_vectors(std::string name, std::vector<Vec3> values);
  VtkCellData& add_ints(std::string name, std::vector<int> values);
};

// The .vtu document. Throws std::invalid_argument when a data array's length
// differs from blocks.size() or a face refers to a missing vertex.
// Non-finite doubles are written as "nan"/"inf"/"-inf".
std::string vtu_document(const std::vector<Polyhedron>& blocks, const VtkCellData& cell_data = {});
void write_vtu(const std::string& path, const std::vector<Polyhedron>& blocks, const VtkCellData& cell_data = {});

// A .pvd collection: one DataSet per entry. `file` is written as given; use a
// path relative to the .pvd (e.g. "vtk/step_000100.vtu") so the run folder
// can be moved.
// Polygons (VTK_POLYGON cells), e.g. the contact patches of the joints.
std::string vtu_polygons_document(const std::vector<std::vector<Vec3>>& polygons, const VtkCellData& cell_data = {});
void write_vtu_polygons(const std::string& path, const std::vector<std::vector<Vec3>>& polygons,
                        const VtkCellData& cell_data = {});

struct PvdEntry {
  double time = 0;
  std::string file;
};
std::string pvd_document(const std::vector<PvdEntry>& entries);
void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries);

}  // namespace polydem
