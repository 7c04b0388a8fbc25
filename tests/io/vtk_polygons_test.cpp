// Joint snapshots: contact patches as VTK_POLYGON cells with cell data.
#include "io/deck.hpp"
#include "io/snapshots.hpp"
#include "io/vtk.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <string>

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

// A stone at rest on a fixed base: its joint's normal force is its weight
// under either joint model. Under the overlap model the subcontacts carry
// no force; the cell must show the pair's.
void check_resting_stone(const char* model) {
  const std::string deck = std::string("[simulation]\nend_time = 0.6\njoint_model = \"") + model +
                           "\"\n\n[joint]\nfriction_angle = 30\n\n"
                           "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [2.0, 2.0, 0.5]\n"
                           "center = [0.0, 0.0, -0.25]\nmotion = \"fixed\"\n\n"
                           "[[block]]\nname = \"stone\"\nshape = \"box\"\nsize = [1.0, 0.5, 0.4]\n"
                           "center = [0.0, 0.0, 0.2]\n\n"
                           "[output]\nsnapshot_interval = 0.3\nenergies = false\n";
  RunControl control;
  JointCells last;
  double weight = 0;
  control.snapshot = [&](const Simulation& sim, double) {
    last = joint_cells(sim.contacts());
    weight = sim.blocks().props.mass[sim.blocks().find("stone")] * 9.81;
  };
  run_scene(parse_deck(deck, std::string(model) + ".toml"), control);
  ASSERT_EQ(last.normal_force.size(), 1u) << model;
  EXPECT_NEAR(last.normal_force[0], weight, 1e-3 * weight) << model;  // at rest: its weight, to 0.1 %
  EXPECT_LT(last.shear_force[0], 1e-6 * weight) << model;              // no load along the joint
  EXPECT_LT(last.opening[0], 0.0) << model;                            // closed
  EXPECT_EQ(last.polygons[0].size(), 4u) << model;
}

TEST(JointCells, ARestingStoneCarriesItsWeightUnderTheSubcontactModel) { check_resting_stone("subcontacts"); }
TEST(JointCells, ARestingStoneCarriesItsWeightUnderTheOverlapModel) { check_resting_stone("overlap"); }

}  // namespace
}  // namespace polydem
