// Tests of label cleaning (correspondence/clean_labels.h): islands, jagged borders,
// regions touching themselves at a vertex, clean labels left alone, and the
// same result whatever the face and vertex order.
#include "test_data.h"

#include <diffuv/layout/disc_patches.h>
#include <diffuv/correspondence/clean_labels.h>
#include <diffuv/patches/patches_from_labels.h>
#include <diffuv/patches/segmentation.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace diffuv_test;
using vertex_descriptor = Mesh::Vertex_index;
using face_descriptor = Mesh::Face_index;

// Labels of a grid of nx columns from a function of the cell (i, j).
std::vector<int> cell_labels(std::size_t nx, std::size_t ny, const std::function<int(int, int)>& label)
{
  std::vector<int> labels(2 * nx * ny);
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i) labels[2 * (j * nx + i)] = labels[2 * (j * nx + i) + 1] = label(int(i), int(j));
  return labels;
}

// Face index of the lower (0) or upper (1) triangle of cell (i, j).
std::size_t cell_face(std::size_t nx, std::size_t i, std::size_t j, int upper) { return 2 * (j * nx + i) + upper; }

// Number of components of each label.
std::map<int, std::size_t> components_per_label(const Mesh& m, const std::vector<int>& labels)
{
  const auto seg = diffuv::patches_from_labels(m, m.points(), labels);
  std::map<int, std::size_t> count;
  for(int l : seg.patch_label) ++count[l];
  return count;
}

// (vertex, label) pairs around which the faces of the label form two or more
// fans (separated by other labels or the mesh border): written here
// independently of the library, on Surface_mesh's own circulator.
std::size_t pinched_pairs(const Mesh& m, const std::vector<int>& labels)
{
  std::size_t pinched = 0;
  for(vertex_descriptor v : vertices(m)) {
    std::vector<int> ring; // face labels, with a sentinel for a border gap
    std::vector<bool> gap;
    for(auto h : CGAL::halfedges_around_target(m.halfedge(v), m)) {
      const face_descriptor f = m.face(h);
      gap.push_back(f == Mesh::null_face());
      ring.push_back(f == Mesh::null_face() ? 0 : labels[f.idx()]);
    }
    std::map<int, int> starts; // label -> fans starting here
    const std::size_t n = ring.size();
    bool changes = false;
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t p = (i + n - 1) % n;
      if(!gap[i] && (gap[p] || ring[p] != ring[i])) {
        ++starts[ring[i]];
        changes = true;
      }
    }
    if(!changes) continue; // one label all around
    for(const auto& [label, fans] : starts)
      if(fans >= 2) ++pinched;
  }
  return pinched;
}

// The other label of which face f has two or more edge-neighbours (an ear), or -1.
int ear_label(const Mesh& m, const std::vector<int>& labels, face_descriptor f)
{
  std::map<int, int> other;
  for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
    const face_descriptor g = m.face(m.opposite(h));
    if(g != Mesh::null_face() && labels[g.idx()] != labels[f.idx()]) ++other[labels[g.idx()]];
  }
  for(const auto& [l, n] : other)
    if(n >= 2) return l;
  return -1;
}

// Faces with two or more edge-neighbours of one other label.
std::size_t ear_faces(const Mesh& m, const std::vector<int>& labels)
{
  std::size_t ears = 0;
  for(face_descriptor f : faces(m)) ears += ear_label(m, labels, f) >= 0;
  return ears;
}

// Moves ears (faces with two edges towards one other label) to that label,
// one face at a time until none is left: a test set-up helper, so that a test
// of another rule starts from labels border smoothing leaves alone.
void remove_ears(const Mesh& m, std::vector<int>& labels)
{
  for(bool changed = true; changed;) {
    changed = false;
    for(face_descriptor f : faces(m)) {
      const int l = ear_label(m, labels, f);
      if(l >= 0) {
        labels[f.idx()] = l;
        changed = true;
      }
    }
  }
}

