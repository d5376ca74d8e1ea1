// Tests of include/diffuv/io/atomic_file.h: files written to a temporary
// and renamed on commit, output folders that are all written or not at all,
// and the checks of an output directory.
#include "test_data.h"

#include <diffuv/io/atomic_file.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <iterator>
#include <ostream>
#include <string>

namespace {

namespace fs = std::filesystem;

using IoAtomicFile = diffuv_test::Temp_dir_test;

TEST_F(IoAtomicFile, NotCommittedLeavesNothing)
{
  const std::string target = path("a.txt");
  std::string temporary;
  {
    diffuv::Atomic_output_file file(target);
    temporary = file.temporary_path();
    EXPECT_EQ(temporary, path(".a.txt.tmp." + std::to_string(::getpid())));
    file.stream() << "hello";
    EXPECT_TRUE(fs::exists(temporary));
    EXPECT_FALSE(fs::exists(target));
  }
  EXPECT_FALSE(fs::exists(target));
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(IoAtomicFile, CommitReplacesTheTarget)
{
  const std::string target = write("a.txt", "old");
  {
    diffuv::Atomic_output_file file(target);
    file.stream() << "new content";
    EXPECT_EQ(diffuv_test::file_content(target), "old"); // untouched until the commit
    file.commit();
    EXPECT_FALSE(fs::exists(file.temporary_path()));
  }
  EXPECT_EQ(diffuv_test::file_content(target), "new content");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(IoAtomicFile, FailedWriteKeepsTheOldFile)
{
  const std::string target = write("a.txt", "old");
  diffuv::Atomic_output_file file(target);
  file.stream() << "half";
  file.stream().setstate(std::ios::badbit); // what a full disk does to the stream
  try {
    file.commit();
    ADD_FAILURE() << "no error";
  } catch(const diffuv::Output_error& e) {
    EXPECT_EQ(std::string(e.what()), target + ": writing failed (disk full or I/O error)");
  }
  EXPECT_EQ(diffuv_test::file_content(target), "old");
  EXPECT_FALSE(fs::exists(file.temporary_path()));
}

// A full disk on the second file of a folder: neither file is replaced (the
// first one, complete, must not be renamed before the second is known good).
TEST_F(IoAtomicFile, AFailedFileLeavesTheWholeFolderAsItWas)
{
  const std::string a = write("a.txt", "old a");
  const std::string b = write("b.txt", "old b");
  {
    diffuv::Output_folder folder(dir_.string());
    folder.open("a.txt") << "new a";
    std::ostream& second = folder.open("b.txt");
    second << "half";
    second.setstate(std::ios::badbit); // what a full disk does to the stream
    try {
      folder.commit();
      ADD_FAILURE() << "no error";
    } catch(const diffuv::Output_error& e) {
      EXPECT_EQ(std::string(e.what()), b + ": writing failed (disk full or I/O error)");
    }
  }
  EXPECT_EQ(diffuv_test::file_content(a), "old a");
  EXPECT_EQ(diffuv_test::file_content(b), "old b");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 2); // no temporary left

  // The same in a folder the run creates: the folder goes too.
  const fs::path fresh = dir_ / "fresh";
  {
    diffuv::Output_folder folder(fresh.string());
    folder.open("a.txt") << "new a";
    folder.open("b.txt").setstate(std::ios::badbit);
    EXPECT_THROW(folder.commit(), diffuv::Output_error);
  }
  EXPECT_FALSE(fs::exists(fresh));
}

TEST_F(IoAtomicFile, MissingFolderThrows)
{
  const std::string target = path("no/such/folder/a.txt");
  EXPECT_THROW(diffuv::Atomic_output_file file(target), diffuv::Output_error);
}

TEST_F(IoAtomicFile, EnsureOutputDirectory)
{
  const std::string nested = path("x/y/z");
  diffuv::ensure_output_directory(nested);
  EXPECT_TRUE(fs::is_directory(nested));
  EXPECT_TRUE(fs::is_empty(nested)); // the probe file is gone
  diffuv::ensure_output_directory(nested); // existing: fine

  const std::string file = write("plain.txt", "x");
  try {
    diffuv::ensure_output_directory(file);
    ADD_FAILURE() << "no error";
  } catch(const diffuv::Output_error& e) {
    EXPECT_EQ(std::string(e.what()), file + ": exists and is not a directory");
    EXPECT_EQ(e.path(), file);
  }
  try {
    diffuv::ensure_output_directory(file + "/sub");
    ADD_FAILURE() << "no error";
  } catch(const diffuv::Output_error& e) {
    EXPECT_EQ(std::string(e.what()), file + "/sub: cannot create the directory (Not a directory)");
  }
}

TEST_F(IoAtomicFile, UnwritableDirectory)
{
  // /proc refuses new files even to root, unlike a folder without write bits.
  if(!fs::is_directory("/proc"))
    GTEST_SKIP() << "no /proc";
  try {
    diffuv::ensure_output_directory("/proc");
    ADD_FAILURE() << "no error";
  } catch(const diffuv::Output_error& e) {
    EXPECT_EQ(std::string(e.what()), "/proc: the directory is not writable");
  }
}

} // namespace
