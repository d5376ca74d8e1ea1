// Tests of include/diffuv/io/painted_labels.h: painted regions in OFF and
// PLY files (CGAL's coloured meshes, MeshLab- and Blender-style headers, text
// and binary), every rejection with its exact message and line, and the
// per-vertex rule.
//
// Expectations come from the files, read by eye and written here, or from
// CGAL's readers where they read the same thing.
#include "test_data.h"

#include <diffuv/core/color.h>
#include <diffuv/io/paint_look.h>
#include <diffuv/io/painted_labels.h>
#include <diffuv/io/read_mesh.h>

#include <CGAL/IO/OFF.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace {

using diffuv::Color;
using diffuv::Label_source;
using diffuv_test::Mesh;
using diffuv_test::Point_3;
using Polygons = std::vector<std::vector<std::size_t>>;

using LabelsPainted = diffuv_test::Temp_dir_test;
using LabelsPaintedErrors = diffuv_test::Temp_dir_test;

diffuv::Input_error painted_error(const std::string& file, const std::string& property = std::string())
{
  return diffuv_test::input_error([&] { diffuv::read_painted_labels(file, property); });
}

// ---------------------------------------------------------------------------
// Painted regions in CGAL's coloured meshes

TEST_F(LabelsPainted, ColoredTetraPlyFaceColors)
{
  // The faces of colored_tetra.ply (red green blue, then an int label):
  //   3 0 1 2 255 0 0 -1 / 3 0 3 1 0 255 0 1 / 3 1 3 2 0 0 255 -1 / 3 0 2 3 255 0 255 0
  // Sorted colours: (0,0,255) (0,255,0) (255,0,0) (255,0,255). Its label
  // property does not group the faces as the colours do (and is negative):
  // the colours are used.
  const std::string file = diffuv_test::data_path("meshes/colored_tetra.ply");
  const diffuv::Painted_labels p = diffuv::read_painted_labels(file);
  EXPECT_EQ(p.source, Label_source::face_colors);
  EXPECT_EQ(p.property, "red/green/blue");
  EXPECT_EQ(p.polygon_labels, (std::vector<int>{2, 1, 0, 3}));
  EXPECT_EQ(p.colors, (std::vector<Color>{{0, 0, 255}, {0, 255, 0}, {255, 0, 0}, {255, 0, 255}}));

  // CGAL's reader gives the same colours, face by face.
  std::vector<Point_3> points;
  Polygons polygons;
  std::vector<CGAL::IO::Color> colors;
  ASSERT_TRUE(diffuv_test::cgal_read_ply(file, points, polygons, colors));
  ASSERT_EQ(colors.size(), p.polygon_labels.size());
  for(std::size_t j = 0; j < colors.size(); ++j)
    EXPECT_EQ(p.colors[p.polygon_labels[j]], (Color{colors[j].r(), colors[j].g(), colors[j].b()})) << j;

  // Asked for, the label property is read, and its -1 is an error.
  const diffuv::Input_error e = painted_error(file, "label");
  EXPECT_EQ(e.reason(), "face 0 has label -1 (property \"label\"); labels are non-negative integers");
  EXPECT_EQ(e.line(), 29u);
}

TEST_F(LabelsPainted, MeshWithColorsOff)
{
  // COFF, faces "3 0 1 7 0.9 0 0", "3 1 2 3 0.9 0 0", "3 5 6 7 0.9 0 0",
  // "5 1 3 4 5 7 0 0 0.9": float colours, 0.9 -> round(229.5) = 230.
  // Blue (0,0,230) sorts before red (230,0,0). The vertices are coloured too:
  // face colours come first.
  const std::string file = diffuv_test::data_path("meshes/mesh_with_colors.off");
  const diffuv::Painted_labels p = diffuv::read_painted_labels(file);
  EXPECT_EQ(p.source, Label_source::face_colors);
  EXPECT_EQ(p.property, "rgb");
  EXPECT_EQ(p.polygon_labels, (std::vector<int>{1, 1, 1, 0}));
  EXPECT_EQ(p.colors, (std::vector<Color>{{0, 0, 230}, {230, 0, 0}}));

  // CGAL reads the same regions, but truncates 0.9 * 255 to 229.
  std::vector<Point_3> points;
  Polygons polygons;
  std::vector<CGAL::IO::Color> colors;
  const auto np = CGAL::parameters::face_color_output_iterator(std::back_inserter(colors)).verbose(false);
  ASSERT_TRUE(CGAL::IO::read_OFF(file, points, polygons, np));
  ASSERT_EQ(colors.size(), 4u);
  EXPECT_EQ(colors[0], CGAL::IO::Color(229, 0, 0));
  EXPECT_EQ(colors[3], CGAL::IO::Color(0, 0, 229));
}

