#pragma once
/// \file
/// \brief A fresh directory per test for the cfg and mesh files the planner tests write.

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace adsd::planner::test {

class ScratchDir {
 public:
  ScratchDir() {
    std::random_device entropy;  // unique per process and test: parallel ctest runs share nothing
    path_ = std::filesystem::temp_directory_path() /
            ("adsd-planner-test-" + std::to_string(entropy()) + "-" + std::to_string(entropy()));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  std::string write(const std::string& name, const std::string& content) const {
    const std::string file = path(name);
    std::ofstream out(file, std::ios::binary);
    out << content;
    return file;
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& root() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace adsd::planner::test
