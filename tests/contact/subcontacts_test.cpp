// carry_history: a subcontact found again (same pair, same key) keeps its
// shear force, bond and dissipation; one that is gone retires its
// dissipation to the ledger's totals.
#include "contact/subcontacts.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace polydem {
namespace {

// One pair (a, b) whose subcontacts have the given keys.
ContactSet one_pair(int a, int b, const std::vector<std::uint64_t>& keys) {
  ContactSet cs;
  ContactPair p;
  p.a = a;
  p.b = b;
  p.count = static_cast<int>(keys.size());
  cs.pairs.push_back(p);
  cs.sub.resize(keys.size());
  for (std::size_t s = 0; s < keys.size(); ++s) {
    cs.sub.key[s] = keys[s];
    cs.sub.area[s] = 0.25;
    cs.sub.shear_force[s] = Vec3::Zero();
    cs.sub.bonded[s] = 0;
    cs.sub.slip_energy[s] = 0;
    cs.sub.damping_energy[s] = 0;
    cs.sub.damping_force[s] = Vec3::Zero();
  }
  return cs;
}

TEST(CarryHistory, MatchedSubcontactsKeepTheirHistoryAndTheRestRetire) {
  ContactSet previous = one_pair(0, 1, {11, 22});
  previous.sub.shear_force[0] = Vec3(1, 2, 3);
  previous.sub.slip_energy[0] = 0.5;
  previous.sub.damping_energy[0] = 0.25;
  previous.sub.shear_force[1] = Vec3(4, 5, 6);
  previous.sub.bonded[1] = 1;
  previous.sub.slip_energy[1] = 2.0;
  previous.sub.damping_energy[1] = 1.0;
  previous.retired_slip_energy = 10.0;
  previous.retired_damping_energy = 20.0;

  ContactSet current = one_pair(0, 1, {22, 33});
  std::vector<char> matched;
  carry_history(previous, current, matched);
  // Key 22 found again: its history carries over.
  EXPECT_EQ(current.sub.shear_force[0], Vec3(4, 5, 6));
  EXPECT_EQ(current.sub.bonded[0], 1);
  EXPECT_EQ(current.sub.slip_energy[0], 2.0);
  EXPECT_EQ(current.sub.damping_energy[0], 1.0);
  // Key 33 is new.
  EXPECT_EQ(current.sub.shear_force[1], Vec3::Zero());
  // The shear displacement carries over: on half the area, half the force
  // (the patch changed shape), not the whole force on a smaller spring.
  ContactSet smaller = one_pair(0, 1, {22});
  smaller.sub.area[0] = 0.125;
  carry_history(previous, smaller, matched);
  EXPECT_EQ(smaller.sub.shear_force[0], Vec3(2, 2.5, 3));
  EXPECT_EQ(current.sub.slip_energy[1], 0.0);
  // Key 11 is gone: its dissipation is retired.
  EXPECT_EQ(current.retired_slip_energy, 10.5);
  EXPECT_EQ(current.retired_damping_energy, 20.25);
}

TEST(CarryHistory, AnotherPairDoesNotInherit) {
  ContactSet previous = one_pair(0, 1, {11});
  previous.sub.slip_energy[0] = 3.0;
  ContactSet current = one_pair(0, 2, {11});
  std::vector<char> matched;
  carry_history(previous, current, matched);
  EXPECT_EQ(current.sub.slip_energy[0], 0.0);
  EXPECT_EQ(current.retired_slip_energy, 3.0);
  EXPECT_EQ(find_pair(previous, 0, 1), &previous.pairs[0]);
  EXPECT_EQ(find_pair(previous, 0, 2), nullptr);
}

}  // namespace
}  // namespace polydem