// ---------------------------------------------------------------------------
// OFF as MeshLab and Geomview write it

const std::string square_points = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

TEST_F(LabelsPainted, OffFaceColorsWithoutC)
{
  // MeshLab writes face colours (integers and alpha) under a plain "OFF".
  const std::string file =
    write("m.off", "OFF\n4 2 0\n" + square_points + "3 0 1 2 200 10 10 255\n3 0 2 3 20 20 200 255\n");
  const diffuv::Painted_labels p = diffuv::read_painted_labels(file);
  EXPECT_EQ(p.source, Label_source::face_colors);
  EXPECT_EQ(p.polygon_labels, (std::vector<int>{1, 0}));
  EXPECT_EQ(p.colors, (std::vector<Color>{{20, 20, 200}, {200, 10, 10}}));

  // A pitfall: CGAL's reader reads face colours only after a "COFF" header.
  std::vector<Point_3> points;
  Polygons polygons;
  std::vector<CGAL::IO::Color> colors;
  const auto np = CGAL::parameters::face_color_output_iterator(std::back_inserter(colors)).verbose(false);
  ASSERT_TRUE(CGAL::IO::read_OFF(file, points, polygons, np));
  EXPECT_TRUE(colors.empty());
}

TEST_F(LabelsPainted, CoffVertexColors)
{
  // Vertex colours (floats with alpha) and none on the faces: vertex labels
  // red = 1, blue = 0 (blue sorts first): 1 1 0 0. Face 0 (1, 1, 0) -> 1,
  // face 1 (1, 0, 0) -> 0.
  const std::string file = write("c.off", "COFF\n4 2 0\n0 0 0 1.0 0.0 0.0 1.0\n1 0 0 1.0 0.0 0.0 1.0\n"
                                          "1 1 0 0.0 0.0 1.0 1.0\n0 1 0 0 0 1.0 1.0\n3 0 1 2\n3 0 2 3\n");
  const diffuv::Painted_labels p = diffuv::read_painted_labels(file);
  EXPECT_EQ(p.source, Label_source::vertex_colors);
  EXPECT_EQ(p.property, "rgb");
  EXPECT_EQ(p.polygon_labels, (std::vector<int>{1, 0}));
  EXPECT_EQ(p.colors, (std::vector<Color>{{0, 0, 255}, {255, 0, 0}}));

  // Without colours, and for OBJ and STL: none.
  const std::string plain = write("plain.off", "OFF\n4 2 0\n" + square_points + "3 0 1 2\n3 0 2 3\n");
  EXPECT_EQ(diffuv::read_painted_labels(plain).source, Label_source::none);
  const diffuv::Painted_labels obj =
    diffuv::read_painted_labels(write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_EQ(obj.source, Label_source::none);
  EXPECT_TRUE(obj.polygon_labels.empty());
  EXPECT_EQ(diffuv::read_painted_labels(diffuv_test::data_path("meshes/sphere.stl")).source, Label_source::none);
  EXPECT_EQ(diffuv::read_painted_labels(diffuv_test::data_path("meshes/cow.off")).source, Label_source::none);
}

TEST_F(LabelsPainted, ReadReportSaysWhenTheFileCanHoldNoRegions)
{
  // read_triangle_mesh() says where read_painted_labels() would find nothing
  // (so the tool skips that second read): OBJ, STL and OFF without a colour.
  // Wherever painted regions are found, the report must not have said no.
  const std::string plain = write("plain.off", "OFF\n4 2 0\n" + square_points + "3 0 1 2\n3 0 2 3\n");
  const std::string face_colors =
    write("faces.off", "OFF\n4 2 0\n" + square_points + "3 0 1 2 200 10 10 255\n3 0 2 3 20 20 200 255\n");
  const std::string vertex_colors = write("c.off", "COFF\n4 2 0\n0 0 0 1.0 0.0 0.0 1.0\n1 0 0 1.0 0.0 0.0 1.0\n"
                                                   "1 1 0 0.0 0.0 1.0 1.0\n0 1 0 0 0 1.0 1.0\n3 0 1 2\n3 0 2 3\n");
  const std::string obj = write("t.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n");
  const std::vector<std::pair<std::string, bool>> files = {
      {plain, false},
      {face_colors, true},
      {vertex_colors, true},
      {obj, false},
      {diffuv_test::data_path("meshes/cow.off"), false},
      {diffuv_test::data_path("meshes/sphere.stl"), false},
      {diffuv_test::data_path("meshes/mesh_with_colors.off"), true},
      {diffuv_test::data_path("meshes/colored_tetra.ply"), true}};
  for(const auto& [file, may_hold] : files) {
    Mesh mesh;
    const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(file, mesh);
    EXPECT_EQ(report.may_hold_regions, may_hold) << file;
    if(!report.may_hold_regions) EXPECT_EQ(diffuv::read_painted_labels(file).source, Label_source::none) << file;
  }
  // And over CGAL's OFF meshes: a file without colours paints nothing.
  std::size_t without = 0;
  for(const char* name : {"elephant.off", "mushroom.off", "nefertiti.off", "3torus.off", "mesh_with_colors.off"}) {
    const std::string file = diffuv_test::data_path(std::string("meshes/") + name);
    Mesh mesh;
    const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(file, mesh);
    if(report.may_hold_regions) continue;
    ++without;
    EXPECT_EQ(diffuv::read_painted_labels(file).source, Label_source::none) << name;
  }
  EXPECT_EQ(without, 4u);
}

TEST_F(LabelsPaintedErrors, Off)
{
  const std::string head = "OFF\n4 2 0\n" + square_points;
  diffuv::Input_error e = painted_error(write("a.off", head + "3 0 1 2 255 0 0\n3 0 2 3 300 0 0\n"));
  EXPECT_EQ(e.reason(), "face 1 has colour component 300, outside [0, 255] (integers)");
  EXPECT_EQ(e.line(), 8u);
  e = painted_error(write("b.off", head + "3 0 1 2 1.5 0 0\n3 0 2 3 0 0 1\n"));
  EXPECT_EQ(e.reason(), "face 0 has colour component 1.5, outside [0, 1]");
  EXPECT_EQ(e.line(), 7u);
  EXPECT_EQ(painted_error(write("c.off", head + "3 0 1 2 1 0\n3 0 2 3 1 0\n")).reason(),
            "face 0 has 2 colour components; expected 3 or 4");
  EXPECT_EQ(painted_error(write("d.off", head + "3 0 1 2 7\n3 0 2 3 7\n")).reason(),
            "face 0 has a colour-map index; colour maps are not supported");
  e = painted_error(write("e.off", head + "3 0 1 2 255 0 0\n3 0 2 3\n"));
  EXPECT_EQ(e.reason(), "face 1 has no colour, but face 0 has one");
  EXPECT_EQ(e.line(), 8u);
  EXPECT_EQ(painted_error(write("f.off", head + "3 0 1 2\n3 0 2 3 0 0 255\n")).reason(),
            "face 1 has a colour, but face 0 has none");
  EXPECT_EQ(painted_error(write("g.off", head + "3 0 1 2 255 0 0\n")).reason(),
            "not a valid OFF file (the file ends before face 1 of 2)");
  EXPECT_EQ(painted_error(write("h.off", "COFF\n4 2 0\n" + square_points + "3 0 1 2\n3 0 2 3 9\n")).reason(),
            "face 1 has a colour-map index; colour maps are not supported");
  EXPECT_EQ(painted_error(path("missing.off")).reason(), "cannot open file");
  EXPECT_EQ(painted_error(write("x.txt", "1\n")).reason(),
            "unknown mesh file extension \".txt\" (expected .off, .obj, .ply or .stl)");
  EXPECT_EQ(painted_error(write("i.off", head + "3 0 1 2\n3 0 2 3\n"), "label").reason(),
            "the file has no face or vertex property \"label\"");
}

// ---------------------------------------------------------------------------
// PLY as MeshLab and Blender write it

// Bytes of a binary PLY, little- or big-endian.
struct Bytes {
  bool big;
  std::string s;
  void put(const void* p, std::size_t n)
  {
    const std::uint16_t probe = 1;
    unsigned char host_little;
    std::memcpy(&host_little, &probe, 1);
    std::string b(static_cast<const char*>(p), n);
    if(big == (host_little == 1))
      std::reverse(b.begin(), b.end());
    s += b;
  }
  void f32(float v) { put(&v, 4); }
  void i32(std::int32_t v) { put(&v, 4); }
  void u8(std::uint8_t v) { put(&v, 1); }
};

std::string meshlab_ply(bool big)
{
  Bytes b{big, "ply\nformat " + std::string(big ? "binary_big_endian" : "binary_little_endian") +
                   " 1.0\ncomment VCGLIB generated\nelement vertex 4\nproperty float x\nproperty float y\n"
                   "property float z\nelement face 2\nproperty list uchar int vertex_indices\nproperty uchar red\n"
                   "property uchar green\nproperty uchar blue\nproperty uchar alpha\nend_header\n"};
  const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for(const auto& p : xyz)
    for(float c : p)
      b.f32(c);
  const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  const std::uint8_t rgba[2][4] = {{10, 200, 30, 255}, {10, 200, 29, 255}};
  for(int j = 0; j < 2; ++j) {
    b.u8(3);
    for(int i : faces[j])
      b.i32(i);
    for(std::uint8_t c : rgba[j])
      b.u8(c);
  }
  return b.s;
}

TEST_F(LabelsPainted, MeshLabBinaryPlyFaceColors)
{
  for(bool big : {false, true}) {
    const std::string file = write("m.ply", meshlab_ply(big));
    const diffuv::Painted_labels p = diffuv::read_painted_labels(file);
    EXPECT_EQ(p.source, Label_source::face_colors) << big;
    EXPECT_EQ(p.property, "red/green/blue");
    EXPECT_EQ(p.polygon_labels, (std::vector<int>{1, 0})) << big;
    EXPECT_EQ(p.colors, (std::vector<Color>{{10, 200, 29}, {10, 200, 30}})) << big;
    Mesh mesh; // the mesh reader reads the same file
    EXPECT_EQ(diffuv::read_triangle_mesh(file, mesh).faces_in_file, 2u);
  }
  std::string cut = meshlab_ply(false);
  cut.resize(cut.size() - 3);
  const diffuv::Input_error e = painted_error(write("cut.ply", cut));
  EXPECT_EQ(e.reason(), "not a valid PLY file (the file ends in property \"green\" of face 1)");
  EXPECT_EQ(e.line(), 0u);
}

// A PLY as Blender exports it: vertex colours (with alpha), normals and uv,
// uint indices; text (format 0), little-endian (1) or big-endian (2, not
// Blender's). A quad and a triangle; vertices red red blue red blue.
std::string blender_ply(int format)
{
  const char* formats[] = {"ascii", "binary_little_endian", "binary_big_endian"};
  Bytes b{format == 2, "ply\nformat " + std::string(formats[format]) +
                           " 1.0\ncomment Created in Blender version 4.1.0\n"
                           "element vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                           "property float nx\nproperty float ny\nproperty float nz\n"
                           "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                           "property uchar alpha\nproperty float s\nproperty float t\n"
                           "element face 2\nproperty list uchar uint vertex_indices\nend_header\n"};
  const float xy[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}};
  const bool red[5] = {true, true, false, true, false};
  const std::vector<std::vector<std::uint32_t>> faces = {{0, 1, 2, 3}, {1, 4, 2}};
  std::ostringstream text;
  for(int i = 0; i < 5; ++i) {
    const float v[8] = {xy[i][0], xy[i][1], 0, 0, 0, 1, xy[i][0], xy[i][1]};
    const std::uint8_t rgba[4] = {std::uint8_t(red[i] ? 255 : 0), 0, std::uint8_t(red[i] ? 0 : 255), 255};
    for(int k = 0; k < 6; ++k)
      format ? b.f32(v[k]) : void(text << v[k] << ' ');
    for(std::uint8_t c : rgba)
      format ? b.u8(c) : void(text << int(c) << ' ');
    for(int k = 6; k < 8; ++k)
      format ? b.f32(v[k]) : void(text << v[k] << (k == 7 ? '\n' : ' '));
  }
  for(const auto& f : faces) {
    format ? b.u8(std::uint8_t(f.size())) : void(text << f.size());
    for(std::uint32_t i : f)
      format ? b.put(&i, 4) : void(text << ' ' << i);
    if(!format)
      text << '\n';
  }
  return b.s + text.str();
}

