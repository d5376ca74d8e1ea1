// Tests of `diffuv segment`: the patches it writes read back as labels and as
// paint; flat triangles handed to a neighbour.
#include "test_cli_tool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

using namespace diffuv_cli_test;

TEST_F(Tool, SegmentWritesPatchesThatReadBackAsLabelsAndAsPaint)
{
  const Tool_run seg = run("segment " + data_path("meshes/cow.off") + " -o " + out_dir().string());
  ASSERT_EQ(seg.code, 0) << seg.err;
  const fs::path labels = out_dir() / "cow.patches.txt";
  const fs::path ply = out_dir() / "cow.patches.ply";
  ASSERT_TRUE(fs::exists(labels));
  ASSERT_TRUE(fs::exists(ply));

  // The label file as --labels: the same patches come back (same count, none cut or split).
  const Tool_run with_labels = run("param " + data_path("meshes/cow.off") + " --labels " + labels.string() + " -o " +
                                   (dir_ / "a").string());
  ASSERT_EQ(with_labels.code, 0) << with_labels.err;
  EXPECT_NE(with_labels.out.find("(the regions, kept whole)"), std::string::npos) << with_labels.out;
  EXPECT_TRUE(slurp(dir_ / "a" / "cow.patches.txt") == slurp(labels));

  // The coloured PLY as the mesh: its painted regions are used, same patches.
  const Tool_run painted = run("param " + ply.string() + " -o " + (dir_ / "b").string());
  ASSERT_EQ(painted.code, 0) << painted.err;
  EXPECT_NE(painted.out.find("painted"), std::string::npos) << painted.out;
  // Outputs named once (issue #19): after the PLY, whose name ends in .patches already.
  EXPECT_TRUE(slurp(dir_ / "b" / "cow.patches.txt") == slurp(labels));
  EXPECT_TRUE(fs::exists(dir_ / "b" / "cow.patches.obj"));
  for(const auto& e : fs::directory_iterator(dir_ / "b"))
    EXPECT_EQ(e.path().filename().string().find("patches.patches"), std::string::npos) << e.path();
}

// Issue #5: a face left flat by its sides that no corners can mend (a small
// patch of anchor with more ears than corners) goes to a neighbouring patch;
// --keep-flat-triangles keeps it (and says nothing).
TEST_F(Tool, SegmentHandsFlatFacesToANeighbourUnlessKept)
{
  const std::string anchor = data_path("meshes/anchor.off");
  const Tool_run handed = run("segment " + anchor + " -o " + (dir_ / "a").string());
  ASSERT_EQ(handed.code, 0) << handed.err;
  const auto clause = handed.out.find(" handed to a neighbour");
  ASSERT_NE(clause, std::string::npos) << handed.out;
  const auto noun = handed.out.rfind(" flat triangle", clause);
  ASSERT_NE(noun, std::string::npos) << handed.out;
  const std::size_t count = std::stoul(handed.out.substr(handed.out.rfind(' ', noun - 1) + 1));
  EXPECT_GT(count, 0u);
  const Tool_run kept = run("segment " + anchor + " --keep-flat-triangles -o " + (dir_ / "b").string());
  ASSERT_EQ(kept.code, 0) << kept.err;
  EXPECT_EQ(kept.out.find("handed"), std::string::npos) << kept.out;

  // The two label files differ in exactly the faces handed.
  std::istringstream a(slurp(dir_ / "a" / "anchor.patches.txt")), b(slurp(dir_ / "b" / "anchor.patches.txt"));
  std::string la, lb;
  std::size_t lines = 0, different = 0;
  while(std::getline(a, la) && std::getline(b, lb)) {
    ++lines;
    different += la != lb;
  }
  EXPECT_EQ(lines, 1050u);
  EXPECT_EQ(different, count);
}

TEST_F(Tool, PatchesOfAPolygonMeshReadBackAsLabels)
{
  // cube_quad.off has quads: patches.txt has one line per quad, the file's faces.
  const Tool_run seg = run("segment " + data_path("meshes/cube_quad.off") + " -o " + out_dir().string());
  ASSERT_EQ(seg.code, 0) << seg.err;
  const fs::path labels = out_dir() / "cube_quad.patches.txt";
  std::ifstream in(labels);
  std::size_t lines = 0;
  for(std::string l; std::getline(in, l);) ++lines;
  EXPECT_EQ(lines, 6u);
  const Tool_run param = run("param " + data_path("meshes/cube_quad.off") + " --labels " + labels.string() + " -o " +
                             (dir_ / "p").string());
  EXPECT_EQ(param.code, 0) << param.err;
}

// Counts agree in number (issue #19): a disc was "1 patches".
TEST_F(Tool, SegmentCountsAgreeInNumber)
{
  const Tool_run r = run("segment " + write("m.off", grid_off) + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(": 9 vertices, 8 faces\n1 patch (the whole disc), 8 faces; "), std::string::npos)
      << r.out;
  EXPECT_EQ(r.err, "") << "no face has zero area";
}

// segment warns of a face of zero area as param does (issue #19: it said
// nothing), and still writes its files.
TEST_F(Tool, SegmentWarnsOfAFaceOfZeroArea)
{
  const std::string mesh = write("flat.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n2 0 0\n1 1 0\n0 1 0\n3 0 1 3\n3 1 2 3\n3 0 2 1\n");
  const Tool_run r = run("segment " + mesh + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "diffuv: warning: " + mesh + ": 1 face has zero area; its (u,v) triangle may be flat\n");
  EXPECT_TRUE(fs::exists(out_dir() / "flat.patches.txt"));
}

