// Tests of include/diffuv/output/write_ply.h: labelled PLY files (text and
// binary) read back by read_painted_labels() and by CGAL's reader, repainted
// or shared colours, errors that write nothing; vertex-coloured PLY files
// read back by read_vertex_colors() and by CGAL's reader.
#include "test_data.h"

#include <diffuv/core/color.h>
#include <diffuv/io/painted_labels.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/io/read_vertex_colors.h>
#include <diffuv/output/write_ply.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using diffuv::Color;
using diffuv::Label_source;
using diffuv_test::Mesh;
using diffuv_test::Point_3;
using face_descriptor = boost::graph_traits<Mesh>::face_descriptor;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using Polygons = std::vector<std::vector<std::size_t>>;

using LabelsPly = diffuv_test::Temp_dir_test;
using VertexColoredPly = diffuv_test::Temp_dir_test;

// ---------------------------------------------------------------------------
// Labelled PLY: write, then read back

TEST_F(LabelsPly, RoundTripOfARealMesh)
{
  Mesh mesh;
  const diffuv::Mesh_read_report report =
    diffuv::read_triangle_mesh(diffuv_test::data_path("meshes/nefertiti.off"), mesh);
  std::vector<int> labels(report.faces);
  for(std::size_t f = 0; f < labels.size(); ++f) // gaps, and labels past the palette
    labels[f] = static_cast<int>((f / 37) % 9 * 5 + (f % 5 == 0 ? 1000000 : 0));

  for(bool binary : {false, true}) {
    const std::string file = path(binary ? "binary.ply" : "text.ply");
    diffuv::Labelled_ply_options options;
    options.binary = binary;
    diffuv::write_labelled_ply(file, mesh, get(CGAL::vertex_point, mesh), labels, options);

    const diffuv::Painted_labels p = diffuv::read_painted_labels(file);
    EXPECT_EQ(p.source, Label_source::face_property) << binary;
    EXPECT_EQ(p.property, "label");
    EXPECT_EQ(p.polygon_labels, labels) << binary;

    // CGAL's reader: the same points in the same order, the same faces, and
    // each face in the colour of its label.
    std::vector<Point_3> points;
    Polygons polygons;
    std::vector<CGAL::IO::Color> colors;
    ASSERT_TRUE(diffuv_test::cgal_read_ply(file, points, polygons, colors, binary));
    ASSERT_EQ(points.size(), num_vertices(mesh));
    ASSERT_EQ(polygons.size(), num_faces(mesh));
    ASSERT_EQ(colors.size(), num_faces(mesh));
    std::size_t i = 0, wrong_points = 0;
    for(vertex_descriptor v : vertices(mesh))
      wrong_points += points[i++] != mesh.point(v);
    EXPECT_EQ(wrong_points, 0u);
    std::size_t j = 0, wrong_faces = 0, wrong_colors = 0;
    for(face_descriptor f : faces(mesh)) {
      wrong_faces += polygons[j] != diffuv_test::face_vertex_numbers(mesh, f);
      const Color expected = diffuv::label_color(labels[j]);
      wrong_colors += Color{colors[j].r(), colors[j].g(), colors[j].b()} != expected;
      ++j;
    }
    EXPECT_EQ(wrong_faces, 0u);
    EXPECT_EQ(wrong_colors, 0u);
  }
}

TEST_F(LabelsPly, RepaintedOrSharedColorsAreReadAsColors)
{
  const Mesh grid = diffuv_test::make_grid(2, 2); // 8 triangles
  const std::vector<int> labels = {0, 0, 1, 1, 2, 2, 3, 3};
  const std::string file = path("g.ply");
  diffuv::write_labelled_ply(file, grid, get(CGAL::vertex_point, grid), labels);

  // Repaint the last face in the colour of label 0 (MeshLab keeps the stale
  // label property): the colours win, ranked (r, g, b).
  std::ifstream in(file);
  std::vector<std::string> lines;
  for(std::string line; std::getline(in, line);)
    lines.push_back(line);
  in.close();
  const Color c0 = diffuv::label_color(0);
  std::istringstream last(lines.back()); // "3 i j k r g b label"
  std::string count, i, j, k;
  last >> count >> i >> j >> k;
  lines.back() = count + " " + i + " " + j + " " + k + " " + std::to_string(c0.r) + " " + std::to_string(c0.g) +
                 " " + std::to_string(c0.b) + " 3";
  std::string text;
  for(const std::string& line : lines)
    text += line + "\n";
  const diffuv::Painted_labels p = diffuv::read_painted_labels(write("g2.ply", text));
  EXPECT_EQ(p.source, Label_source::face_colors);
  // Colours of labels 0-3: (31,119,180) (255,127,14) (44,160,44) (214,39,40).
  EXPECT_EQ(p.polygon_labels, (std::vector<int>{0, 0, 3, 3, 1, 1, 2, 0}));

  // Colours given by the caller, shared by two labels: read back as colours.
  diffuv::Labelled_ply_options options;
  options.colors = {{9, 9, 9}, {9, 9, 9}, {1, 2, 3}, {200, 0, 0}};
  diffuv::write_labelled_ply(file, grid, get(CGAL::vertex_point, grid), labels, options);
  const diffuv::Painted_labels shared = diffuv::read_painted_labels(file);
  EXPECT_EQ(shared.source, Label_source::face_colors);
  EXPECT_EQ(shared.polygon_labels, (std::vector<int>{1, 1, 1, 1, 0, 0, 2, 2}));
}

