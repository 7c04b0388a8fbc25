// Plain binary encoding of run state, for checkpoints (io/checkpoint.hpp).
//
// Fixed width and little-endian whatever the host: integers as 1, 4 or 8
// bytes, doubles as their IEEE-754 bit pattern in 8 bytes, vectors as a u64
// count followed by the elements. Vec3/Quat/Mat3 are 3/4/9 doubles (Quat in
// Eigen's coefficient order x, y, z, w; Mat3 column-major). A double goes
// out and comes back with the same bits, which is what a bitwise-identical
// restart needs. No framing or versioning here: the checkpoint file adds a
// header (magic, version, size, checksum) around the payload.
//
// ByteReader throws StateFormatError when a read would run past the end or
// a count cannot fit in what is left (a corrupted or truncated payload).
#pragma once

#include "geometry/polyhedron.hpp"
#include "geometry/vec3_array.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace polydem {

struct StateFormatError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class ByteWriter {
 public:
  explicit ByteWriter(std::string& out) : out_(out) {}

  void put(bool v) { put(static_cast<std::uint8_t>(v ? 1 : 0)); }
  void put(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void put(std::int32_t v) { put_le(static_cast<std::uint32_t>(v), 4); }
  void put(std::uint32_t v) { put_le(v, 4); }
  void put(std::int64_t v) { put_le(static_cast<std::uint64_t>(v), 8); }
  void put(std::uint64_t v) { put_le(v, 8); }
  void put(double v) { put_le(std::bit_cast<std::uint64_t>(v), 8); }
  void put(const std::string& s) {
    put(static_cast<std::uint64_t>(s.size()));
    out_.append(s);
  }
  void put(const Vec3& v) { put_doubles(v.data(), 3); }
  void put(const Mat3& m) { put_doubles(m.data(), 9); }
  void put(const Quat& q) { put_doubles(q.coeffs().data(), 4); }
  // The same bytes as a std::vector<Vec3> of the same values.
  void put(const Vec3Array& v) {
    put(static_cast<std::uint64_t>(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) {
      put(v.x[i]);
      put(v.y[i]);
      put(v.z[i]);
    }
  }

  template <class T>
  void put(const std::vector<T>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    if constexpr (std::is_same_v<T, double>) {
      put_doubles(v.data(), v.size());
    } else if constexpr (std::is_same_v<T, Vec3> || std::is_same_v<T, Mat3>) {
      for (const T& x : v) put_doubles(x.data(), static_cast<std::size_t>(x.size()));
    } else {
      for (const auto& x : v) put(static_cast<const T&>(x));
    }
  }

 private:
  void put_le(std::uint64_t v, int bytes) {
    char b[8];
    for (int k = 0; k < bytes; ++k) b[k] = static_cast<char>((v >> (8 * k)) & 0xFF);
    out_.append(b, static_cast<std::size_t>(bytes));
  }
  void put_doubles(const double* p, std::size_t n) {
    if (n == 0) return;
    if constexpr (std::endian::native == std::endian::little) {
      out_.append(reinterpret_cast<const char*>(p), 8 * n);
    } else {
      for (std::size_t k = 0; k < n; ++k) put(p[k]);
    }
  }

  std::string& out_;
};

class ByteReader {
 public:
  explicit ByteReader(std::string_view in) : in_(in) {}

  std::size_t remaining() const { return in_.size() - pos_; }
  bool at_end() const { return pos_ == in_.size(); }

  void get(bool& v) {
    std::uint8_t b = 0;
    get(b);
    if (b > 1) throw StateFormatError("bad boolean byte");
    v = b == 1;
  }
  void get(std::uint8_t& v) { v = static_cast<std::uint8_t>(take(1)[0]); }
  void get(std::int32_t& v) { v = static_cast<std::int32_t>(static_cast<std::uint32_t>(get_le(4))); }
  void get(std::uint32_t& v) { v = static_cast<std::uint32_t>(get_le(4)); }
  void get(std::int64_t& v) { v = static_cast<std::int64_t>(get_le(8)); }
  void get(std::uint64_t& v) { v = get_le(8); }
  void get(double& v) { v = std::bit_cast<double>(get_le(8)); }
  void get(std::string& s) {
    const std::size_t n = count(1);
    s.assign(take(n), n);
  }
  void get(Vec3& v) { get_doubles(v.data(), 3); }
  void get(Mat3& m) { get_doubles(m.data(), 9); }
  void get(Quat& q) { get_doubles(q.coeffs().data(), 4); }

  template <class T>
  void get(std::vector<T>& v) {
    // Each element takes at least one byte: a count beyond what is left is
    // corruption, refused before allocating.
    const std::size_t n = count(1);
    v.resize(n);
    if constexpr (std::is_same_v<T, double>) {
      get_doubles(v.data(), n);
    } else if constexpr (std::is_same_v<T, Vec3> || std::is_same_v<T, Mat3>) {
      for (T& x : v) get_doubles(x.data(), static_cast<std::size_t>(x.size()));
    } else {
      for (T& x : v) get(x);
    }
  }

  void get(Vec3Array& v) {
    const std::size_t n = count(24);
    v.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      get(v.x[i]);
      get(v.y[i]);
      get(v.z[i]);
    }
  }

  // A vector whose length must be `expected` (e.g. one entry per block).
  template <class T>
  void get_sized(T& v, std::size_t expected, const char* what) {
    get(v);
    if (v.size() != expected)
      throw StateFormatError(std::string(what) + ": " + std::to_string(v.size()) + " entries, expected " +
                             std::to_string(expected));
  }

 private:
  const char* take(std::size_t n) {
    if (n > remaining()) throw StateFormatError("truncated (ends inside a record)");
    const char* p = in_.data() + pos_;
    pos_ += n;
    return p;
  }
  std::size_t count(std::size_t min_bytes_each) {
    std::uint64_t n = 0;
    get(n);
    if (n > remaining() / min_bytes_each) throw StateFormatError("count " + std::to_string(n) + " beyond the data");
    return static_cast<std::size_t>(n);
  }
  std::uint64_t get_le(int bytes) {
    const char* p = take(static_cast<std::size_t>(bytes));
    std::uint64_t v = 0;
    for (int k = 0; k < bytes; ++k) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(p[k])) << (8 * k);
    return v;
  }
  void get_doubles(double* p, std::size_t n) {
    if (n == 0) return;  // an empty vector's data() may be null: memcpy must not see it
    if constexpr (std::endian::native == std::endian::little) {
      if (n > remaining() / 8) throw StateFormatError("truncated (ends inside a record)");
      std::memcpy(p, take(8 * n), 8 * n);
    } else {
      for (std::size_t k = 0; k < n; ++k) get(p[k]);
    }
  }

  std::string_view in_;
  std::size_t pos_ = 0;
};

// 64-bit checksum of a byte string: FNV-1a over 64-bit little-endian words
// (the tail zero-padded), with the length mixed in and a final avalanche.
// Not cryptographic; it catches truncation, torn writes and flipped bits.
inline std::uint64_t checksum64(std::string_view data) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  const std::uint64_t prime = 0x100000001b3ull;
  std::size_t k = 0;
  for (; k + 8 <= data.size(); k += 8) {
    std::uint64_t w = 0;
    for (int b = 0; b < 8; ++b) w |= static_cast<std::uint64_t>(static_cast<unsigned char>(data[k + b])) << (8 * b);
    h = (h ^ w) * prime;
  }
  std::uint64_t w = 0;
  for (int b = 0; k + b < data.size(); ++b)
    w |= static_cast<std::uint64_t>(static_cast<unsigned char>(data[k + b])) << (8 * b);
  h = (h ^ w) * prime;
  h = (h ^ static_cast<std::uint64_t>(data.size())) * prime;
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  return h;
}

}  // namespace polydem
