#pragma once
// Raw little helpers for the checkpoint format: fixed-width values written as bytes, exactly
// (a restart must reproduce the uninterrupted run bit for bit, so nothing goes through text).

#include <Eigen/Core>
#include <Eigen/Geometry>

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

template <typename T>
void get(std::istream& in, std::vector<T>& values) {
  std::uint64_t size = 0;
  get(in, size);
  if (size > (std::uint64_t{1} << 34))
    throw std::runtime_error("checkpoint is corrupt (array size " + std::to_string(size) + ")");
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
  if (size > (std::uint64_t{1} << 30)) throw std::runtime_error("checkpoint is corrupt (string size)");
  text.resize(size);
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (!in) throw std::runtime_error("checkpoint ends early or cannot be read");
}

}  // namespace ellc::engine::binary
