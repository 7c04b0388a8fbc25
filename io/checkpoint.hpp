// Checkpoint files: DIR/checkpoint.bin, the whole state of a run so that
// `polydem run DECK --restart DIR` continues it bitwise identically.
//
// Layout (all integers little-endian, fixed width):
//   offset  size  field
//        0     8  magic "PDEMCKPT"
//        8     4  format version (kCheckpointVersion)
//       12     4  reserved, 0
//       16     8  deck fingerprint: checksum of the deck text, the --set
//                 overrides, the ground-motion record's bytes and the
//                 polydem version (a restart with anything else is refused)
//       24     8  payload size in bytes
//       32     8  payload checksum (checksum64, core/byte_stream.hpp)
//       40     …  payload: run_scene's state (run/run_scene.hpp)
// The file is written with write_file_atomic (temporary, fsync, rename), so
// a machine that dies mid-write leaves the previous checkpoint; the size and
// checksum catch any file damaged some other way.
#pragma once

#include "core/scene_spec.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace polydem {

// 2: the assessment keeps the monitor block's peak displacement.
// 3: and the dislodged stones.
// 4: the subcontacts' pending dashpot force, the dropped shear and the
//    re-sampled normal strain energies.
// 5: the subcontacts' crush (the re-sampling's shift of a spring's zero).
// 6: the assessment judges the final state: its excursions past the
//    collapse fraction, the certain collapse.
// 9: under joint_sampling = "clip", each pair's rest from its last clip,
//    the clips so far and the pairs to clip again at the next step.
// 10: the same layout; a deck that does not set joint_sampling is now
//    clipped ("automatic"), so a run or sweep point of 9 is another model's.
inline constexpr std::uint32_t kCheckpointVersion = 10;
inline constexpr const char* kCheckpointFile = "checkpoint.bin";

// A checkpoint file that cannot be used; the message says why.
struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The fingerprint of what decides a run besides its state (with the
// checkpoint format, so that a sweep does not take a point of another
// model revision as its own).
std::uint64_t deck_fingerprint(const std::string& deck_text, const std::vector<std::string>& overrides,
                               const std::string& record_bytes, const std::string& version);
// The same for a parsed deck and this polydem: reads the ground-motion
// record's bytes when the deck has one (checkpoints; sweep point ids).
std::uint64_t run_fingerprint(const SceneSpec& spec, const std::vector<std::string>& overrides);

// Header + payload, ready for write_file_atomic.
std::string encode_checkpoint(std::uint64_t fingerprint, const std::string& payload);

// Checks magic, version, size, checksum and fingerprint of a checkpoint
// file's bytes and returns the payload. `path` names the file in messages.
std::string decode_checkpoint(const std::string& bytes, std::uint64_t fingerprint, const std::string& path);

// Reads a whole file; throws CheckpointError if it cannot.
std::string read_checkpoint_file(const std::string& path);

}  // namespace polydem
