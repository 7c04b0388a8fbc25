#include "io/vtk.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "io/atomic_file.hpp"

namespace polydem {
namespace {

constexpr int kVtkPolyhedron = 42;

// Shortest text that reads back to the same double.
void put_number(std::string& out, double x) {
  if (std::isnan(x)) {
    out += "nan";
  } else if (std::isinf(x)) {
    out += x > 0 ? "inf" : "-inf";
  } else {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    out.append(buf, r.ptr);
  }
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// Writes values, `per_line` to a line, indented.
template <class T, class Put>
void put_values(std::string& out, const std::vector<T>& v, std::size_t per_line, Put put) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i % per_line == 0) out += i == 0 ? "          " : "\n          ";
    else out += ' ';
    put(out, v[i]);
  }
  out += '\n';
}

void put_int_array(std::string& out, const char* type, const std::string& name, const std::vector<long long>& v,
                   std::size_t per_line = 12) {
  out += "        <DataArray type=\"";
  out += type;
  out += "\" Name=\"" + xml_escape(name) + "\" format=\"ascii\">\n";
  put_values(out, v, per_line, [](std::string& o, long long x) { o += std::to_string(x); });
  out += "        </DataArray>\n";
}

void check_size(const std::string& name, std::size_t n, std::size_t blocks) {
  if (n != blocks)
    throw std::invalid_argument("VTK cell data '" + name + "' has " + std::to_string(n) + " values for " +
                                std::to_string(blocks) + " blocks");
}

}  // namespace

VtkCellData& VtkCellData::add_scalars(std::string name, std::vector<double> values) {
  scalars.push_back({std::move(name), std::move(values)});
  return *this;
}
VtkCellData& VtkCellData::add_vectors(std::string name, std::vector<Vec3> values) {
  vectors.push_back({std::move(name), std::move(values)});
  return *this;
}
VtkCellData& VtkCellData::add_ints(std::string name, std::vector<int> values) {
  ints.push_back({std::move(name), std::move(values)});
  return *this;
}

namespace {

void put_cell_data(std::string& out, const VtkCellData& data) {
  const bool any = !data.scalars.empty() || !data.vectors.empty() || !data.ints.empty();
  if (any) {
    out += "      <CellData";
    if (!data.scalars.empty()) out += " Scalars=\"" + xml_escape(data.scalars.front().name) + "\"";
    if (!data.vectors.empty()) out += " Vectors=\"" + xml_escape(data.vectors.front().name) + "\"";
    out += ">\n";
    for (const auto& s : data.scalars) {
      out += "        <DataArray type=\"Float64\" Name=\"" + xml_escape(s.name) + "\" format=\"ascii\">\n";
      put_values(out, s.values, 6, put_number);
      out += "        </DataArray>\n";
    }
    for (const auto& s : data.vectors) {
      out += "        <DataArray type=\"Float64\" Name=\"" + xml_escape(s.name) +
             "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      std::vector<double> flat;
      flat.reserve(3 * s.values.size());
      for (const Vec3& v : s.values) flat.insert(flat.end(), {v.x(), v.y(), v.z()});
      put_values(out, flat, 3, put_number);
      out += "        </DataArray>\n";
    }
    for (const auto& s : data.ints)
      put_int_array(out, "Int32", s.name, std::vector<long long>(s.values.begin(), s.values.end()));
    out += "      </CellData>\n";
  }
}

// The parts of an unstructured-grid document that do not depend on the
// cell type: the header, the points and the cell connectivity and offsets
// (the caller adds the types and, for polyhedra, the faces), and the end.
void open_grid(std::string& out, const std::vector<double>& points, const std::vector<long long>& connectivity,
               const std::vector<long long>& offsets, std::size_t cells) {
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  out += "  <UnstructuredGrid>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(points.size() / 3) + "\" NumberOfCells=\"" +
         std::to_string(cells) + "\">\n";
  out += "      <Points>\n";
  out += "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  put_values(out, points, 3, put_number);
  out += "        </DataArray>\n";
  out += "      </Points>\n";
  out += "      <Cells>\n";
  put_int_array(out, "Int64", "connectivity", connectivity);
  put_int_array(out, "Int64", "offsets", offsets);
}

void close_grid(std::string& out, const VtkCellData& data) {
  put_cell_data(out, data);
  out += "    </Piece>\n";
  out += "  </UnstructuredGrid>\n";
  out += "</VTKFile>\n";
}

}  // namespace