TEST_F(LabelsPainted, BlenderPlyVertexColors)
{
  // Vertex labels by colour: blue (0,0,255) = 0, red = 1: 1 1 0 1 0.
  // Quad (1, 1, 0, 1) -> 1; triangle 1 4 2 (1, 0, 0) -> 0.
  for(int format : {0, 1, 2}) {
    const diffuv::Painted_labels p = diffuv::read_painted_labels(write("b.ply", blender_ply(format)));
    EXPECT_EQ(p.source, Label_source::vertex_colors) << format;
    EXPECT_EQ(p.property, "red/green/blue");
    EXPECT_EQ(p.polygon_labels, (std::vector<int>{1, 0})) << format;
    EXPECT_EQ(p.colors, (std::vector<Color>{{0, 0, 255}, {255, 0, 0}})) << format;
  }
}

// An ascii PLY of a square cut in two, with optional vertex and face properties.
std::string property_ply(const std::string& vertex_property, const std::string vertex_values[4],
                         const std::string& face_property, const std::string face_values[2])
{
  std::string s = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n";
  if(!vertex_property.empty())
    s += "property " + vertex_property + "\n";
  s += "element face 2\nproperty list uchar int vertex_indices\n";
  if(!face_property.empty())
    s += "property " + face_property + "\n";
  s += "end_header\n";
  const char* xyz[4] = {"0 0 0", "1 0 0", "1 1 0", "0 1 0"};
  for(int i = 0; i < 4; ++i)
    s += std::string(xyz[i]) + (vertex_property.empty() ? "" : " " + vertex_values[i]) + "\n";
  const char* faces[2] = {"3 0 1 2", "3 0 2 3"};
  for(int j = 0; j < 2; ++j)
    s += std::string(faces[j]) + (face_property.empty() ? "" : " " + face_values[j]) + "\n";
  return s;
}