// Edges between faces of different labels.
std::size_t border_edges(const Mesh& m, const std::vector<int>& labels)
{
  std::size_t n = 0;
  for(auto e : edges(m)) {
    const face_descriptor a = m.face(m.halfedge(e)), b = m.face(m.opposite(m.halfedge(e)));
    if(a != Mesh::null_face() && b != Mesh::null_face() && labels[a.idx()] != labels[b.idx()]) ++n;
  }
  return n;
}

// Every patch of the labels is a topological disc.
::testing::AssertionResult all_discs(const Mesh& m, const std::vector<int>& labels)
{
  const auto seg = diffuv::patches_from_labels(m, m.points(), labels);
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
    const diffuv::Status s = diffuv::check_patch_disc(m, seg, p);
    if(!s) return ::testing::AssertionFailure() << s.what();
  }
  return ::testing::AssertionSuccess();
}

std::size_t differences(const std::vector<int>& a, const std::vector<int>& b)
{
  std::size_t n = 0;
  for(std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
  return n;
}

// The automatic disc patches of a mesh, as face labels (computed once per mesh).
const std::vector<int>& automatic_labels(const std::string& name)
{
  static std::map<std::string, std::vector<int>> cache;
  auto it = cache.find(name);
  if(it == cache.end()) {
    const Mesh& m = cgal_mesh(name);
    // Region-sized labels, as a user paints them: the Voronoi layout's patches
    // (the four-sided layout's quads are many times smaller than a region).
    diffuv::Segmentation<Mesh> seg;
    diffuv::Patching_options options;
    options.layout = diffuv::Patch_layout::voronoi;
    EXPECT_TRUE(diffuv::disc_patches(m, m.points(), std::vector<int>(), seg, options).ok()) << name;
    it = cache.emplace(name, std::vector<int>(seg.face_patch.begin(), seg.face_patch.end())).first;
  }
  return it->second;
}

// Flips `fraction` of the faces, picked among faces on region borders, to the
// label of one of their neighbours of another label (deterministic).
std::vector<int> noisy(const Mesh& m, std::vector<int> labels, double fraction, unsigned seed)
{
  std::mt19937 rng(seed);
  std::vector<face_descriptor> on_border;
  for(face_descriptor f : faces(m))
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
      const face_descriptor g = m.face(m.opposite(h));
      if(g != Mesh::null_face() && labels[g.idx()] != labels[f.idx()]) { on_border.push_back(f); break; }
    }
  std::shuffle(on_border.begin(), on_border.end(), rng);
  const std::size_t flips = std::min(on_border.size(), std::size_t(fraction * double(num_faces(m))));
  for(std::size_t k = 0; k < flips; ++k) {
    const face_descriptor f = on_border[k];
    std::vector<int> other;
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
      const face_descriptor g = m.face(m.opposite(h));
      if(g != Mesh::null_face() && labels[g.idx()] != labels[f.idx()]) other.push_back(labels[g.idx()]);
    }
    if(!other.empty()) labels[f.idx()] = other[rng() % other.size()];
  }
  return labels;
}

// A copy of `m` with vertices and faces stored in a random order and each
// face starting at a random one of its vertices; new face k is old face old_face[k].
struct Shuffled {
  Mesh mesh;
  std::vector<std::size_t> old_face;
};
Shuffled shuffled_copy(const Mesh& m, unsigned seed)
{
  std::mt19937 rng(seed);
  std::vector<std::size_t> new_vertex(num_vertices(m)), old_vertex(num_vertices(m));
  std::iota(new_vertex.begin(), new_vertex.end(), 0);
  std::shuffle(new_vertex.begin(), new_vertex.end(), rng);
  for(std::size_t i = 0; i < new_vertex.size(); ++i) old_vertex[new_vertex[i]] = i;
  Shuffled s;
  for(std::size_t k = 0; k < old_vertex.size(); ++k) s.mesh.add_vertex(m.point(vertex_descriptor(Mesh::size_type(old_vertex[k]))));
  s.old_face.resize(num_faces(m));
  std::iota(s.old_face.begin(), s.old_face.end(), 0);
  std::shuffle(s.old_face.begin(), s.old_face.end(), rng);
  for(std::size_t old : s.old_face) {
    std::vector<vertex_descriptor> fv;
    for(auto v : vertices_around_face(m.halfedge(face_descriptor(Mesh::size_type(old))), m))
      fv.push_back(vertex_descriptor(Mesh::size_type(new_vertex[v.idx()])));
    std::rotate(fv.begin(), fv.begin() + std::ptrdiff_t(rng() % fv.size()), fv.end());
    EXPECT_NE(s.mesh.add_face(fv), Mesh::null_face());
  }
  return s;
}

