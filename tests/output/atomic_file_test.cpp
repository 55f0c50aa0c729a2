// AtomicFile: a file is replaced whole or not at all, and a failure says why.
#include "output/atomic_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace sled::runtime {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "sled_atomic_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    folder_ = pattern;
  }
  void TearDown() override { fs::remove_all(folder_); }
  static std::string Read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  std::size_t Entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder_), {}));
  }
  fs::path folder_;
};

TEST_F(AtomicFileTest, ACommittedFileHoldsEveryByteAndNoTemporaryIsLeft) {
  const fs::path path = folder_ / "data.csv";
  {
    AtomicFile file(path.string());
    // More than the buffer, in pieces and in one large write.
    for (int i = 0; i < 20000; ++i) file << "0.001,2.5,-3\n";
    file.Write(std::string(200000, 'x'));
    std::string error;
    ASSERT_TRUE(file.Commit(&error)) << error;
  }
  EXPECT_EQ(Read(path).size(), 20000u * 13 + 200000);
  EXPECT_EQ(Entries(), 1u);
}

TEST_F(AtomicFileTest, AnUncommittedFileLeavesTheOldOneAsItWas) {
  const fs::path path = folder_ / "summary.json";
  { std::ofstream(path) << "old"; }
  {
    AtomicFile file(path.string());
    file << "new, but never committed";
  }
  EXPECT_EQ(Read(path), "old");
  EXPECT_EQ(Entries(), 1u);
}

TEST_F(AtomicFileTest, AFailureNamesTheFileAndItsCause) {
  const fs::path path = folder_ / "no_such_folder" / "data.csv";
  AtomicFile file(path.string());
  file << "text";
  std::string error;
  EXPECT_FALSE(file.Commit(&error));
  EXPECT_THAT(error, HasSubstr("cannot write `" + path.string() + "`: No such file or directory"));
}

TEST_F(AtomicFileTest, TemporaryNamesAreRecognised) {
  const fs::path path = folder_ / "timeseries.csv";
  AtomicFile file(path.string());
  file << "x";
  bool seen = false;
  for (const auto& entry : fs::directory_iterator(folder_)) {
    seen = seen || AtomicFile::IsTemporaryName(entry.path().filename().string());
  }
  EXPECT_TRUE(seen);
  EXPECT_FALSE(AtomicFile::IsTemporaryName("timeseries.csv"));
  EXPECT_FALSE(AtomicFile::IsTemporaryName(".hidden"));
}

}  // namespace
}  // namespace sled::runtime