TEST_F(LabelsPainted, IntegerProperties)
{
  const std::string regions[4] = {"5", "5", "6", "6"}, none[4];
  const std::string segments[2] = {"4", "7"};
  // A face property first.
  diffuv::Painted_labels p =
    diffuv::read_painted_labels(write("a.ply", property_ply("int region", regions, "int segment", segments)));
  EXPECT_EQ(p.source, Label_source::face_property);
  EXPECT_EQ(p.property, "segment");
  EXPECT_EQ(p.polygon_labels, (std::vector<int>{4, 7}));
  EXPECT_TRUE(p.colors.empty());
  // Then a vertex property: (5, 5, 6) -> 5, (5, 6, 6) -> 6.
  p = diffuv::read_painted_labels(write("b.ply", property_ply("int region", regions, "", segments)));
  EXPECT_EQ(p.source, Label_source::vertex_property);
  EXPECT_EQ(p.property, "region");
  EXPECT_EQ(p.polygon_labels, (std::vector<int>{5, 6}));
  // MeshLab's quality is a float: used when its values are whole numbers...
  const std::string whole[2] = {"2", "3.0"}, fractional[2] = {"2.5", "3"};
  p = diffuv::read_painted_labels(write("c.ply", property_ply("int region", regions, "float quality", whole)));
  EXPECT_EQ(p.source, Label_source::face_property);
  EXPECT_EQ(p.property, "quality");
  EXPECT_EQ(p.polygon_labels, (std::vector<int>{2, 3}));
  // ... and skipped otherwise (it is not a labelling), unless asked for.
  const std::string d = write("d.ply", property_ply("int region", regions, "float quality", fractional));
  EXPECT_EQ(diffuv::read_painted_labels(d).source, Label_source::vertex_property);
  const diffuv::Input_error e = painted_error(d, "quality");
  EXPECT_EQ(e.reason(), "face 0 has value 2.5 in property \"quality\", not an integer label");
  EXPECT_EQ(e.line(), 16u);
  // An unknown name is not a label property, unless asked for.
  const std::string f = write("f.ply", property_ply("", none, "ushort my_regions", segments));
  EXPECT_EQ(diffuv::read_painted_labels(f).source, Label_source::none);
  p = diffuv::read_painted_labels(f, "MY_REGIONS");
  EXPECT_EQ(p.source, Label_source::face_property);
  EXPECT_EQ(p.property, "my_regions");
  EXPECT_EQ(p.polygon_labels, (std::vector<int>{4, 7}));
  EXPECT_EQ(painted_error(f, "label").reason(), "the file has no face or vertex property \"label\"");
}