// Cleans `labels` on `m` and on a shuffled copy; expects the same label on every face.
void expect_order_independent(const Mesh& m, const std::vector<int>& labels, unsigned seed)
{
  std::vector<int> direct = labels;
  const auto report = diffuv::clean_labels(m, m.points(), direct);
  EXPECT_GT(report.changed_faces(), 0u); // something to compare
  const Shuffled s = shuffled_copy(m, seed);
  std::vector<int> shuffled_labels(num_faces(s.mesh));
  for(std::size_t k = 0; k < s.old_face.size(); ++k) shuffled_labels[k] = labels[s.old_face[k]];
  const auto shuffled_report = diffuv::clean_labels(s.mesh, s.mesh.points(), shuffled_labels);
  std::size_t disagree = 0;
  for(std::size_t k = 0; k < s.old_face.size(); ++k) disagree += shuffled_labels[k] != direct[s.old_face[k]];
  EXPECT_EQ(disagree, 0u);
  EXPECT_EQ(report.changed_faces(), shuffled_report.changed_faces());
  EXPECT_EQ(report.islands, shuffled_report.islands);
  EXPECT_EQ(report.smoothed_faces, shuffled_report.smoothed_faces);
  EXPECT_EQ(report.pinches, shuffled_report.pinches);
  EXPECT_EQ(report.rounds, shuffled_report.rounds);
}

TEST(CleanLabels, CleanLabelsAreLeftAlone)
{
  const Mesh grid = make_grid(9, 9);
  const std::vector<int> blocks = cell_labels(9, 9, [](int i, int j) { return 3 * (j / 3) + i / 3; });
  std::vector<int> labels = blocks;
  const auto report = diffuv::clean_labels(grid, grid.points(), labels);
  EXPECT_EQ(labels, blocks);
  EXPECT_TRUE(report.empty());
  EXPECT_EQ(report.changed_faces(), 0u);
  EXPECT_EQ(report.rounds, 1u);
}

TEST(CleanLabels, OneFaceAndSmallIslandsAreAbsorbed)
{
  const std::size_t n = 12;
  const Mesh grid = make_grid(n, n);
  const std::vector<int> halves = cell_labels(n, n, [](int i, int) { return i < 6 ? 0 : 1; });
  std::vector<int> labels = halves;
  labels[cell_face(n, 2, 6, 0)] = 1;                       // one face of label 1 inside label 0
  for(std::size_t i : {8, 9})
    for(std::size_t j : {3, 4})
      for(int t : {0, 1}) labels[cell_face(n, i, j, t)] = 0; // 2x2 cells (8 faces) of label 0 inside label 1
  ASSERT_EQ(components_per_label(grid, labels), (std::map<int, std::size_t>{{0, 2}, {1, 2}}));

  const auto report = diffuv::clean_labels(grid, grid.points(), labels);
  EXPECT_EQ(labels, halves);
  EXPECT_EQ(report.islands, 2u);
  EXPECT_EQ(report.island_faces, 9u);
  EXPECT_EQ(report.changed_faces(), 9u);
  EXPECT_EQ(report.smoothed_faces, 0u);
  EXPECT_EQ(report.pinches, 0u);
  EXPECT_EQ(report.rounds, 2u); // one that cleans, one that finds nothing left
  EXPECT_FALSE(report.empty());
}