TEST_F(LabelsPly, WriteErrorsWriteNothing)
{
  const Mesh grid = diffuv_test::make_grid(2, 2);
  const auto vpm = get(CGAL::vertex_point, grid);
  const std::string file = path("g.ply");
  EXPECT_EQ(diffuv_test::error_text<diffuv::Output_error>([&] { diffuv::write_labelled_ply(file, grid, vpm, {0, 0}); }),
            file + ": 2 face labels for a mesh of 8 faces");
  EXPECT_EQ(diffuv_test::error_text<diffuv::Output_error>(
              [&] { diffuv::write_labelled_ply(file, grid, vpm, {0, 0, 0, 0, 0, 0, -2, 0}); }),
            file + ": face 6 has label -2; labels are non-negative integers");
  diffuv::Labelled_ply_options options;
  options.colors = {{1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  EXPECT_EQ(diffuv_test::error_text<diffuv::Output_error>(
              [&] { diffuv::write_labelled_ply(file, grid, vpm, {0, 1, 2, 0, 1, 2, 3, 0}, options); }),
            file + ": face 6 has label 3, but only 3 colours are given");
  EXPECT_FALSE(fs::exists(file));
  EXPECT_TRUE(fs::is_empty(dir_));
}

// ---------------------------------------------------------------------------
// Vertex-coloured PLY: write, then read back

TEST_F(VertexColoredPly, RoundTrip)
{
  const Mesh grid = diffuv_test::make_grid(2, 1); // 6 vertices, 4 triangles
  std::vector<Color> colors;
  for(unsigned char i = 0; i < 6; ++i)
    colors.push_back(Color{static_cast<unsigned char>(50 * i), 255, static_cast<unsigned char>(7 - i)});
  const std::string file = path("v.ply");
  {
    std::ofstream out(file);
    diffuv::write_vertex_colored_ply(out, grid, get(CGAL::vertex_point, grid), colors, file);
  }
  EXPECT_EQ(diffuv::read_vertex_colors(file), colors);

  // CGAL's reader: the same points in the same order, the same faces and colours.
  std::vector<Point_3> points;
  Polygons polygons;
  std::vector<CGAL::IO::Color> face_colors, vertex_colors;
  ASSERT_TRUE(diffuv_test::cgal_read_ply(file, points, polygons, face_colors, false, &vertex_colors));
  ASSERT_EQ(points.size(), 6u);
  ASSERT_EQ(vertex_colors.size(), 6u);
  std::size_t i = 0;
  for(vertex_descriptor v : vertices(grid)) {
    EXPECT_EQ(points[i], grid.point(v)) << i;
    EXPECT_EQ((Color{vertex_colors[i].r(), vertex_colors[i].g(), vertex_colors[i].b()}), colors[i]) << i;
    ++i;
  }
  std::size_t j = 0;
  for(face_descriptor f : faces(grid))
    EXPECT_EQ(polygons[j++], diffuv_test::face_vertex_numbers(grid, f));

  // A colour per vertex, or nothing is written.
  std::ostringstream out;
  colors.pop_back();
  EXPECT_EQ(diffuv_test::error_text<diffuv::Output_error>(
              [&] { diffuv::write_vertex_colored_ply(out, grid, get(CGAL::vertex_point, grid), colors, file); }),
            file + ": 5 vertex colours for a mesh of 6 vertices");
  EXPECT_TRUE(out.str().empty());
}

} // namespace
