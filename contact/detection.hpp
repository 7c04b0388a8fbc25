// Contact detection: broad phase, narrow phase and patch, subcontact
// persistence, and the per-block gather lists.
//
// Broad phase: FCL's dynamic AABB tree over the blocks' world boxes, each
// grown by half the contact margin. Detection runs only when some block has
// moved (translation plus rotation times its radius) more than half the
// margin since the last one: until then no pair can close a gap wider than
// the margin, and existing subcontacts follow their blocks exactly.
// Blocks that cannot move (fixed, kinematic) are never paired with each other.
//
// Subcontacts are keyed by (pair, reference side and face, incident face,
// clipped feature). A subcontact found again keeps its shear force, bond and
// dissipation; one that disappears hands its dissipation to the ledger.
#pragma once

#include "contact/subcontacts.hpp"
#include "core/blocks.hpp"

#include <memory>

namespace polydem {

class ContactDetector {
 public:
  ContactDetector(const Blocks& blocks, double margin);
  ~ContactDetector();
  ContactDetector(const ContactDetector&) = delete;
  ContactDetector& operator=(const ContactDetector&) = delete;

  double margin() const { return margin_; }
  // True when some block moved more than half the margin since detect().
  bool needs_detection(const Blocks& blocks) const;
  // Rebuilds `contacts` for the current state, carrying history over.
  // New subcontacts start bonded when `bond_new` is set (cohesion/tension at t = 0).
  void detect(const Blocks& blocks, ContactSet& contacts, bool bond_new);

  // Checkpoints: the poses at the last detection (they decide when the next
  // one runs). Nothing else carries over: the contacts of the detection
  // before (`previous` inside) are only read during detect(), which swaps the
  // current set in as the history and rebuilds every array it hands back,
  // and the FCL tree is refitted to exact boxes at each detection and its
  // pairs are sorted, so a tree rebuilt after a restart finds the same ones.
  void save(ByteWriter& w) const;
  void load(ByteReader& r);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double margin_;
};

}  // namespace polydem