TEST(CleanLabels, IslandInsideAnIslandEndsInTheRegionAroundBoth)
{
  // Three bands 0 | 1 | 2; in band 1 a 3x3-cell block of 0 (18 faces), and in
  // its middle one face of 2. The face joins the block (its only neighbour),
  // then the grown block (still an island) joins band 1.
  const std::size_t n = 18;
  const Mesh grid = make_grid(n, n);
  const std::vector<int> bands = cell_labels(n, n, [](int i, int) { return i / 6; });
  std::vector<int> labels = bands;
  for(std::size_t i = 7; i < 10; ++i)
    for(std::size_t j = 7; j < 10; ++j)
      for(int t : {0, 1}) labels[cell_face(n, i, j, t)] = 0;
  labels[cell_face(n, 8, 8, 0)] = 2; // all three neighbours in the block

  const auto report = diffuv::clean_labels(grid, grid.points(), labels);
  EXPECT_EQ(labels, bands);
  EXPECT_EQ(report.islands, 2u);
  EXPECT_EQ(report.island_faces, 1u + 18u);
  EXPECT_EQ(report.changed_faces(), 18u);
  EXPECT_EQ(report.rounds, 2u); // both in the first round: the grown block was looked at again
}

TEST(CleanLabels, LargeComponentsOfOneLabelAreAllKept)
{
  // Label 1 painted twice, as two equal 3x3-cell blocks (two hands), and once
  // as a stray face: the blocks stay, the stray face goes.
  const std::size_t n = 16;
  const Mesh grid = make_grid(n, n);
  const std::vector<int> painted = cell_labels(n, n, [](int i, int j) {
    return ((i >= 2 && i < 5 && j >= 2 && j < 5) || (i >= 10 && i < 13 && j >= 10 && j < 13)) ? 1 : 0;
  });
  std::vector<int> labels = painted;
  labels[cell_face(n, 3, 12, 1)] = 1;
  const auto report = diffuv::clean_labels(grid, grid.points(), labels);
  EXPECT_EQ(report.islands, 1u);
  EXPECT_EQ(report.island_faces, 1u);
  EXPECT_EQ(labels[cell_face(n, 3, 12, 1)], 0);
  const auto seg = diffuv::patches_from_labels(grid, grid.points(), labels);
  ASSERT_EQ(seg.number_of_patches(), 3u); // label 0, then the two blocks of label 1
  EXPECT_EQ(seg.patch_label[1], 1);
  EXPECT_EQ(seg.patch_label[2], 1);
  // Each block keeps its faces but the two corner triangles that stick out
  // (two edges towards label 0: border smoothing cuts them).
  EXPECT_EQ(seg.patch_faces[1].size(), 16u);
  EXPECT_EQ(seg.patch_faces[2].size(), 16u);
  EXPECT_EQ(report.changed_faces(), 1u + 4u);

  // 18 faces against 32: kept by default; with a fraction of 1 (everything
  // below the largest component is an island) the smaller block goes.
  const std::vector<int> uneven = cell_labels(n, n, [](int i, int j) {
    return ((i >= 2 && i < 6 && j >= 2 && j < 6) || (i >= 10 && i < 13 && j >= 10 && j < 13)) ? 1 : 0;
  });
  std::vector<int> kept = uneven, strict = uneven;
  diffuv::clean_labels(grid, grid.points(), kept);
  EXPECT_EQ(components_per_label(grid, kept)[1], 2u);
  diffuv::Label_cleaning_options all;
  all.island_fraction = 1.0;
  diffuv::clean_labels(grid, grid.points(), strict, all);
  EXPECT_EQ(components_per_label(grid, strict)[1], 1u);
}

TEST(CleanLabels, JaggedBorderIsSmoothed)
{
  // Border between 0 (left) and 1 (right) one cell further right on every
  // other row: a sawtooth of one-cell teeth.
  const std::size_t n = 16;
  const Mesh grid = make_grid(n, n);
  std::vector<int> labels = cell_labels(n, n, [](int i, int j) { return i < 8 + (j % 2) ? 0 : 1; });
  const std::size_t ears_before = ear_faces(grid, labels), borders_before = border_edges(grid, labels);
  ASSERT_GT(ears_before, 0u);

  const auto report = diffuv::clean_labels(grid, grid.points(), labels);
  EXPECT_GT(report.smoothed_faces, 0u);
  EXPECT_EQ(report.islands, 0u);
  EXPECT_LT(report.rounds, diffuv::Label_cleaning_options().max_rounds); // a fixed point was reached
  EXPECT_EQ(ear_faces(grid, labels), 0u);
  EXPECT_LT(border_edges(grid, labels), borders_before);
  EXPECT_EQ(components_per_label(grid, labels), (std::map<int, std::size_t>{{0, 1}, {1, 1}}));
  EXPECT_TRUE(all_discs(grid, labels));
  // The border stays where it was: every face moved is next to the sawtooth.
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      if(i >= 7 && i <= 9) continue;
      for(int t : {0, 1}) EXPECT_EQ(labels[cell_face(n, i, j, t)], i < 8 ? 0 : 1) << i << " " << j;
    }
}

