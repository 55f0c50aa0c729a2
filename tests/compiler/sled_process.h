// Runs the built `sled` program from a test: each test gets a temporary folder of its own, so
// tests that ctest runs side by side never share a file. CMake gives the binary's path
// (SLED_BINARY, tests/CMakeLists.txt) and builds it before the tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

namespace sled::testing {

namespace fs = std::filesystem;

inline const fs::path kSourceRoot = SLED_SOURCE_ROOT;

inline std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

inline fs::path SledBinary() { return SLED_BINARY; }

// A word for /bin/sh: single quotes, with embedded single quotes closed and escaped.
inline std::string Quote(const std::string& word) {
  std::string out = "'";
  for (char c : word) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

// Moves to `path` for the lifetime of the guard, so relative paths resolve there.
class WorkingDirectory {
 public:
  explicit WorkingDirectory(const fs::path& path) : saved_(fs::current_path()) {
    fs::current_path(path);
  }
  ~WorkingDirectory() {
    std::error_code error;
    fs::current_path(saved_, error);
  }
  WorkingDirectory(const WorkingDirectory&) = delete;
  WorkingDirectory& operator=(const WorkingDirectory&) = delete;

 private:
  fs::path saved_;
};

// A folder of its own under the system's temporary folder, removed at the end of the test.
class TempFolder {
 public:
  TempFolder() {
    std::string pattern = (fs::temp_directory_path() / "sled_test_XXXXXX").string();
    if (mkdtemp(pattern.data()) != nullptr) path_ = pattern;
  }
  ~TempFolder() {
    std::error_code error;
    if (!path_.empty()) fs::remove_all(path_, error);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

struct SledResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Fixture for tests of the `sled` program: Sled({...}) runs it in the repository root (or in
// `directory`) with both streams captured into the test's own folder, temp() is that folder.
class SledProcessTest : public ::testing::Test {
 protected:
  void SetUp() override {
    sled_ = SledBinary();
    ASSERT_TRUE(fs::exists(sled_))
        << "no sled binary at " << sled_ << "; build the `sled` target first";
    ASSERT_FALSE(temp_.path().empty()) << "cannot create a temporary folder";
  }

  SledResult Sled(const std::vector<std::string>& args, const fs::path& directory = kSourceRoot) {
    const fs::path out = temp_.path() / "stdout.txt";
    const fs::path err = temp_.path() / "stderr.txt";
    std::string command = "cd " + Quote(directory.string()) + " && " + Quote(sled_.string());
    for (const std::string& arg : args) command += " " + Quote(arg);
    command += " >" + Quote(out.string()) + " 2>" + Quote(err.string()) + " </dev/null";
    SledResult result;
    const int status = std::system(command.c_str());
    if (status != -1 && WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    result.out = ReadText(out);
    result.err = ReadText(err);
    return result;
  }

  const fs::path& temp() const { return temp_.path(); }

 private:
  fs::path sled_;
  TempFolder temp_;
};

}  // namespace sled::testing
