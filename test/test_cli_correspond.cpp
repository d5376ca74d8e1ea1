// Tests of `diffuv correspond`: cow and a shuffled, moved copy of it, mapped
// vertex by vertex through matching labels; a coarse copy with carried labels.
#include "test_cli_tool.h"
#include "test_remeshed_copy.h"

#include <diffuv/core/color.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace diffuv_cli_test;

// ---- diffuv correspond -------------------------------------------------------

// Cow written as OFF (A), and a copy with vertices and faces shuffled, each face
// listed from a random corner, rotated, scaled by 2 and moved (B), with the
// face labels of `diffuv segment` carried over. Optionally B has vertex colours.
class Correspond : public Tool {
protected:
  void SetUp() override
  {
    Tool::SetUp();
    if(IsSkipped()) return;  // built without the tool
    const auto& m = diffuv_test::cgal_mesh("cow.off");
    nv_ = num_vertices(m);
    std::ostringstream a;
    a.precision(17);
    a << "OFF\n" << nv_ << ' ' << num_faces(m) << " 0\n";
    for(auto v : vertices(m)) a << m.point(v).x() << ' ' << m.point(v).y() << ' ' << m.point(v).z() << '\n';
    std::vector<std::array<std::size_t, 3>> faces_a;
    for(auto f : faces(m)) {
      std::array<std::size_t, 3> t{};
      int k = 0;
      for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) t[k++] = v.idx();
      faces_a.push_back(t);
      a << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
    a_ = write("a.off", a.str());
    // Region-sized labels, as a user paints them: the Voronoi layout's patches.
    const Tool_run seg = run("segment " + a_ + " --layout voronoi -o " + path("seg"));
    ASSERT_EQ(seg.code, 0) << seg.err;
    std::vector<int> labels;
    std::ifstream in(path("seg") + "/a.patches.txt");
    for(int l; in >> l;) labels.push_back(l);
    ASSERT_EQ(labels.size(), faces_a.size());

    std::mt19937 rng(17);
    std::vector<std::size_t> vperm(nv_), fperm(faces_a.size());
    std::iota(vperm.begin(), vperm.end(), 0);
    std::iota(fperm.begin(), fperm.end(), 0);
    std::shuffle(vperm.begin(), vperm.end(), rng); // B's vertex k is A's vertex vperm[k]
    std::shuffle(fperm.begin(), fperm.end(), rng); // B's face k is A's face fperm[k]
    copy_of_.assign(nv_, 0);
    for(std::size_t k = 0; k < nv_; ++k) copy_of_[vperm[k]] = k;
    b_points_.resize(nv_);
    for(std::size_t k = 0; k < nv_; ++k) {
      const auto& p = m.point(Mesh_vertex(static_cast<std::uint32_t>(vperm[k])));
      b_points_[k] = {{-2. * p.y() + 5., 2. * p.x(), 2. * p.z() - 3.}}; // a quarter turn, twice the size
    }
    for(std::size_t k = 0; k < fperm.size(); ++k) {
      const auto& t = faces_a[fperm[k]];
      const std::size_t start = rng() % 3;
      b_faces_.push_back({{copy_of_[t[start]], copy_of_[t[(start + 1) % 3]], copy_of_[t[(start + 2) % 3]]}});
      b_labels_.push_back(labels[fperm[k]]);
    }
    labels_a_ = path("seg") + "/a.patches.txt";
  }

  std::string write_b(bool colors, const std::string& name = "b.off")
  {
    std::ostringstream b;
    b.precision(17);
    b << (colors ? "COFF\n" : "OFF\n") << nv_ << ' ' << b_faces_.size() << " 0\n";
    for(std::size_t k = 0; k < nv_; ++k) {
      b << b_points_[k][0] << ' ' << b_points_[k][1] << ' ' << b_points_[k][2];
      if(colors) b << ' ' << k % 256 << " 50 200 255";
      b << '\n';
    }
    for(const auto& t : b_faces_) b << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    return write(name, b.str());
  }
  std::string write_labels(const std::vector<int>& labels, const std::string& name)
  {
    std::ostringstream out;
    for(int l : labels) out << l << '\n';
    return write(name, out.str());
  }

