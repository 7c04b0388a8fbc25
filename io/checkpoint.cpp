#include "io/checkpoint.hpp"

#include "core/byte_stream.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#ifndef POLYDEM_VERSION
#define POLYDEM_VERSION "0.1.0"
#endif

namespace polydem {

namespace {

constexpr char kMagic[8] = {'P', 'D', 'E', 'M', 'C', 'K', 'P', 'T'};
constexpr std::size_t kHeaderSize = 40;

}  // namespace

std::uint64_t deck_fingerprint(const std::string& deck_text, const std::vector<std::string>& overrides,
                               const std::string& record_bytes, const std::string& version) {
  std::string all;
  ByteWriter w(all);
  w.put(deck_text);
  w.put(overrides);
  w.put(record_bytes);
  w.put(version);
  w.put(kCheckpointVersion);
  return checksum64(all);
}

std::uint64_t run_fingerprint(const SceneSpec& spec, const std::vector<std::string>& overrides) {
  std::string record_bytes;
  if (spec.ground_motion.kind == GroundMotionKind::record) {
    std::ifstream in(spec.ground_motion.record_path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    record_bytes = ss.str();
  }
  return deck_fingerprint(spec.deck_text, overrides, record_bytes, POLYDEM_VERSION);
}

std::string encode_checkpoint(std::uint64_t fingerprint, const std::string& payload) {
  std::string out;
  out.reserve(kHeaderSize + payload.size());
  out.append(kMagic, sizeof kMagic);
  ByteWriter w(out);
  w.put(kCheckpointVersion);
  w.put(std::uint32_t{0});
  w.put(fingerprint);
  w.put(static_cast<std::uint64_t>(payload.size()));
  w.put(checksum64(payload));
  out.append(payload);
  return out;
}

std::string decode_checkpoint(const std::string& bytes, std::uint64_t fingerprint, const std::string& path) {
  auto fail = [&](const std::string& why) { throw CheckpointError(path + ": " + why); };
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    fail("not a polydem checkpoint (no PDEMCKPT header)");
  if (bytes.size() < kHeaderSize) fail("truncated checkpoint (" + std::to_string(bytes.size()) + " bytes, header incomplete)");
  ByteReader r(std::string_view(bytes).substr(sizeof kMagic, kHeaderSize - sizeof kMagic));
  std::uint32_t version = 0, reserved = 0;
  std::uint64_t fp = 0, size = 0, sum = 0;
  r.get(version);
  r.get(reserved);
  r.get(fp);
  r.get(size);
  r.get(sum);
  if (version != kCheckpointVersion)
    fail("checkpoint format version " + std::to_string(version) + ", this polydem reads version " +
         std::to_string(kCheckpointVersion));
  const std::size_t have = bytes.size() - kHeaderSize;
  if (size != have) {
    std::ostringstream m;
    m << (have < size ? "truncated" : "oversized") << " checkpoint: payload of " << have << " bytes, the header says "
      << size;
    fail(m.str());
  }
  std::string payload = bytes.substr(kHeaderSize);
  if (checksum64(payload) != sum) fail("corrupted checkpoint: the payload's checksum does not match the header");
  if (fp != fingerprint)
    fail("the checkpoint was written for a different deck, --set overrides, ground-motion record or polydem "
         "version; restart with exactly the deck and --set options of the original run");
  return payload;
}

std::string read_checkpoint_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(path + ": cannot open the checkpoint (" + std::strerror(errno) + ")");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw CheckpointError(path + ": cannot read the checkpoint");
  return s.str();
}

}  // namespace polydem
