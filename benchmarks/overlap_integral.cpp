// The cost of one Winkler joint integral (contact/overlap_integral.hpp) per
// pair of blocks, for the contacts a step meets: a face contact of two
// boxes, two stones of neighbouring courses of the default spire, an edge,
// a corner, a pair of random hulls, and a pair apart along n (the early
// exit). Each row is the median over `--repeats` runs of `--calls` calls on
// one pair with one warmed-up scratch: the pair's data stay in cache, as for
// a contact loop that visits each pair once per step.
//
//   polydem_overlap_integral [--calls N] [--repeats R] [--engine LABEL]
#include "bench_util.hpp"
#include "contact/overlap_integral.hpp"
#include "structures/spire.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace polydem;

namespace {

struct Pair {
  Pair() = default;
  Pair(std::string n, Polyhedron pa, Polyhedron pb) : name(std::move(n)), a(std::move(pa)), b(std::move(pb)) {}
  std::string name;
  Polyhedron a, b;
  Mat3 Ra = Mat3::Identity(), Rb = Mat3::Identity();
  Vec3 xa = Vec3::Zero(), xb = Vec3::Zero();
  JointFrame frame;
};

Pair boxes() {
  Pair p{"box on box, face (0.6 × 0.5 on 1 × 0.8)", make_box(Vec3(1, 0.8, 0.5)), make_box(Vec3(0.6, 0.5, 0.4))};
  p.xa = Vec3(0, 0, -0.25);
  p.xb = Vec3(0.1, 0.05, 0.2 - 1e-4);
  return p;
}

// The first stones of face 1 in courses 2 and 3 (staggered: half
// overlapping), the upper one pressed down by 0.1 mm.
Pair spire_stones() {
  const SpireModel model = build_spire(SpireSpec{});
  const auto named = [&](const std::string& name) {
    for (const GeneratedBlock& b : model.blocks)
      if (b.name == name) return b.shape;
    throw std::runtime_error("no spire block " + name);
  };
  Pair p{"spire stones, course joint", named("course02_face1_stone0"), named("course03_face1_stone0")};
  p.xb = Vec3(0, 0, -1e-4);
  p.frame = make_joint_frame(Vec3::UnitZ(), 0.5 * (mass_properties(p.a).centroid + mass_properties(p.b).centroid));
  return p;
}

// A cube of side 0.4 with rotation R over a 2 × 2 face, its lowest point 1 mm deep.
Pair cube_on_face(const std::string& name, const Mat3& R) {
  Pair p{name, make_box(Vec3(2, 2, 1)), make_box(Vec3(0.4, 0.4, 0.4))};
  p.xa = Vec3(0, 0, -0.5);
  p.Rb = R;
  double low = 1e300;
  for (const Vec3& v : p.b.vertices) low = std::min(low, (R * v).z());
  p.xb = Vec3(0, 0, -low - 1e-3);
  return p;
}

Pair random_hulls(double depth, const std::string& name) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> r(0.3, 0.5);
  const auto unit = [&] { return Vec3(g(rng), g(rng), g(rng)).normalized(); };
  const auto hull = [&] {
    std::vector<Vec3> pts;
    for (int i = 0; i < 20; ++i) pts.push_back(r(rng) * unit());
    return convex_hull(pts);
  };
  Pair p{name, hull(), hull()};
  // B's lowest vertex `depth` below A's highest, straight above it.
  Vec3 top = p.a.vertices[0], low = p.b.vertices[0];
  for (const Vec3& v : p.a.vertices)
    if (v.z() > top.z()) top = v;
  for (const Vec3& v : p.b.vertices)
    if (v.z() < low.z()) low = v;
  p.xb = top - low - Vec3(0, 0, depth);
  p.frame = make_joint_frame(Vec3::UnitZ(), top);
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace polydem::bench;
  const long calls = std::stol(option(argc, argv, "--calls", "200000"));
  const int repeats = std::stoi(option(argc, argv, "--repeats", "7"));
  std::vector<Pair> pairs = {boxes(),
                             spire_stones(),
                             cube_on_face("edge (cube at 30° about x)", Eigen::AngleAxisd(M_PI / 6, Vec3::UnitX()).toRotationMatrix()),
                             cube_on_face("corner (cube diagonal vertical)",
                                          Quat::FromTwoVectors(Vec3(1, 1, 1).normalized(), Vec3::UnitZ())
                                              .toRotationMatrix()),
                             random_hulls(0.05, "random hulls (20 points each), 5 cm deep"),
                             random_hulls(-1e-3, "random hulls, 1 mm apart (early exit)")};
  Table table({"pair", "faces A/B", "cells", "area (m²)", "ns per pair"});
  for (Pair& p : pairs) {
    const PosedBlock a{&p.a, p.Ra, p.xa}, b{&p.b, p.Rb, p.xb};
    OverlapScratch scratch;
    OverlapMoments m = overlap_integral(a, b, p.frame, scratch);
    std::vector<double> ns;
    double sink = 0;
    for (int r = 0; r < repeats; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      for (long k = 0; k < calls; ++k) sink += overlap_integral(a, b, p.frame, scratch).volume;
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      ns.push_back(1e9 * s / calls);
    }
    std::sort(ns.begin(), ns.end());
    if (sink < 0) std::printf("%g\n", sink);  // keeps the calls
    table.add_row({p.name, std::to_string(p.a.faces.size()) + "/" + std::to_string(p.b.faces.size()),
                   std::to_string(m.cells), fmt(m.area, 3), fmt(ns[ns.size() / 2], 3)});
  }
  const Machine machine = this_machine();
  std::printf("%s\n", table.markdown().c_str());
  std::printf("median of %d runs of %ld calls; %s, %s, load %s, polydem %s\n", repeats, calls,
              machine.cpu_model.c_str(), machine.build.c_str(), machine.load_average.c_str(),
              engine_version(argc, argv).c_str());
  return 0;
}