// A disc whose map as one patch is good stays whole; --patches lays it out
// (issue #18), except with the Voronoi layout, where the tool says the option
// had no effect. A disc that one square would not serve (lion-head: its map
// folds, the repair moved every vertex) is laid out by default. On a closed
// mesh nothing is said.
TEST_F(Tool, PatchesOnADiscLayItOut)
{
  const std::string disc = data_path("meshes/nefertiti.off");
  const Tool_run whole = run("segment " + disc + " -o " + (dir_ / "a").string());
  ASSERT_EQ(whole.code, 0) << whole.err;
  EXPECT_NE(whole.out.find("\n1 patch (the whole disc), 562 faces; kept whole: its map as one patch is good\n"), std::string::npos)
      << whole.out;
  const Tool_run asked = run("segment " + disc + " --patches 5 -o " + (dir_ / "b").string());
  ASSERT_EQ(asked.code, 0) << asked.err;
  EXPECT_EQ(asked.err, "");
  EXPECT_EQ(asked.out.find("1 patch (the whole disc)"), std::string::npos) << asked.out;
  EXPECT_NE(asked.out.find(", 1 disc laid out (--patches given)\n"), std::string::npos) << asked.out;
  const Tool_run voronoi = run("segment " + disc + " --patches 5 --layout voronoi -o " + (dir_ / "c").string());
  ASSERT_EQ(voronoi.code, 0) << voronoi.err;
  EXPECT_EQ(voronoi.err, "diffuv: warning: --patches 5 has no effect on " + disc +
                             ": the mesh is a disc, and a disc is one patch\n");
  const Tool_run relief = run("segment " + data_path("meshes/lion-head.off") + " -o " + (dir_ / "d").string());
  ASSERT_EQ(relief.code, 0) << relief.err;
  EXPECT_NE(relief.out.find(", 1 disc laid out (as one patch its map would fold or stretch)\n"), std::string::npos)
      << relief.out;
  const Tool_run closed = run("segment " + data_path("meshes/cow.off") + " --patches 5 -o " + (dir_ / "e").string());
  ASSERT_EQ(closed.code, 0) << closed.err;
  EXPECT_EQ(closed.err, "");
}

// Issue #21: vertex colours are regions only when they look painted. Cow as
// COFF, its vertices coloured in four height bands (painting) or each with a
// colour of its own (a scan, a transferred field).
TEST_F(Tool, VertexColoursAreRegionsOnlyWhenTheyLookPainted)
{
  const diffuv_test::File_soup cow = diffuv_test::parse_off(data_path("meshes/cow.off"));
  double low = 1e300, high = -1e300;
  for(const auto& p : cow.points) {
    low = std::min(low, p[1]);
    high = std::max(high, p[1]);
  }
  const auto write_coff = [&](const std::string& name, auto color_of) {
    std::ostringstream off;
    off.precision(17);
    off << "COFF\n" << cow.points.size() << ' ' << cow.faces.size() << " 0\n";
    for(std::size_t i = 0; i < cow.points.size(); ++i) {
      const auto c = color_of(i);
      off << cow.points[i][0] << ' ' << cow.points[i][1] << ' ' << cow.points[i][2] << ' ' << c[0] << ' ' << c[1] << ' '
          << c[2] << " 255\n";
    }
    for(const auto& f : cow.faces) off << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
    return write(name, off.str());
  };
  const std::string bands = write_coff("bands.off", [&](std::size_t i) {
    const int band = std::min(3, static_cast<int>(4 * (cow.points[i][1] - low) / (high - low)));
    return std::array<int, 3>{{60 * band, 200, 100}};
  });
  const std::string scan = write_coff("scan.off", [](std::size_t i) {
    return std::array<int, 3>{{static_cast<int>(i % 256), static_cast<int>(i / 256 % 256), 7}};
  });

  const Tool_run painted = run("segment " + bands + " -o " + (dir_ / "a").string());
  ASSERT_EQ(painted.code, 0) << painted.err;
  EXPECT_NE(painted.out.find("regions painted in the mesh file"), std::string::npos) << painted.out;
  EXPECT_EQ(painted.err, "");

  const Tool_run scanned = run("segment " + scan + " -o " + (dir_ / "b").string());
  ASSERT_EQ(scanned.code, 0) << scanned.err;
  EXPECT_EQ(scanned.out.find("painted"), std::string::npos) << scanned.out;
  EXPECT_EQ(scanned.err.rfind("diffuv: warning: " + scan + ": " + std::to_string(cow.points.size()) +
                                  " distinct vertex colours, taken by the faces as ", 0), 0u) << scanned.err;
  EXPECT_NE(scanned.err.find("areas: not taken as regions (--regions-from colors takes them)\n"), std::string::npos)
      << scanned.err;
  // The same patches as the mesh without colours.
  const Tool_run plain = run("segment " + data_path("meshes/cow.off") + " -o " + (dir_ / "c").string());
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_TRUE(slurp(dir_ / "b" / "scan.patches.txt") == slurp(dir_ / "c" / "cow.patches.txt"));

  // Asked for: the scan's colours are regions (and merged where too small to map).
  const Tool_run forced = run("segment " + scan + " --regions-from colors -o " + (dir_ / "d").string());
  ASSERT_EQ(forced.code, 0) << forced.err;
  EXPECT_NE(forced.out.find("regions painted in the mesh file"), std::string::npos) << forced.out;
  // Painting ignored on request.
  const Tool_run ignored = run("segment " + bands + " --regions-from none -o " + (dir_ / "e").string());
  ASSERT_EQ(ignored.code, 0) << ignored.err;
  EXPECT_EQ(ignored.out.find("painted"), std::string::npos) << ignored.out;
  EXPECT_TRUE(slurp(dir_ / "e" / "bands.patches.txt") == slurp(dir_ / "c" / "cow.patches.txt"));
}

} // namespace