// Around vertex (6, 6) of a grid (cells cut along (i, j)-(i+1, j+1)), the
// cell above left (5, 6) and the cell below right (6, 5) each have one
// triangle at the vertex, the two other cells two. A region in the first two
// cells touches itself there with one triangle on each side, separated by two
// triangles of other labels. (On the other diagonal, a gap of one triangle is
// an ear, and border smoothing fills it before the pinch rule looks.)

TEST(CleanLabels, RegionTouchingItselfAtAVertexIsCut)
{
  // Label 1 is a "C" whose two ends touch at vertex (6, 6), around label 2;
  // label 0 outside. Its boundary passes (6, 6) twice: not a disc. Its two
  // fans there (one triangle each) have equal areas, so both are cut.
  const std::size_t n = 12;
  const Mesh grid = make_grid(n, n);
  std::vector<int> labels = cell_labels(n, n, [](int i, int j) {
    const bool below = i >= 6 && j >= 2 && j < 6, right = i >= 10 && j >= 6 && j < 11, top = i >= 2 && j == 10,
               above = i >= 2 && i < 6 && j >= 6 && j < 10, inside = i >= 6 && i < 10 && j >= 6 && j < 10;
    return (below || right || top || above) ? 1 : (inside ? 2 : 0);
  });
  remove_ears(grid, labels); // three corner triangles
  ASSERT_EQ(components_per_label(grid, labels), (std::map<int, std::size_t>{{0, 1}, {1, 1}, {2, 1}}));
  ASSERT_EQ(pinched_pairs(grid, labels), 1u);
  ASSERT_EQ(ear_faces(grid, labels), 0u);
  ASSERT_FALSE(all_discs(grid, labels));

  const auto report = diffuv::clean_labels(grid, grid.points(), labels);
  EXPECT_EQ(report.pinches, 1u);
  EXPECT_EQ(report.pinch_faces, 2u);
  EXPECT_EQ(report.changed_faces(), 2u);
  EXPECT_EQ(pinched_pairs(grid, labels), 0u);
  EXPECT_TRUE(all_discs(grid, labels));
  EXPECT_NE(labels[cell_face(n, 5, 6, 0)], 1); // the triangles at (6, 6) left label 1
  EXPECT_NE(labels[cell_face(n, 6, 5, 1)], 1);
}

TEST(CleanLabels, TheLargerFanAtAPinchIsKept)
{
  // Two quadrants of label 1 meeting at vertex (6, 6): A above left, B below
  // right; label 0 below left, 2 above right. Columns right of x = 6 are
  // twice as wide, so B's triangle at the vertex is larger than A's: B keeps
  // it, A gives its own up.
  std::vector<double> xs, ys;
  for(int k = 0; k <= 12; ++k) xs.push_back(k <= 6 ? k : 6 + 2. * (k - 6));
  for(int k = 0; k <= 12; ++k) ys.push_back(k);
  const Mesh grid = make_grid_at(xs, ys);
  const std::size_t n = 12;
  std::vector<int> labels = cell_labels(n, n, [](int i, int j) {
    if((i < 6) != (j < 6)) return 1; // A and B
    return j < 6 ? 0 : 2;
  });
  ASSERT_EQ(pinched_pairs(grid, labels), 1u);
  ASSERT_EQ(ear_faces(grid, labels), 0u);
  const std::vector<int> before = labels;

  const auto report = diffuv::clean_labels(grid, grid.points(), labels);
  EXPECT_EQ(report.pinches, 1u);
  EXPECT_EQ(report.pinch_faces, 1u);
  EXPECT_EQ(report.changed_faces(), 1u);
  EXPECT_EQ(labels[cell_face(n, 6, 5, 1)], 1); // B keeps its triangle at (6, 6)
  // A's goes to the most common other label across its edges: 2 (cell (6, 6))
  // and 0 (cell (5, 5)) tie, the smaller wins.
  EXPECT_EQ(labels[cell_face(n, 5, 6, 0)], 0);
  EXPECT_EQ(differences(before, labels), 1u);
  EXPECT_EQ(pinched_pairs(grid, labels), 0u);
  EXPECT_EQ(components_per_label(grid, labels)[1], 2u);
  EXPECT_TRUE(all_discs(grid, labels));
}