TEST_F(LabelsPainted, VertexPropertyBeforeVertexColors)
{
  const std::string values[4] = {"0 255 0 0", "0 255 0 0", "3 0 0 255", "3 0 0 255"}, none[2];
  const std::string properties = "int label\nproperty uint8 Red\nproperty uint8 green\nproperty uint8 blue";
  const std::string file = write("v.ply", property_ply(properties, values, "", none));
  const diffuv::Painted_labels p = diffuv::read_painted_labels(file);
  EXPECT_EQ(p.source, Label_source::vertex_property);
  EXPECT_EQ(p.property, "label");
  EXPECT_EQ(p.polygon_labels, (std::vector<int>{0, 3}));
}

TEST_F(LabelsPaintedErrors, Ply)
{
  const std::string regions[4] = {"5", "5", "6", "6"}, none[4];
  const std::string negative[2] = {"4", "-1"}, huge[2] = {"4", "4294967295"};
  diffuv::Input_error e = painted_error(write("a.ply", property_ply("", none, "int segment", negative)));
  EXPECT_EQ(e.reason(), "face 1 has label -1 (property \"segment\"); labels are non-negative integers");
  EXPECT_EQ(e.line(), 16u);
  EXPECT_EQ(painted_error(write("b.ply", property_ply("", none, "uint segment", huge))).reason(),
            "face 1 has label 4294967295 (property \"segment\"), out of range");
  const std::string colors[4] = {"255 0 0", "255 0 0", "0 0 1.5", "0 0 255"};
  e = painted_error(write("c.ply", property_ply("float red\nproperty float green\nproperty float blue", colors, "",
                                                none)));
  EXPECT_EQ(e.reason(), "vertex 0 has colour component 255, outside [0, 1]");
  EXPECT_EQ(e.line(), 13u);
  // A vertex index out of range matters for vertex sources.
  std::string bad = property_ply("int region", regions, "", none);
  bad.replace(bad.find("3 0 2 3"), 7, "3 0 2 9");
  e = painted_error(write("d.ply", bad));
  EXPECT_EQ(e.reason(), "face 1 has vertex index 9, out of range (the file has 4 vertices)");
  EXPECT_EQ(e.line(), 16u);

  EXPECT_EQ(painted_error(write("e.ply", "plx\n")).reason(),
            "not a valid PLY file (the file does not start with \"ply\")");
  e = painted_error(write("f.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty half x\nend_header\n"));
  EXPECT_EQ(e.reason(), "not a valid PLY file (cannot read the property line \"property half x\")");
  EXPECT_EQ(e.line(), 4u);
  EXPECT_EQ(painted_error(write("g.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n")).reason(),
            "not a valid PLY file (the header has no end_header line)");
  e = painted_error(write("h.ply", "ply\nformat ascii 1.0\nelement vertex 1000\nproperty float x\nend_header\n1\n"));
  EXPECT_EQ(e.reason(), "not a valid PLY file (the header announces 1000 vertex items, more than the file can hold)");
  EXPECT_EQ(e.line(), 3u);
  e = painted_error(write("i.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nend_header\n1\nz\n"));
  EXPECT_EQ(e.reason(), "not a valid PLY file (cannot read property \"x\" of vertex 1)");
  EXPECT_EQ(e.line(), 7u);
}

