#include "io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "tests/test_util.hpp"

namespace polydem {
namespace {

using test::read_text;
using test::ScratchDir;
using Names = std::vector<std::string>;

TEST(AtomicFile, WritesContentAndLeavesNoTemporary) {
  ScratchDir dir("atomic");
  write_file_atomic(dir.path("a.txt"), "hello\nworld\n");
  EXPECT_EQ(read_text(dir.path("a.txt")), "hello\nworld\n");
  EXPECT_EQ(dir.entries(), Names{"a.txt"});
}

TEST(AtomicFile, ReplacesAnExistingFile) {
  ScratchDir dir("atomic");
  write_file_atomic(dir.path("a.txt"), std::string(100000, 'x'));
  write_file_atomic(dir.path("a.txt"), "short");
  EXPECT_EQ(read_text(dir.path("a.txt")), "short");
  EXPECT_EQ(dir.entries(), Names{"a.txt"});
}

TEST(AtomicFile, EmptyContentIsAValidFile) {
  ScratchDir dir("atomic");
  write_file_atomic(dir.path("empty"), "");
  EXPECT_TRUE(std::filesystem::exists(dir.path("empty")));
  EXPECT_EQ(std::filesystem::file_size(dir.path("empty")), 0u);
}

TEST(AtomicFile, MissingDirectoryThrowsNamingThePathAndLeavesNothing) {
  ScratchDir dir("atomic");
  const std::string target = dir.path("no/such/dir/a.txt");
  try {
    write_file_atomic(target, "x");
    FAIL() << "expected std::system_error";
  } catch (const std::system_error& e) {
    EXPECT_NE(std::string(e.what()).find("no/such/dir/a.txt"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(TempPath, UncommittedTemporaryIsRemovedAndFinalNeverAppears) {
  ScratchDir dir("atomic");
  std::string temp;
  {
    TempPath t(dir.path("results.h5"));
    temp = t.path();
    EXPECT_NE(temp, t.final_path());
    EXPECT_EQ(temp.rfind(dir.path("results.h5.tmp-"), 0), 0u) << temp;
    test::write_text(temp, "partial");
    EXPECT_TRUE(std::filesystem::exists(temp));
  }
  EXPECT_FALSE(std::filesystem::exists(temp));
  EXPECT_TRUE(dir.entries().empty());
}

TEST(TempPath, UncommittedRunKeepsThePreviousFinalFile) {
  ScratchDir dir("atomic");
  write_file_atomic(dir.path("summary.json"), "old");
  {
    TempPath t(dir.path("summary.json"));
    test::write_text(t.path(), "new but unfinished");
  }
  EXPECT_EQ(read_text(dir.path("summary.json")), "old");
  EXPECT_EQ(dir.entries(), Names{"summary.json"});
}

TEST(TempPath, CommitRenamesOntoFinalPath) {
  ScratchDir dir("atomic");
  {
    TempPath t(dir.path("out.vtu"));
    test::write_text(t.path(), "complete");
    EXPECT_FALSE(std::filesystem::exists(dir.path("out.vtu")));
    t.commit();
    EXPECT_TRUE(t.committed());
    EXPECT_THROW(t.commit(), std::logic_error);
  }
  EXPECT_EQ(read_text(dir.path("out.vtu")), "complete");
  EXPECT_EQ(dir.entries(), Names{"out.vtu"});
}

TEST(TempPath, CommitWithoutATemporaryFileThrows) {
  ScratchDir dir("atomic");
  TempPath t(dir.path("never_written"));
  EXPECT_THROW(t.commit(), std::system_error);
  EXPECT_FALSE(std::filesystem::exists(dir.path("never_written")));
}

TEST(TempPath, MovedFromDoesNotRemoveTheNewOwnersFile) {
  ScratchDir dir("atomic");
  TempPath a(dir.path("f"));
  test::write_text(a.path(), "data");
  TempPath b(std::move(a));
  { TempPath sink = std::move(a); }  // a is empty: nothing to remove
  EXPECT_TRUE(std::filesystem::exists(b.path()));
  b.commit();
  EXPECT_EQ(read_text(dir.path("f")), "data");
}

TEST(TempPath, TemporaryNamesAreUnique) {
  EXPECT_NE(temporary_name_for("x"), temporary_name_for("x"));
}

}  // namespace
}  // namespace polydem