  using Mesh_vertex = diffuv_test::Mesh::Vertex_index;
  std::size_t nv_ = 0;
  std::string a_, labels_a_;
  std::vector<std::size_t> copy_of_;                 // A's vertex -> B's vertex
  std::vector<std::array<double, 3>> b_points_;
  std::vector<std::array<std::size_t, 3>> b_faces_;  // as listed in b.off
  std::vector<int> b_labels_;
};

TEST_F(Correspond, ShuffledMovedCopyMapsEveryVertexOntoItsCopy)
{
  const std::string b = write_b(false);
  const std::string labels_b = write_labels(b_labels_, "b.labels.txt");
  const Tool_run r = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --labels-b " + labels_b +
                         " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("vertices mapped: " + std::to_string(nv_) + " of " + std::to_string(nv_)), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("regions matched: "), std::string::npos) << r.out;
  const auto rows = read_csv(out_dir() / "correspondence.csv");
  ASSERT_EQ(rows.size(), nv_ + 1);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"vertex", "face", "b0", "b1", "b2", "x", "y", "z"}));
  double worst_point = 0, worst_weights = 0;
  for(std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 8u) << i;
    EXPECT_EQ(std::stoul(rows[i][0]), i - 1);
    const auto& truth = b_points_[copy_of_[i - 1]];
    const std::size_t face = std::stoul(rows[i][1]);
    ASSERT_LT(face, b_faces_.size());
    for(int k = 0; k < 3; ++k) {
      worst_point = std::max(worst_point, std::abs(std::stod(rows[i][5 + k]) - truth[k]));
      // b0..b2 weight the face's vertices in the order b.off lists them.
      double x = 0;
      for(int c = 0; c < 3; ++c) x += std::stod(rows[i][2 + c]) * b_points_[b_faces_[face][c]][k];
      worst_weights = std::max(worst_weights, std::abs(x - std::stod(rows[i][5 + k])));
    }
  }
  EXPECT_LT(worst_point, 1e-9);
  EXPECT_LT(worst_weights, 1e-9);
  EXPECT_TRUE(fs::exists(out_dir() / "transfer.ply"));
  EXPECT_TRUE(fs::exists(out_dir() / "reference.ply"));
}

// B's vertex colours land on A's vertices (each maps onto its copy), and
// --values rows are interpolated the same way.
TEST_F(Correspond, ColorsAndValuesAreCarriedToA)
{
  const std::string b = write_b(true, "b_colored.off");
  const std::string labels_b = write_labels(b_labels_, "b.labels.txt");
  std::ostringstream values;
  for(std::size_t k = 0; k < nv_; ++k) values << k << ' ' << 0.5 * k << '\n';
  const std::string values_file = write("values.txt", values.str());
  const Tool_run r = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --labels-b " + labels_b +
                         " --values " + values_file + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("B's vertex colours"), std::string::npos) << r.out;
  std::ifstream ply(out_dir() / "transfer.ply");
  std::string line;
  while(std::getline(ply, line) && line != "end_header") {}
  for(std::size_t i = 0; i < nv_; ++i) {
    double x, y, z;
    int red, green, blue;
    ASSERT_TRUE(ply >> x >> y >> z >> red >> green >> blue);
    EXPECT_EQ(red, static_cast<int>(copy_of_[i] % 256)) << i;
    EXPECT_EQ(green, 50);
    EXPECT_EQ(blue, 200);
  }
  std::ifstream out(out_dir() / "values.txt");
  std::getline(out, line); // comment
  for(std::size_t i = 0; i < nv_; ++i) {
    double first, second;
    ASSERT_TRUE(out >> first >> second);
    // The image's barycentric coordinates are exact to ~1e-9 (a point located in uv).
    EXPECT_NEAR(first, double(copy_of_[i]), 1e-8 * nv_);
    EXPECT_NEAR(second, 0.5 * copy_of_[i], 1e-8 * nv_);
  }
  // A values file with the wrong number of rows is refused, naming the file.
  const std::string short_file = write("short.txt", "1\n2\n");
  const Tool_run bad = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --labels-b " + labels_b +
                           " --values " + short_file + " -o " + path("bad_out"));
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("short.txt: the file has 2 rows, mesh B has " + std::to_string(nv_) + " vertices"),
            std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(path("bad_out")));
}

