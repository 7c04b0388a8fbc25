// Joint snapshots: contact patches as VTK_POLYGON cells with cell data.
#include "io/vtk.hpp"

#include <gtest/gtest.h>

namespace polydem {
namespace {

TEST(VtkPolygons, PatchesAsPolygonCells) {
  const std::vector<std::vector<Vec3>> patches = {
      {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
      {Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(2, 1, 0)},
  };
  VtkCellData data;
  data.add_scalars("normal_force", {10.0, 20.0});
  const std::string doc = vtu_polygons_document(patches, data);
  EXPECT_NE(doc.find("NumberOfPoints=\"7\" NumberOfCells=\"2\""), std::string::npos) << doc;
  EXPECT_NE(doc.find("Name=\"normal_force\""), std::string::npos);
  // Offsets 4 and 7, both cells of type 7 (VTK_POLYGON).
  const auto offsets = doc.find("Name=\"offsets\"");
  ASSERT_NE(offsets, std::string::npos);
  EXPECT_NE(doc.find("4 7", offsets), std::string::npos);
  const auto types = doc.find("Name=\"types\"");
  ASSERT_NE(types, std::string::npos);
  EXPECT_NE(doc.find("7 7", types), std::string::npos);
  // Cell data must match the cell count.
  VtkCellData bad;
  bad.add_scalars("normal_force", {1.0});
  EXPECT_THROW(vtu_polygons_document(patches, bad), std::invalid_argument);
}

}  // namespace
}  // namespace polydem
