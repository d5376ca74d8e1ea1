// Tests of include/diffuv/io/selection_file.h: CGAL's selection files (the
// vertex indices of their first line), every rejection with its exact
// message and line, and indices checked against a mesh.
#include "test_data.h"

#include <diffuv/io/selection_file.h>

#include <gtest/gtest.h>

#include <iterator>
#include <string>
#include <vector>

namespace {

using diffuv_test::Mesh;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

using IoSelection = diffuv_test::Temp_dir_test;

TEST_F(IoSelection, ReadsCgalSquareCorners)
{
  const std::string file = diffuv_test::data_path("selections/square_corners.selection.txt");
  const std::vector<std::size_t> indices = diffuv::read_selection_file(file);
  EXPECT_EQ(indices, (std::vector<std::size_t>{133, 8, 0, 287}));

  const Mesh& mesh = diffuv_test::cgal_mesh("nefertiti.off");
  const std::vector<vertex_descriptor> corners = diffuv::selection_vertices(mesh, indices, file);
  ASSERT_EQ(corners.size(), 4u);
  for(std::size_t k = 0; k < 4; ++k)
    EXPECT_EQ(corners[k], *std::next(vertices(mesh).begin(), static_cast<std::ptrdiff_t>(indices[k])));
}

TEST_F(IoSelection, CgalSelectionWithoutVertices)
{
  // lion.selection.txt selects edges only (its first line is empty).
  const std::string file = diffuv_test::data_path("selections/lion.selection.txt");
  try {
    diffuv::read_selection_file(file);
    ADD_FAILURE() << "no error";
  } catch(const diffuv::Input_error& e) {
    EXPECT_EQ(std::string(e.what()), file + ":1: no vertex index on the first line");
  }
}

TEST_F(IoSelection, Errors)
{
  struct Case { std::string content; std::size_t line; std::string reason; };
  const Case cases[] = {
    {"", 1, "no vertex index on the first line"},
    {"   \n1 2 3\n", 1, "no vertex index on the first line"},
    {"1 2 x\n", 1, "\"x\" is not a vertex index (a non-negative integer)"},
    {"4 -3\n", 1, "\"-3\" is not a vertex index (a non-negative integer)"},
    {"1.5\n", 1, "\"1.5\" is not a vertex index (a non-negative integer)"},
    {"+2\n", 1, "\"+2\" is not a vertex index (a non-negative integer)"},
    {"7 99999999999999999999999\n", 1, "vertex index 99999999999999999999999 is too large"},
    {std::string("3 \x01\0\n", 5), 1, "\"\\x01\\x00\" is not a vertex index (a non-negative integer)"},
  };
  int k = 0;
  for(const Case& c : cases) {
    const std::string file = write("s" + std::to_string(k++) + ".selection.txt", c.content);
    try {
      diffuv::read_selection_file(file);
      ADD_FAILURE() << "no error for " << c.content;
    } catch(const diffuv::Input_error& e) {
      EXPECT_EQ(e.reason(), c.reason);
      EXPECT_EQ(e.line(), c.line);
      EXPECT_EQ(e.file(), file);
    }
  }
  try {
    diffuv::read_selection_file(path("missing.selection.txt"));
    ADD_FAILURE() << "no error";
  } catch(const diffuv::Input_error& e) {
    EXPECT_EQ(std::string(e.what()), path("missing.selection.txt") + ": cannot open file");
  }
}

TEST_F(IoSelection, ByteOrderMarkIsSkipped)
{
  EXPECT_EQ(diffuv::read_selection_file(write("bom.txt", "\xEF\xBB\xBF" "0 2 8 6\n")),
            (std::vector<std::size_t>{0, 2, 8, 6}));
}

TEST_F(IoSelection, TabsCarriageReturnsAndOtherLines)
{
  const std::string file = write("ok.selection.txt", "3\t1  2 \r\n5 6\n0 1\n");
  EXPECT_EQ(diffuv::read_selection_file(file), (std::vector<std::size_t>{3, 1, 2}));
}

TEST_F(IoSelection, IndexOutOfRange)
{
  const Mesh& mesh = diffuv_test::cgal_mesh("nefertiti.off");
  ASSERT_EQ(num_vertices(mesh), 299u);
  EXPECT_EQ(diffuv::selection_vertices(mesh, {298}, "s.txt").size(), 1u);
  try {
    diffuv::selection_vertices(mesh, {0, 299}, "s.txt");
    ADD_FAILURE() << "no error";
  } catch(const diffuv::Input_error& e) {
    EXPECT_EQ(std::string(e.what()), "s.txt:1: vertex index 299 is out of range (the mesh has 299 vertices)");
  }
}

} // namespace
