// Tests of include/diffuv/output/write_labels.h: a label file, written then
// read back by read_face_labels(); a bad label writes nothing.
#include "test_data.h"

#include <diffuv/io/read_labels.h>
#include <diffuv/output/write_labels.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using LabelsFile = diffuv_test::Temp_dir_test;

TEST_F(LabelsFile, WriteThenRead)
{
  const std::vector<int> labels = {0, 5, 2147483647, 3, 3};
  diffuv::write_face_labels(path("out.txt"), labels);
  EXPECT_EQ(diffuv_test::file_content(path("out.txt")), "0\n5\n2147483647\n3\n3\n");
  EXPECT_EQ(diffuv::read_face_labels(path("out.txt"), labels.size()), labels);

  EXPECT_EQ(diffuv_test::error_text<diffuv::Output_error>([&] { diffuv::write_face_labels(path("neg.txt"), {1, -1}); }),
            path("neg.txt") + ": face 1 has label -1; labels are non-negative integers");
  EXPECT_FALSE(fs::exists(path("neg.txt")));
}

} // namespace
