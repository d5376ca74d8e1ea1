// Tests of include/diffuv/io/read_labels.h: label files (every rejection with
// its exact message and line), and labels of a file's polygons carried to
// the triangles of the mesh.
//
// Expectations come from the files, read by eye and written here.
#include "test_data.h"

#include <diffuv/io/read_labels.h>
#include <diffuv/io/read_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

using diffuv_test::Mesh;
using face_descriptor = boost::graph_traits<Mesh>::face_descriptor;
using Polygons = std::vector<std::vector<std::size_t>>;

using LabelsFile = diffuv_test::Temp_dir_test;
using LabelsMesh = diffuv_test::Temp_dir_test;

diffuv::Input_error label_file_error(const std::string& file, std::size_t expected)
{
  return diffuv_test::input_error([&] { diffuv::read_face_labels(file, expected); });
}

// ---------------------------------------------------------------------------
// Label files

TEST_F(LabelsFile, AnyLayoutWithComments)
{
  const std::string file = write("l.txt", "# regions of the cow\n3\n0 1\r\n\n   7   # the head\n2147483647\n#end");
  EXPECT_EQ(diffuv::read_face_labels(file, 5), (std::vector<int>{3, 0, 1, 7, 2147483647}));
  EXPECT_TRUE(diffuv::read_face_labels(write("empty.txt", "# nothing\n"), 0).empty());
}

TEST_F(LabelsFile, Errors)
{
  diffuv::Input_error e = label_file_error(path("missing.txt"), 1);
  EXPECT_EQ(e.reason(), "cannot open file");
  EXPECT_EQ(e.line(), 0u);
  EXPECT_EQ(label_file_error(dir_.string(), 1).reason(), "cannot open file");

  e = label_file_error(write("a.txt", "1\n2\n# three\n3 abc\n"), 5);
  EXPECT_EQ(e.reason(), "\"abc\" is not an integer label");
  EXPECT_EQ(e.line(), 4u);
  EXPECT_EQ(label_file_error(write("b.txt", "1.5\n"), 1).reason(), "\"1.5\" is not an integer label");
  EXPECT_EQ(label_file_error(write("c.txt", "+3\n"), 1).reason(), "\"+3\" is not an integer label");
  EXPECT_EQ(label_file_error(write("d.txt", "0x10\n"), 1).reason(), "\"0x10\" is not an integer label");

  e = label_file_error(write("e.txt", "0\n2147483648\n"), 2);
  EXPECT_EQ(e.reason(), "label 2147483648 is out of range");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(label_file_error(write("f.txt", "-2147483649\n"), 1).reason(), "label -2147483649 is out of range");
  EXPECT_EQ(label_file_error(write("g.txt", "99999999999999999999\n"), 1).reason(),
            "label 99999999999999999999 is out of range");

  e = label_file_error(write("h.txt", "0\n1\n2\n3\n4\n5\n-3\n"), 7);
  EXPECT_EQ(e.reason(), "label -3 is negative; labels are non-negative integers");
  EXPECT_EQ(e.line(), 7u);
  EXPECT_EQ(std::string(e.what()), path("h.txt") + ":7: label -3 is negative; labels are non-negative integers");

  // Bytes that would cut or garble the one-line message are spelled out.
  e = label_file_error(write("i.txt", std::string("0\n1\x01\0z\n", 7)), 2);
  EXPECT_EQ(e.reason(), "\"1\\x01\\x00z\" is not an integer label");
  EXPECT_EQ(e.line(), 2u);
  // A UTF-8 byte-order mark (Windows editors) is not part of the first label.
  EXPECT_EQ(diffuv::read_face_labels(write("bom.txt", "\xEF\xBB\xBF" "4\n2\n"), 2), (std::vector<int>{4, 2}));

  e = label_file_error(write("i.txt", "0\n1\n2\n"), 4);
  EXPECT_EQ(e.reason(), "the file has 3 labels, the mesh has 4 faces");
  EXPECT_EQ(e.line(), 0u);
  EXPECT_EQ(label_file_error(write("j.txt", "0\n"), 2).reason(), "the file has 1 label, the mesh has 2 faces");
  EXPECT_EQ(label_file_error(write("k.txt", "0 0\n"), 1).reason(), "the file has 2 labels, the mesh has 1 face");
}

// ---------------------------------------------------------------------------
// Labels of the polygons of a file -> labels of the triangles of the mesh

// Checks that each face of the mesh read from `file` gets the label of the
// only polygon of the file that has its three corners.
void expect_triangles_take_their_polygon_label(const std::string& file, const Polygons& polygons)
{
  std::vector<int> polygon_labels(polygons.size());
  for(std::size_t j = 0; j < polygons.size(); ++j)
    polygon_labels[j] = static_cast<int>((7 * j + 3) % 11);
  Mesh mesh;
  const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(file, mesh);
  const std::vector<int> labels = diffuv::face_labels_of_mesh(polygon_labels, report);
  ASSERT_EQ(labels.size(), num_faces(mesh)) << file;
  std::size_t f = 0;
  std::vector<std::size_t> triangles(polygons.size(), 0);
  for(face_descriptor face : faces(mesh)) {
    std::vector<std::size_t> owners;
    for(std::size_t j = 0; j < polygons.size(); ++j) {
      const auto& p = polygons[j];
      const auto c = diffuv_test::face_vertex_numbers(mesh, face);
      if(std::all_of(c.begin(), c.end(), [&](std::size_t v) { return std::find(p.begin(), p.end(), v) != p.end(); }))
        owners.push_back(j);
    }
    ASSERT_EQ(owners.size(), 1u) << file << " face " << f;
    ++triangles[owners[0]];
    EXPECT_EQ(labels[f++], polygon_labels[owners[0]]) << file << " face " << f - 1;
  }
  for(std::size_t j = 0; j < polygons.size(); ++j)
    EXPECT_EQ(triangles[j], polygons[j].size() - 2) << file << " polygon " << j;
}

TEST_F(LabelsMesh, TrianglesOfAQuadTakeItsLabel)
{
  for(const char* name : {"meshes/cube_quad.off", "meshes/torus_quad.off"}) {
    const std::string file = diffuv_test::data_path(name);
    expect_triangles_take_their_polygon_label(file, diffuv_test::parse_off(file).faces);
  }
  // Quads, a pentagon (triangulated by CGAL's CDT) and a triangle.
  const std::string file = write("q.off", "OFF\n9 4 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n"
                                          "2 2 0.1\n3 0 0\n4 0 1 4 3\n4 1 2 5 4\n5 3 4 5 7 6\n3 2 8 5\n");
  expect_triangles_take_their_polygon_label(file, diffuv_test::parse_off(file).faces);
}

TEST_F(LabelsMesh, Errors)
{
  Mesh mesh;
  diffuv::Mesh_read_report report =
    diffuv::read_triangle_mesh(write("q.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"), mesh);
  EXPECT_EQ(diffuv::face_labels_of_mesh({8}, report), (std::vector<int>{8, 8}));
  EXPECT_EQ(diffuv_test::error_text<diffuv::Error>([&] { diffuv::face_labels_of_mesh({1, 2}, report); }),
            "there are 2 polygon labels, the mesh file has 1 face");
  report.file_face.clear();
  EXPECT_EQ(diffuv_test::error_text<diffuv::Error>([&] { diffuv::face_labels_of_mesh({1}, report); }),
            "the mesh read report has no face provenance (file_face)");
}

} // namespace
