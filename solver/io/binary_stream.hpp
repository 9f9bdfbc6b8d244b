// Minimal binary serialisation for checkpoints: fixed-width values, strings and arrays with their
// length in front. A reader that runs past the end, or finds a length it did not expect, throws.
#pragma once

#include "core/types.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace mrsph {

// Types stored as raw bytes: trivially copyable ones, and Eigen's fixed-size vectors and matrices
// (plain arrays of doubles, though their copy constructors are user-provided).
template <class T>
inline constexpr bool kRawCopyable = std::is_trivially_copyable_v<T> || std::is_same_v<T, Vec2> || std::is_same_v<T, Mat2>;

class BinaryWriter {
 public:
  BinaryWriter() = default;
  // Writes into `reuse`, emptied first: its capacity is kept (no allocation when the size repeats).
  explicit BinaryWriter(std::string reuse) : buffer_(std::move(reuse)) { buffer_.clear(); }
  template <class T>
  void value(const T& v) {
    static_assert(kRawCopyable<T>);
    const auto* p = reinterpret_cast<const char*>(&v);
    buffer_.append(p, sizeof(T));
  }
  void text(const std::string& s) {
    value<std::uint64_t>(s.size());
    buffer_.append(s);
  }
  template <class T>
  void array(const std::vector<T>& a) {
    array(a.data(), a.size());
  }
  // The first n elements at `data`, stored as an array of n.
  template <class T>
  void array(const T* data, std::size_t n) {
    static_assert(kRawCopyable<T>);
    value<std::uint64_t>(n);
    if (n > 0) buffer_.append(reinterpret_cast<const char*>(data), n * sizeof(T));
  }
  // Bytes another writer wrote, as they are.
  void raw(const std::string& bytes) { buffer_.append(bytes); }
  const std::string& bytes() const { return buffer_; }
  std::string take() && { return std::move(buffer_); }

 private:
  std::string buffer_;
};

class BinaryReader {
 public:
  BinaryReader(std::string bytes, std::string source) : bytes_(std::move(bytes)), source_(std::move(source)) {}
  template <class T>
  T value() {
    T v;
    take(reinterpret_cast<char*>(&v), sizeof(T));
    return v;
  }
  std::string text() {
    const auto n = value<std::uint64_t>();
    need(n);
    std::string s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  // Reads an array; if expected_size is given, its length must match.
  template <class T>
  std::vector<T> array(std::size_t expected_size, const std::string& what) {
    const auto n = value<std::uint64_t>();
    if (expected_size != kAnySize && n != expected_size)
      throw std::runtime_error(source_ + ": " + what + " has " + std::to_string(n) + " entries, the scene has " +
                               std::to_string(expected_size) + " (is this checkpoint from another scene?)");
    std::vector<T> a(n);
    take(reinterpret_cast<char*>(a.data()), n * sizeof(T));
    return a;
  }
  bool at_end() const { return pos_ == bytes_.size(); }
  static constexpr std::size_t kAnySize = static_cast<std::size_t>(-1);

 private:
  void need(std::size_t n) const {
    if (pos_ + n > bytes_.size()) throw std::runtime_error(source_ + ": truncated checkpoint");
  }
  void take(char* out, std::size_t n) {
    need(n);
    if (n > 0) std::memcpy(out, bytes_.data() + pos_, n);  // an empty vector's data() may be null
    pos_ += n;
  }
  std::string bytes_;
  std::string source_;
  std::size_t pos_ = 0;
};

}  // namespace mrsph
