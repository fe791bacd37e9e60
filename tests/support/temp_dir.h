#pragma once
// A fresh folder per test case (named after the process and the case, so parallel ctest runs of
// one binary never share it), removed with its contents at the end of the case.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace cgtmo::test {

struct CaseDir {
  std::filesystem::path path;
  explicit CaseDir(const std::string& prefix) {
    path = std::filesystem::temp_directory_path() /
           (prefix + "_" + std::to_string(::getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~CaseDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  CaseDir(const CaseDir&) = delete;
  CaseDir& operator=(const CaseDir&) = delete;
};

}  // namespace cgtmo::test