TEST(CleanLabels, ASaddleNeedsOneCut)
{
  // Quadrants 1, 0, 1, 0 around vertex (6, 6): both labels touch themselves
  // there. Cutting label 1 (one triangle on each side, the cheaper) joins the
  // two halves of label 0 through the vertex, so label 0 needs no cut. (Those
  // two triangles are ears too: without smoothing the pinch rule must do it.)
  const std::size_t n = 12;
  const Mesh grid = make_grid(n, n);
  std::vector<int> labels = cell_labels(n, n, [](int i, int j) { return (i < 6) != (j < 6) ? 1 : 0; });
  ASSERT_EQ(pinched_pairs(grid, labels), 2u);

  diffuv::Label_cleaning_options no_smoothing;
  no_smoothing.smoothing_passes = 0;
  const auto report = diffuv::clean_labels(grid, grid.points(), labels, no_smoothing);
  EXPECT_EQ(report.smoothed_faces, 0u);
  EXPECT_EQ(report.pinches, 1u);
  EXPECT_EQ(report.pinch_faces, 2u);
  EXPECT_EQ(labels[cell_face(n, 5, 6, 0)], 0);
  EXPECT_EQ(labels[cell_face(n, 6, 5, 1)], 0);
  EXPECT_EQ(pinched_pairs(grid, labels), 0u);
  EXPECT_EQ(components_per_label(grid, labels), (std::map<int, std::size_t>{{0, 1}, {1, 2}}));
  EXPECT_TRUE(all_discs(grid, labels));
}

TEST(CleanLabels, AutomaticPatchesOfCowAreLeftAlone)
{
  // disc_patches() (the Voronoi layout) ends with discs, one component each,
  // borders smoothed: nothing for the rules to do.
  const Mesh& cow = cgal_mesh("cow.off");
  std::vector<int> labels = automatic_labels("cow.off");
  const auto report = diffuv::clean_labels(cow, cow.points(), labels);
  EXPECT_EQ(report.changed_faces(), 0u);
  EXPECT_EQ(report.islands, 0u);
  EXPECT_EQ(report.smoothed_faces, 0u);
  EXPECT_EQ(report.pinches, 0u);
  EXPECT_TRUE(report.empty());
  EXPECT_EQ(labels, automatic_labels("cow.off"));
}