TEST_F(Correspond, MissingLabelsSayHowToProvideThem)
{
  const std::string b = write_b(false);
  // A command-line mistake points at the command's own help.
  const Tool_run usage = run("correspond " + a_ + ' ' + b + " --bogus");
  EXPECT_EQ(usage.code, 2);
  EXPECT_NE(usage.err.find("(see diffuv correspond --help)"), std::string::npos) << usage.err;

  const Tool_run none = run("correspond " + a_ + ' ' + b + " -o " + out_dir().string());
  EXPECT_EQ(none.code, 1);
  EXPECT_NE(none.err.find("a.off: the mesh has no region labels"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("--labels-a"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("diffuv segment"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(out_dir()));

  const Tool_run only_a = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " -o " + out_dir().string());
  EXPECT_EQ(only_a.code, 1);
  EXPECT_NE(only_a.err.find("b.off: the mesh has no region labels"), std::string::npos) << only_a.err;
  EXPECT_NE(only_a.err.find("--transfer-labels"), std::string::npos) << only_a.err;
  EXPECT_FALSE(fs::exists(out_dir()));

  // B moved away from A: labels by nearest face would all be wrong; refused.
  const Tool_run moved = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --transfer-labels -o " +
                             out_dir().string());
  EXPECT_EQ(moved.code, 1);
  EXPECT_EQ(moved.err.rfind("diffuv: error: " + b + ": does not lie on " + a_ + " (the median distance from its faces to A is ", 0), 0u)
      << moved.err;
  EXPECT_NE(moved.err.find("--labels-b"), std::string::npos) << moved.err;
  EXPECT_FALSE(fs::exists(out_dir()));

  // B on top of A (not moved): its labels can come from A's nearest faces.
  std::ostringstream on_top;
  on_top.precision(17);
  const auto& m = diffuv_test::cgal_mesh("cow.off");
  on_top << "OFF\n" << nv_ << ' ' << b_faces_.size() << " 0\n";
  std::vector<std::size_t> original_of(nv_);
  for(std::size_t i = 0; i < nv_; ++i) original_of[copy_of_[i]] = i;
  for(std::size_t k = 0; k < nv_; ++k) {
    const auto& p = m.point(Mesh_vertex(static_cast<std::uint32_t>(original_of[k])));
    on_top << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  for(const auto& t : b_faces_) on_top << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  const std::string b_on_top = write("b_on_top.off", on_top.str());
  const Tool_run transferred = run("correspond " + a_ + ' ' + b_on_top + " --labels-a " + labels_a_ +
                                   " --transfer-labels -o " + out_dir().string());
  ASSERT_EQ(transferred.code, 0) << transferred.err;
  EXPECT_NE(transferred.out.find("labels of A's nearest faces"), std::string::npos) << transferred.out;
  EXPECT_NE(transferred.out.find("vertices mapped: " + std::to_string(nv_) + " of"), std::string::npos) << transferred.out;
}

// A label that only one mesh has is reported, and its vertices get face -1.
TEST_F(Correspond, LabelsInOneMeshOnlyAreReported)
{
  const std::string b = write_b(false);
  std::vector<int> renamed = b_labels_;
  for(int& l : renamed) if(l == 0) l = 1000;
  const std::string labels_b = write_labels(renamed, "b.labels.txt");
  const Tool_run r = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --labels-b " + labels_b +
                         " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("labels only in A (not mapped): 0\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("labels only in B (nothing maps there): 1000\n"), std::string::npos) << r.out;
  const auto rows = read_csv(out_dir() / "correspondence.csv");
  std::size_t unmapped = 0;
  for(std::size_t i = 1; i < rows.size(); ++i)
    if(rows[i][1] == "-1") ++unmapped;
  EXPECT_GT(unmapped, 50u);
  EXPECT_LT(unmapped, nv_ / 2);

  // No label in common: an error, nothing written.
  std::vector<int> disjoint = b_labels_;
  for(int& l : disjoint) l += 5000;
  const Tool_run none = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --labels-b " +
                            write_labels(disjoint, "disjoint.txt") + " -o " + path("none_out"));
  EXPECT_EQ(none.code, 1);
  EXPECT_NE(none.err.find("no patch of A pairs with a patch of B"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(path("none_out")));
}

// Regions painted on both meshes: A as `diffuv segment` writes it (palette
// colours and a label property), B painted with the same colours only (another
// file, another numbering): the colours name the same regions.
TEST_F(Correspond, PaintedRegionsPairByColor)
{
  std::ostringstream b;
  b.precision(17);
  b << "OFF\n" << nv_ << ' ' << b_faces_.size() << " 0\n";
  for(std::size_t k = 0; k < nv_; ++k) b << b_points_[k][0] << ' ' << b_points_[k][1] << ' ' << b_points_[k][2] << '\n';
  for(std::size_t k = 0; k < b_faces_.size(); ++k) {
    const auto c = diffuv::label_color(b_labels_[k]);
    b << "3 " << b_faces_[k][0] << ' ' << b_faces_[k][1] << ' ' << b_faces_[k][2] << ' ' << int(c.r) << ' '
      << int(c.g) << ' ' << int(c.b) << '\n';
  }
  const std::string painted_b = write("b_painted.off", b.str());
  const Tool_run r = run("correspond " + path("seg") + "/a.patches.ply " + painted_b + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("vertices mapped: " + std::to_string(nv_) + " of " + std::to_string(nv_)), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("labels only in"), std::string::npos) << r.out;
  const auto rows = read_csv(out_dir() / "correspondence.csv");
  ASSERT_EQ(rows.size(), nv_ + 1);
  double worst = 0;
  for(std::size_t i = 1; i < rows.size(); ++i)
    for(int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(std::stod(rows[i][5 + k]) - b_points_[copy_of_[i - 1]][k]));
  EXPECT_LT(worst, 1e-9);
}

// What was cleaned adds up (issue #19): an island of four faces was "4 faces
// relabelled (1 island, ...)", an island counted among faces.
TEST_F(Correspond, CleanedFacesAddUp)
{
  const auto& m = diffuv_test::cgal_mesh("cow.off");
  std::vector<int> labels;
  std::ifstream in(labels_a_);
  for(int l; in >> l;) labels.push_back(l);
  // A face and its three neighbours, deep inside one region: relabelled, an island.
  std::vector<std::size_t> island;
  for(auto f : faces(m)) {
    std::set<std::size_t> group = {f.idx()}, halo;
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) group.insert(m.face(m.opposite(h)).idx());
    for(std::size_t g : group)
      for(auto v : CGAL::vertices_around_face(m.halfedge(diffuv_test::Mesh::Face_index(static_cast<std::uint32_t>(g))), m))
        for(auto around : CGAL::faces_around_target(m.halfedge(v), m)) halo.insert(around.idx());
    if(std::all_of(halo.begin(), halo.end(), [&](std::size_t g) { return labels[g] == labels[f.idx()]; })) {
      island.assign(group.begin(), group.end());
      break;
    }
  }
  ASSERT_EQ(island.size(), 4u);
  const int other = labels[island[0]] + 1;
  for(std::size_t g : island) labels[g] = other;
  const std::string b = write_b(false);
  const Tool_run r = run("correspond " + a_ + ' ' + b + " --labels-a " + write_labels(labels, "island.txt") +
                         " --labels-b " + write_labels(b_labels_, "b.labels.txt") + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("; 4 faces relabelled (4 in 1 island, 0 by border smoothing, 0 at 0 pinches))\n"),
            std::string::npos) << r.out;
}

