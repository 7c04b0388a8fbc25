// Contact detection: the stages that rebuild the contact set, in order.
//
//   detect():
//     1. broad phase: candidate pairs from the blocks' boxes   broad_phase.hpp
//     2. narrow phase: which candidates are within the margin  narrow_phase.hpp
//     3. patch: common plane, clipped joint polygon            contact_patch.hpp
//     4. subcontacts from the patches, history carried over    subcontacts.hpp
//     5. per-block gather lists                                gather.hpp
//
// Detection runs only when some block has moved (translation plus rotation
// times its radius) more than half the margin since the last one: until
// then no pair can close a gap wider than the margin (the broad phase grows
// every box by half the margin), and existing subcontacts follow their
// blocks exactly. Steps 2 and 3 run in parallel, one slot per candidate;
// everything is assembled in candidate order (sorted by block pair), so the
// result does not depend on the number of threads.
#pragma once

#include "contact/subcontacts.hpp"
#include "core/blocks.hpp"

#include <memory>

namespace polydem {

// Wall seconds spent in each stage of one detect() call.
struct DetectionTimes {
  double broad_phase = 0;
  double narrow_phase = 0;
  double patch = 0;
  double subcontacts = 0;  // assembly and history carry-over
  double gather = 0;
};

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
  // Returns the time spent in each stage.
  DetectionTimes detect(const Blocks& blocks, ContactSet& contacts, bool bond_new);

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