TEST(CleanLabels, NoisyLabelsComeBack)
{
  // 3% of the faces, all on region borders, flipped to a neighbour's label.
  // A flipped face that sticks out (two edges towards its old label) is what
  // the rules can undo; two flipped neighbours make a bump that is not an
  // ear, and a flip next to a sharp corner of the region is ambiguous (moving
  // the corner face instead is as short a border): those may stay.
  for(const char* name : {"cow.off", "man.off"}) {
    const Mesh& m = cgal_mesh(name);
    const std::vector<int>& original = automatic_labels(name);
    const std::vector<int> noise = noisy(m, original, 0.03, 7);
    std::vector<int> labels = noise;
    const std::size_t before = differences(original, labels);
    ASSERT_GT(before, num_faces(m) / 50) << name;
    std::vector<std::size_t> sticking_out; // flipped faces with two edges towards their original label
    for(face_descriptor f : faces(m)) {
      if(noise[f.idx()] == original[f.idx()]) continue;
      int towards = 0;
      for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
        const face_descriptor g = m.face(m.opposite(h));
        towards += g != Mesh::null_face() && noise[g.idx()] == original[f.idx()];
      }
      if(towards >= 2) sticking_out.push_back(f.idx());
    }

    const auto report = diffuv::clean_labels(m, m.points(), labels);
    const std::size_t after = differences(original, labels);
    std::size_t restored = 0;
    for(std::size_t f : sticking_out) restored += labels[f] == original[f];
    std::cout << name << ": " << num_faces(m) << " faces, " << before << " flipped (" << sticking_out.size()
              << " sticking out, " << restored << " of them restored), " << after << " differ after cleaning ("
              << report.changed_faces() << " changed: " << report.islands << " islands / " << report.island_faces
              << " faces, " << report.smoothed_faces << " smoothed, " << report.pinches << " pinches / "
              << report.pinch_faces << " faces, " << report.rounds << " rounds)\n";
    EXPECT_LT(after * 5, before * 3) << name;                   // 40% of the noise gone at least
    EXPECT_GT(restored * 10, sticking_out.size() * 7) << name;  // 70% of what can be undone
    for(const auto& [label, components] : components_per_label(m, labels))
      EXPECT_EQ(components, 1u) << name << " label " << label;
    EXPECT_EQ(pinched_pairs(m, labels), 0u) << name;
    EXPECT_EQ(ear_faces(m, labels), 0u) << name;
  }
}

TEST(CleanLabels, ResultDoesNotDependOnFaceOrVertexOrder)
{
  // Noisy labels on cow (real geometry) and on a grid (equal areas and
  // lengths everywhere: ties at every step).
  const Mesh& cow = cgal_mesh("cow.off");
  expect_order_independent(cow, noisy(cow, automatic_labels("cow.off"), 0.05, 3), 21);

  const std::size_t n = 20;
  const Mesh grid = make_grid(n, n);
  std::vector<int> labels = cell_labels(n, n, [](int i, int j) { return 4 * (j / 5) + i / 5; });
  labels = noisy(grid, labels, 0.15, 5);
  labels[cell_face(n, 12, 12, 1)] = 3; // an island
  expect_order_independent(grid, labels, 22);

  // Random labels: every rule fires, pinches and saddles everywhere.
  const Mesh small = make_grid(12, 12);
  for(unsigned seed = 0; seed < 10; ++seed) {
    SCOPED_TRACE("random labels, seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    std::vector<int> random(num_faces(small));
    for(int& l : random) l = int(rng() % 4);
    expect_order_independent(small, random, 400 + seed);
  }
}

TEST(CleanLabels, BoundedAndInputChecked)
{
  const Mesh grid = make_grid(4, 4);
  std::vector<int> wrong(3, 0);
  EXPECT_THROW(diffuv::clean_labels(grid, grid.points(), wrong), std::invalid_argument);
  std::vector<int> labels(num_faces(grid), 0);
  diffuv::Label_cleaning_options bad;
  bad.island_fraction = -0.5;
  EXPECT_THROW(diffuv::clean_labels(grid, grid.points(), labels, bad), std::invalid_argument);

  Mesh quad; // triangles only: areas come from face_area()
  quad.add_face(quad.add_vertex(Point_3(0, 0, 0)), quad.add_vertex(Point_3(1, 0, 0)), quad.add_vertex(Point_3(1, 1, 0)),
                quad.add_vertex(Point_3(0, 1, 0)));
  std::vector<int> one(1, 0);
  EXPECT_THROW(diffuv::clean_labels(quad, quad.points(), one), std::invalid_argument);

  // No rounds: nothing is done, even to an island.
  labels[5] = 1;
  diffuv::Label_cleaning_options none;
  none.max_rounds = 0;
  std::vector<int> untouched = labels;
  const auto report = diffuv::clean_labels(grid, grid.points(), untouched, none);
  EXPECT_EQ(untouched, labels);
  EXPECT_TRUE(report.empty());
  EXPECT_EQ(report.rounds, 0u);
}

} // namespace
