#pragma once
/// \file
/// \brief A fresh directory per test for the files the io tests write, removed afterwards.

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace adsd::test {

class TempDir {
 public:
  TempDir() {
    // Unique per process and test, so that parallel ctest runs do not share files.
    std::random_device entropy;
    path_ = std::filesystem::temp_directory_path() /
            ("adsd-io-test-" + std::to_string(entropy()) + "-" + std::to_string(entropy()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// \brief Writes \p content (text or bytes) to \p name inside the directory; returns the full path.
  std::string write(const std::string& name, const std::string& content) const {
    const std::string file = (path_ / name).string();
    std::ofstream out(file, std::ios::binary);
    out << content;
    return file;
  }

  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace adsd::test