// ---------------------------------------------------------------------------
// Per-vertex labels

TEST(LabelsVertexRule, MajorityThenSmallest)
{
  const std::vector<int> vertex_labels = {3, 3, 1, 2, 2, 7};
  const Polygons polygons = {{0, 1, 2},    // 3 3 1: majority 3
                             {1, 2, 3},    // 3 1 2: all differ, smallest 1
                             {0, 2, 3, 4}, // 3 1 2 2: 2
                             {0, 1, 3, 4}, // 3 3 2 2: tie, smallest 2
                             {2, 5, 0, 1}, // 1 7 3 3: 3
                             {5, 5, 5}};
  const std::vector<int> expected = {3, 1, 2, 2, 3, 7};
  EXPECT_EQ(diffuv::vertex_labels_to_polygons(vertex_labels, polygons), expected);
  // Independent of the order of the vertices.
  for(std::size_t j = 0; j < polygons.size(); ++j) {
    std::vector<std::size_t> p = polygons[j];
    std::sort(p.begin(), p.end());
    do
      EXPECT_EQ(diffuv::vertex_labels_to_polygons(vertex_labels, Polygons{p}), std::vector<int>{expected[j]});
    while(std::next_permutation(p.begin(), p.end()));
  }
  EXPECT_EQ(diffuv_test::error_text<diffuv::Error>([&] { diffuv::vertex_labels_to_polygons(vertex_labels, Polygons{{0, 6, 1}}); }),
            "polygon 0 has vertex index 6, but there are 6 vertex labels");
  const std::vector<std::vector<int>> signed_polygons = {{0, 1, 2}, {-1}};
  EXPECT_EQ(diffuv_test::error_text<diffuv::Error>([&] { diffuv::vertex_labels_to_polygons(vertex_labels, signed_polygons); }),
            "polygon 1 has vertex index -1, but there are 6 vertex labels");
  EXPECT_EQ(diffuv_test::error_text<diffuv::Error>([&] { diffuv::vertex_labels_to_polygons(vertex_labels, Polygons{{}}); }),
            "polygon 0 has no vertex");
}