std::string vtu_document(const std::vector<Polyhedron>& blocks, const VtkCellData& data) {
  const std::size_t nb = blocks.size();
  for (const auto& s : data.scalars) check_size(s.name, s.values.size(), nb);
  for (const auto& s : data.vectors) check_size(s.name, s.values.size(), nb);
  for (const auto& s : data.ints) check_size(s.name, s.values.size(), nb);

  std::vector<double> points;
  std::vector<long long> connectivity, offsets, faces, faceoffsets;
  long long first = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    const Polyhedron& p = blocks[b];
    const auto nv = static_cast<long long>(p.vertices.size());
    for (const Vec3& v : p.vertices) points.insert(points.end(), {v.x(), v.y(), v.z()});
    for (long long i = 0; i < nv; ++i) connectivity.push_back(first + i);
    offsets.push_back(static_cast<long long>(connectivity.size()));
    faces.push_back(static_cast<long long>(p.faces.size()));
    for (std::size_t f = 0; f < p.faces.size(); ++f) {
      faces.push_back(static_cast<long long>(p.faces[f].size()));
      for (const int v : p.faces[f]) {
        if (v < 0 || v >= nv)
          throw std::invalid_argument("VTK: block " + std::to_string(b) + " face " + std::to_string(f) +
                                      " refers to vertex " + std::to_string(v) + " of " + std::to_string(nv));
        faces.push_back(first + v);
      }
    }
    faceoffsets.push_back(static_cast<long long>(faces.size()));
    first += nv;
  }

  std::string out;
  out.reserve(64 * (points.size() + faces.size()) + 1024);
  open_grid(out, points, connectivity, offsets, nb);
  put_int_array(out, "UInt8", "types", std::vector<long long>(nb, kVtkPolyhedron), 20);
  put_int_array(out, "Int64", "faces", faces);
  put_int_array(out, "Int64", "faceoffsets", faceoffsets);
  out += "      </Cells>\n";

  close_grid(out, data);
  return out;
}

std::string vtu_polygons_document(const std::vector<std::vector<Vec3>>& polygons, const VtkCellData& data) {
  const std::size_t nc = polygons.size();
  for (const auto& s : data.scalars) check_size(s.name, s.values.size(), nc);
  for (const auto& s : data.vectors) check_size(s.name, s.values.size(), nc);
  for (const auto& s : data.ints) check_size(s.name, s.values.size(), nc);
  std::vector<double> points;
  std::vector<long long> connectivity, offsets;
  for (const auto& poly : polygons) {
    for (const Vec3& v : poly) {
      connectivity.push_back(static_cast<long long>(points.size() / 3));
      points.insert(points.end(), {v.x(), v.y(), v.z()});
    }
    offsets.push_back(static_cast<long long>(connectivity.size()));
  }
  std::string out;
  open_grid(out, points, connectivity, offsets, nc);
  put_int_array(out, "UInt8", "types", std::vector<long long>(nc, 7), 20);  // VTK_POLYGON
  out += "      </Cells>\n";
  close_grid(out, data);
  return out;
}

void write_vtu_polygons(const std::string& path, const std::vector<std::vector<Vec3>>& polygons,
                        const VtkCellData& cell_data) {
  write_file_atomic(path, vtu_polygons_document(polygons, cell_data));
}

void write_vtu(const std::string& path, const std::vector<Polyhedron>& blocks, const VtkCellData& cell_data) {
  write_file_atomic(path, vtu_document(blocks, cell_data));
}

std::string pvd_document(const std::vector<PvdEntry>& entries) {
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "  <Collection>\n";
  for (const auto& e : entries) {
    out += "    <DataSet timestep=\"";
    put_number(out, e.time);
    out += "\" group=\"\" part=\"0\" file=\"" + xml_escape(e.file) + "\"/>\n";
  }
  out += "  </Collection>\n";
  out += "</VTKFile>\n";
  return out;
}

void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries) {
  write_file_atomic(path, pvd_document(entries));
}

}  // namespace polydem
