#pragma once
// Raw little helpers for the checkpoint format: fixed-width values written as bytes, exactly
// (a restart must reproduce the uninterrupted run bit for bit, so nothing goes through text).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace ellc::engine::binary {

template <typename T>
  requires std::is_trivially_copyable_v<T>
void put(std::ostream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <typename T>
  requires std::is_trivially_copyable_v<T>
void get(std::istream& in, T& value) {
  in.read(reinterpret_cast<char*>(&value), sizeof(T));
  if (!in) throw std::runtime_error("checkpoint ends early or cannot be read");
}

// A bool is one byte, 0 or 1; any other byte is corruption (and loading it as a bool undefined).
inline void get(std::istream& in, bool& value) {
  std::uint8_t byte = 0;
  get(in, byte);
  if (byte > 1)
    throw std::runtime_error("checkpoint is corrupt (a flag holds " + std::to_string(byte) + ", not 0 or 1)");
  value = byte != 0;
}

// Bytes left in the stream, or -1 when the stream cannot tell (not seekable).
inline std::streamoff remaining_bytes(std::istream& in) {
  const std::streampos here = in.tellg();
  if (here == std::streampos(-1)) return -1;
  in.seekg(0, std::ios::end);
  const std::streampos end = in.tellg();
  in.seekg(here);
  return end == std::streampos(-1) ? -1 : static_cast<std::streamoff>(end - here);
}

// The fewest bytes one stored element takes (an array's size field is checked against it).
template <typename T>
constexpr std::size_t stored_size_at_least() noexcept {
  if constexpr (std::is_same_v<T, Eigen::Vector3d>) return 3 * sizeof(double);
  if constexpr (std::is_same_v<T, Eigen::Quaterniond>) return 4 * sizeof(double);
  if constexpr (std::is_trivially_copyable_v<T>) return sizeof(T);
  return 1;
}

inline void put(std::ostream& out, const Eigen::Vector3d& v) {
  out.write(reinterpret_cast<const char*>(v.data()), 3 * sizeof(double));
}
inline void get(std::istream& in, Eigen::Vector3d& v) {
  in.read(reinterpret_cast<char*>(v.data()), 3 * sizeof(double));
  if (!in) throw std::runtime_error("checkpoint ends early or cannot be read");
}
inline void put(std::ostream& out, const Eigen::Quaterniond& q) {
  out.write(reinterpret_cast<const char*>(q.coeffs().data()), 4 * sizeof(double));
}
inline void get(std::istream& in, Eigen::Quaterniond& q) {
  in.read(reinterpret_cast<char*>(q.coeffs().data()), 4 * sizeof(double));
  if (!in) throw std::runtime_error("checkpoint ends early or cannot be read");
}

template <typename T>
void put(std::ostream& out, const std::vector<T>& values) {
  put(out, static_cast<std::uint64_t>(values.size()));
  for (const auto& value : values) put(out, value);
}

// `element_bytes`: the fewest bytes one stored element takes, for the size check.
template <typename T>
void get(std::istream& in, std::vector<T>& values, std::size_t element_bytes = stored_size_at_least<T>()) {
  std::uint64_t size = 0;
  get(in, size);
  // Checked against what the stream still holds before anything is allocated.
  const std::streamoff left = remaining_bytes(in);
  const std::uint64_t limit =
      left >= 0 ? static_cast<std::uint64_t>(left) / std::max<std::size_t>(element_bytes, 1) : (std::uint64_t{1} << 34);
  if (size > limit)
    throw std::runtime_error("checkpoint is corrupt (an array of " + std::to_string(size) + " elements where " +
                             (left >= 0 ? std::to_string(left) + " bytes are left" : "at most 2^34 are allowed") + ")");
  values.resize(size);
  for (auto& value : values) get(in, value);
}

inline void put(std::ostream& out, const std::string& text) {
  put(out, static_cast<std::uint64_t>(text.size()));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}
inline void get(std::istream& in, std::string& text) {
  std::uint64_t size = 0;
  get(in, size);
  const std::streamoff left = remaining_bytes(in);
  if (size > (std::uint64_t{1} << 30) || (left >= 0 && size > static_cast<std::uint64_t>(left)))
    throw std::runtime_error("checkpoint is corrupt (a string of " + std::to_string(size) + " bytes)");
  text.resize(size);
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (!in) throw std::runtime_error("checkpoint ends early or cannot be read");
}

}  // namespace ellc::engine::binary