// Painting: few colours, each one area. A scan: a colour per face, or a few
// colours scattered at random.
TEST(PaintLook, PaintingAndScansAreToldApart)
{
  const Mesh& cow = diffuv_test::cgal_mesh("cow.off");
  double low = 1e300, high = -1e300;
  for(auto v : vertices(cow)) {
    low = std::min(low, cow.point(v).y());
    high = std::max(high, cow.point(v).y());
  }
  std::vector<int> bands(num_faces(cow));
  for(auto f : faces(cow)) {
    const double y = cow.point(target(halfedge(f, cow), cow)).y();
    bands[f.idx()] = std::min(3, static_cast<int>(4 * (y - low) / (high - low)));
  }
  const diffuv::Paint_look painted = diffuv::look_of_paint(cow, bands);
  EXPECT_TRUE(painted.painted);
  EXPECT_EQ(painted.colors, 4u);
  EXPECT_GE(painted.areas, 4u); // legs and horns make a band several areas
  EXPECT_LE(painted.areas, 2u * 4u + 16u);

  std::vector<int> own(num_faces(cow));
  for(std::size_t f = 0; f < own.size(); ++f) own[f] = static_cast<int>(f);
  const diffuv::Paint_look every_face = diffuv::look_of_paint(cow, own);
  EXPECT_FALSE(every_face.painted);
  EXPECT_EQ(every_face.colors, num_faces(cow));
  EXPECT_EQ(every_face.areas, num_faces(cow));

  std::vector<int> scattered(num_faces(cow));
  for(std::size_t f = 0; f < scattered.size(); ++f) scattered[f] = static_cast<int>(f * 7919 % 13);
  const diffuv::Paint_look speckled = diffuv::look_of_paint(cow, scattered);
  EXPECT_FALSE(speckled.painted);
  EXPECT_EQ(speckled.colors, 13u);
  EXPECT_GT(speckled.areas, 2u * 13u + 16u);

  // One colour: one area, painted.
  EXPECT_TRUE(diffuv::look_of_paint(cow, std::vector<int>(num_faces(cow), 0)).painted);
}

} // namespace
