#include "apps/mesh_command.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <iostream>
#include <set>

#include "analytical/static_overturning.hpp"
#include "apps/run_command.hpp"
#include "io/block_files.hpp"
#include "io/deck.hpp"
#include "io/vtk.hpp"
#include "structures/generator_specs.hpp"

namespace polydem {

MeshSummary summarize_mesh(const SceneSpec& scene) {
  MeshSummary s;
  s.blocks = static_cast<int>(scene.blocks.size());
  std::set<int> courses;
  double mz = 0;
  for (const BlockSpec& b : scene.blocks) {
    const MassProperties mp = mass_properties(b.shape);
    const double mass = b.density * mp.volume;
    if (b.course >= 0) courses.insert(b.course);
    if (b.motion != BlockMotion::free) {
      s.support_mass += mass;
      continue;
    }
    ++s.free_blocks;
    s.free_mass += mass;
    mz += mass * mp.centroid.z();
  }
  s.courses = static_cast<int>(courses.size());
  s.centroid_height = s.free_mass > 0 ? mz / s.free_mass : 0.0;
  if (const SpireSpec* spire = spire_of(scene.generators)) {
    s.has_cone = true;
    s.cone_radius = spire->base_inradius;
    s.cone_height = spire->height;
    s.lambda_eq1 = analytical::lambda_cone(s.cone_radius, s.cone_height);
    const analytical::GoverningCrack crack = analytical::governing_crack(s.cone_radius, s.cone_height);
    s.lambda_eq2 = crack.lambda;
    s.crack_height = crack.h_c;
  }
  return s;
}

int mesh_command(const MeshOptions& o) {
  SceneSpec scene;
  try {
    scene = read_deck(o.deck_path, o.overrides);
  } catch (const std::exception& e) {
    std::cerr << "polydem: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  const MeshSummary s = summarize_mesh(scene);

  std::vector<Polyhedron> shapes;
  std::vector<std::string> names;
  std::vector<int> ids, course, motion;
  std::vector<double> mass;
  for (std::size_t i = 0; i < scene.blocks.size(); ++i) {
    const BlockSpec& b = scene.blocks[i];
    shapes.push_back(b.shape);
    names.push_back(b.name);
    ids.push_back(static_cast<int>(i));
    course.push_back(b.course);
    motion.push_back(static_cast<int>(b.motion));  // 0 free, 1 fixed, 2 kinematic
    mass.push_back(b.density * mass_properties(b.shape).volume);
  }
  VtkCellData data;
  data.add_ints("block_id", ids).add_ints("course", course).add_ints("motion", motion).add_scalars("mass", mass);
  // The blocks as the deck built them (world coordinates at t = 0, exact
  // round-trip text): for ParaView (.vtu) and for other tools (.obj, one
  // object per block, named); [[import]] reads either back bit for bit.
  const std::string vtu = (std::filesystem::path(o.out_dir) / "blocks.vtu").string();
  const std::string obj = (std::filesystem::path(o.out_dir) / "blocks.obj").string();
  try {
    std::filesystem::create_directories(o.out_dir);
    write_vtu(vtu, shapes, data);
    write_obj(obj, shapes, names);
  } catch (const std::exception& e) {
    std::cerr << "polydem: error: cannot write " << vtu << " and " << obj << ": " << e.what() << "\n";
    return exit_bad_input;
  }

  fmt::print("deck              {}\n", o.deck_path);
  fmt::print("blocks            {} ({} free, {} fixed or kinematic; {} distinct course indices)\n", s.blocks, s.free_blocks,
             s.blocks - s.free_blocks, s.courses);
  fmt::print("total mass        {:.1f} kg of free blocks (+ {:.1f} kg fixed or kinematic)\n", s.free_mass,
             s.support_mass);
  fmt::print("centroid height   {:.4f} m (free blocks)\n", s.centroid_height);
  fmt::print("joint stiffness   kn = {:.4g} GPa/m, ks = {:.4g} GPa/m\n", scene.joint.normal_stiffness / 1e9,
             scene.joint.shear_stiffness / 1e9);
  if (s.has_cone) {
    fmt::print("equivalent cone   r_b = {:.4g} m (base_inradius), H = {:.4g} m (height)\n", s.cone_radius,
               s.cone_height);
    fmt::print("lambda eq. 1      {:.4f} (3 r_b / H, uncracked cone)\n", s.lambda_eq1);
    fmt::print("lambda eq. 2      {:.4f} (governing crack height h_c = {:.4g} m)\n", s.lambda_eq2, s.crack_height);
  }
  fmt::print("wrote             {}\n", vtu);
  fmt::print("                  {}\n", obj);
  return exit_success;
}

}  // namespace polydem