// A copy of cow 1.6 times coarser, given A's labels by nearest face, with A
// labelled by `diffuv segment` (the default layout's small patches): the
// regions the copy loses join a neighbour on both meshes, are listed, and
// nearly every vertex maps (325 unmapped without the joins, test
// Correspondence.RegionsACoarseCopyLosesJoinTheirNeighbourOnBothMeshes).
TEST_F(Correspond, ACoarseCopyWithCarriedLabelsJoinsTheRegionsItLoses)
{
  const Tool_run seg = run("segment " + a_ + " -o " + path("layout"));
  ASSERT_EQ(seg.code, 0) << seg.err;
  const diffuv_test::Mesh coarse = diffuv_test::remeshed_copy(diffuv_test::cgal_mesh("cow.off"), 1.6);
  std::ostringstream b;
  b.precision(17);
  b << "OFF\n" << num_vertices(coarse) << ' ' << num_faces(coarse) << " 0\n";
  for(auto v : vertices(coarse)) b << coarse.point(v) << '\n';
  for(auto f : faces(coarse)) {
    b << 3;
    for(auto v : CGAL::vertices_around_face(coarse.halfedge(f), coarse)) b << ' ' << v.idx();
    b << '\n';
  }
  const Tool_run r = run("correspond " + a_ + ' ' + write("coarse.off", b.str()) + " --labels-a " + path("layout") +
                         "/a.patches.txt --transfer-labels -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::size_t line = r.out.find("regions too small for B, joined to a neighbour on both meshes");
  ASSERT_NE(line, std::string::npos) << r.out;
  // Every joined label is listed with the region it joined, none cut off
  // (the library's test measured 77 joins on this copy).
  const std::string joined = r.out.substr(line, r.out.find('\n', line) - line);
  std::size_t arrows = 0;
  for(std::size_t at = joined.find(" -> "); at != std::string::npos; at = joined.find(" -> ", at + 1)) ++arrows;
  EXPECT_GT(arrows, 20u) << joined;
  EXPECT_EQ(joined.find("..."), std::string::npos) << joined;
  EXPECT_NE(r.out.find(" builds), map "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("labels only in A"), std::string::npos) << r.out;
  const auto rows = read_csv(out_dir() / "correspondence.csv");
  ASSERT_EQ(rows.size(), nv_ + 1);
  std::size_t unmapped = 0;
  for(std::size_t i = 1; i < rows.size(); ++i) unmapped += rows[i][1] == "-1" ? 1 : 0;
  EXPECT_LT(unmapped * 50, nv_) << unmapped << " vertices unmapped";
}

// Patches are named as param names them, and counts agree in number (issue
// #19): a label in two pieces on A and one on B was "1 patches", "1 labels"
// and "0.0".
TEST_F(Tool, CorrespondNamesPatchesAsParamDoes)
{
  const std::string a = write("two.off", two_grids()), b = write("grid.off", grid_off);
  std::string zeros_a, zeros_b;
  for(int f = 0; f < 16; ++f) zeros_a += "0\n";
  for(int f = 0; f < 8; ++f) zeros_b += "0\n";
  const Tool_run r = run("correspond " + a + ' ' + b + " --labels-a " + write("a.txt", zeros_a) + " --labels-b " +
                         write("b.txt", zeros_b) + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\nA: 18 vertices, 2 patches ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nB: 9 vertices, 1 patch ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nregions matched: 1 label, 1 patch\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\npatches of A without a counterpart: 0#2\n"), std::string::npos) << r.out;
}

} // namespace
