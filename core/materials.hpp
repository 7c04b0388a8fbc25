// Materials: joint stiffnesses derived from the masonry's materials.
//
// A bed joint of a course of stone is modelled as one spring per unit area
// between rigid blocks, so all the elastic compliance of one course pitch is
// lumped into it: the stone over the pitch less the mortar, and the mortar,
// in series (the paper, section 3.1 and Table 1). With course pitch h,
// mortar thickness t and Young's moduli E_stone and E_mortar:
//
//   1/kn = (h − t)/E_stone + t/E_mortar          (kn in Pa/m)
//
// Table 1 (h = 0.3 m, t = 0.01 m, E_stone = 30 GPa, E_mortar = 10 GPa)
// gives kn = 93.75 GPa/m. The shear stiffness follows from a ratio,
// ks = ratio·kn, 0.4 in Table 1 (the deck's [joint] and [spire] sections
// read both; io/deck.cpp holds their defaults).
#pragma once

namespace polydem {

// Joint normal stiffness (Pa/m) of stone and mortar in series over one
// course pitch: pitch h and mortar thickness t in m (0 ≤ t < h), Young's
// moduli in Pa. Evaluated as 1 / ((h − t)/E_stone + t/E_mortar).
double series_joint_normal_stiffness(double pitch, double mortar_thickness, double e_stone, double e_mortar);

// Joint shear stiffness (Pa/m) from the normal stiffness (Pa/m) and the
// shear-to-normal ratio (dimensionless): ratio·kn.
double joint_shear_stiffness(double normal_stiffness, double shear_ratio);

}  // namespace polydem
