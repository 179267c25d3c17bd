#pragma once
// A whole file as one string (binary mode: the bytes as written), for tests that read outputs.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ellc::test {

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace ellc::test
