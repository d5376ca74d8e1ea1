// Correspondence through (region, u, v): pairing of patches, mapping of
// vertices and surface points, seams, labels only in one mesh, labels that need
// cleaning, and attribute transfer.
#include "test_data.h"

#include <diffuv/correspondence/correspondence.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/correspondence/nearest_face_labels.h>
#include <diffuv/correspondence/transfer.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/layout/sub_patches.h>
#include <diffuv/patches/patches_from_labels.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace {

using diffuv_test::Mesh;
using diffuv_test::Point_3;
using Atlas = diffuv::Labelled_atlas<Mesh>;
using Correspondence = diffuv::Atlas_correspondence<Mesh, Mesh>;
using vertex_descriptor = Mesh::Vertex_index;
using face_descriptor = Mesh::Face_index;

// Labels of automatic disc patches (what `diffuv segment --layout voronoi`
// writes): region-sized, as a user paints them.
std::vector<int> segment_labels(const Mesh& m, std::size_t patches = 12)
{
  diffuv::Segmentation<Mesh> seg;
  diffuv::Patching_options options;
  options.layout = diffuv::Patch_layout::voronoi;
  options.automatic.patches = patches;
  EXPECT_TRUE(diffuv::disc_patches(m, m.points(), std::vector<int>(), seg, options).ok());
  std::vector<int> labels(num_faces(m));
  for(auto f : faces(m)) labels[f.idx()] = static_cast<int>(seg.face_patch[f.idx()]);
  return labels;
}

// A copy of `m` with vertices and faces in a random order, moved by a
// rotation, a scale and a translation: vertex_of[v] is the copy of vertex v,
// face_of[f] the copy of face f.
struct Moved_copy {
  Mesh mesh;
  std::vector<vertex_descriptor> vertex_of;
  std::vector<face_descriptor> face_of;
  double scale = 1.;
};

Moved_copy shuffled_moved_copy(const Mesh& m, unsigned seed, bool move)
{
  Moved_copy c;
  std::mt19937 rng(seed);
  std::vector<std::size_t> vperm(num_vertices(m)), fperm(num_faces(m));
  std::iota(vperm.begin(), vperm.end(), 0);
  std::iota(fperm.begin(), fperm.end(), 0);
  std::shuffle(vperm.begin(), vperm.end(), rng); // new vertex k is old vertex vperm[k]
  std::shuffle(fperm.begin(), fperm.end(), rng);
  c.scale = move ? 2.5 : 1.;
  const double a = 0.7, b = -1.1;  // rotation angles about z then x
  c.vertex_of.resize(num_vertices(m));
  for(std::size_t k = 0; k < vperm.size(); ++k) {
    const Point_3& p = m.point(vertex_descriptor(static_cast<Mesh::size_type>(vperm[k])));
    Point_3 q = p;
    if(move) {
      const double x1 = std::cos(a) * p.x() - std::sin(a) * p.y(), y1 = std::sin(a) * p.x() + std::cos(a) * p.y();
      const double y2 = std::cos(b) * y1 - std::sin(b) * p.z(), z2 = std::sin(b) * y1 + std::cos(b) * p.z();
      q = Point_3(c.scale * x1 + 3., c.scale * y2 - 7., c.scale * z2 + 1.);
    }
    c.vertex_of[vperm[k]] = c.mesh.add_vertex(q);
  }
  c.face_of.resize(num_faces(m));
  for(std::size_t k = 0; k < fperm.size(); ++k) {
    const face_descriptor f(static_cast<Mesh::size_type>(fperm[k]));
    std::vector<vertex_descriptor> fv;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) fv.push_back(c.vertex_of[v.idx()]);
    c.face_of[f.idx()] = c.mesh.add_face(fv);
  }
  return c;
}

std::vector<int> carry_labels(const std::vector<int>& labels, const Moved_copy& c)
{
  std::vector<int> out(labels.size());
  for(std::size_t f = 0; f < labels.size(); ++f) out[c.face_of[f].idx()] = labels[f];
  return out;
}

double sqrt_area(const Mesh& m) { return std::sqrt(CGAL::Polygon_mesh_processing::area(m)); }

// Build both atlases; the caller keeps them alive for the correspondence.
void build(const Mesh& m, const std::vector<int>& labels, Atlas& atlas,
           const diffuv::Labelled_atlas_options& options = diffuv::Labelled_atlas_options())
{
  ASSERT_TRUE(diffuv::build_labelled_atlas(m, m.points(), labels, atlas, options).ok());
}

// Vertex (label, part) set-up shared by several tests: cow, its automatic patches.
const Mesh& cow() { return diffuv_test::cgal_mesh("cow.off"); }

TEST(Correspondence, NoLabelsIsAnError)
{
  Atlas atlas(cow());
  const diffuv::Status s = diffuv::build_labelled_atlas(cow(), cow().points(), std::vector<int>(), atlas);
  EXPECT_EQ(s.code, diffuv::Status_code::no_labels);
  EXPECT_NE(std::string(s.what()).find("no region labels"), std::string::npos);
}

// The shuffled pair: every vertex lands on its own copy, whatever the order,
// position, scale and orientation of the copy.
TEST(Correspondence, ShuffledAndMovedCopyMapsEveryVertexOntoItself)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  for(bool move : {false, true}) {
    const Moved_copy b = shuffled_moved_copy(a, 11, move);
    Atlas atlas_a(a), atlas_b(b.mesh);
    build(a, labels, atlas_a);
    build(b.mesh, carry_labels(labels, b), atlas_b);
    const Correspondence c(atlas_a, atlas_b);
    EXPECT_EQ(c.report().matched_patches, atlas_a.atlas.number_of_charts());
    EXPECT_TRUE(c.report().labels_only_in_a.empty());
    EXPECT_TRUE(c.report().unmatched_patches_a.empty());
    const auto images = c.map_vertices();
    const double tolerance = 1e-9 * sqrt_area(b.mesh);
    double worst = 0;
    for(auto v : vertices(a)) {
      ASSERT_TRUE(images[v.idx()].mapped());
      worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(images[v.idx()].point, b.mesh.point(b.vertex_of[v.idx()]))));
    }
    EXPECT_LE(worst, tolerance) << (move ? "moved copy" : "shuffled copy");
  }
}

// Regions that need the automatic steps: height bands of cow give rings (cut
// into discs) and caps (split); they must land in the same place on a moved,
// shuffled copy, so the (label, part) keys pair up and vertices map onto themselves.
TEST(Correspondence, CutsAndCapSplitsAreIntrinsic)
{
  const Mesh& a = cow();
  CGAL::Bbox_3 box;
  for(auto v : vertices(a)) box += a.point(v).bbox();
  std::vector<int> labels(num_faces(a));
  for(auto f : faces(a)) {
    double z = 0;
    for(auto v : CGAL::vertices_around_face(a.halfedge(f), a)) z += a.point(v).y() / 3;
    labels[f.idx()] = static_cast<int>(std::floor(3.999 * (z - box.ymin()) / (box.ymax() - box.ymin())));
  }
  // One label per connected band piece: two pieces of one label with nearly
  // equal areas (cow's ears) would pair by area rank, which is ambiguous.
  const auto pieces = diffuv::patches_from_labels(a, a.points(), labels);
  for(auto f : faces(a)) labels[f.idx()] = static_cast<int>(pieces.face_patch[f.idx()]);
  const Moved_copy b = shuffled_moved_copy(a, 5, true);
  Atlas atlas_a(a), atlas_b(b.mesh);
  build(a, labels, atlas_a);
  build(b.mesh, carry_labels(labels, b), atlas_b);
  EXPECT_GT(atlas_a.patching.cut + atlas_a.patching.caps_split, 0u) << "the bands should need cuts or cap splits";
  EXPECT_EQ(atlas_a.segmentation.number_of_patches(), atlas_b.segmentation.number_of_patches());
  const Correspondence c(atlas_a, atlas_b);
  EXPECT_TRUE(c.report().unmatched_patches_a.empty());
  const auto images = c.map_vertices();
  std::size_t far = 0, unmapped = 0;
  const double tolerance = 1e-6 * sqrt_area(b.mesh);
  for(auto v : vertices(a)) {
    if(!images[v.idx()].mapped()) { ++unmapped; continue; }
    const double d = std::sqrt(CGAL::squared_distance(images[v.idx()].point, b.mesh.point(b.vertex_of[v.idx()])));
    if(d > tolerance) {
      ++far;
      if(far < 6) {
        auto e = atlas_a.atlas.entries(v);
        std::cerr << "far vertex " << v.idx() << " d/sqrtA=" << d / sqrt_area(b.mesh) << " charts:";
        for(auto it = e.first; it != e.second; ++it) std::cerr << ' ' << it->chart << "(" << std::get<0>(c.key_a(it->chart)) << "." << std::get<1>(c.key_a(it->chart)) << ")";
        std::cerr << " inside " << images[v.idx()].inside << "\n";
      }
    }
  }
  EXPECT_EQ(unmapped, 0u);
  EXPECT_EQ(far, 0u);
}

// A point on an edge between two charts, or a vertex on a patch border, maps to
// the same place from either side.
TEST(Correspondence, SeamPointsMapToOnePlaceFromEitherPatch)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  const Moved_copy b = shuffled_moved_copy(a, 3, false);
  Atlas atlas_a(a), atlas_b(b.mesh);
  build(a, labels, atlas_a);
  build(b.mesh, carry_labels(labels, b), atlas_b);
  const Correspondence c(atlas_a, atlas_b);
  std::size_t seam_edges = 0;
  for(auto e : edges(a)) {
    const auto h = a.halfedge(e), o = a.opposite(h);
    if(a.is_border(h) || a.is_border(o)) continue;
    const face_descriptor f = a.face(h), g = a.face(o);
    if(atlas_a.atlas.chart_of(f) == atlas_a.atlas.chart_of(g)) continue;
    ++seam_edges;
    // The point 30% of the way from source(h) to target(h), given on either face.
    auto location_on = [&](face_descriptor face_of_point) {
      std::array<double, 3> bary{{0., 0., 0.}};
      const auto fh = a.halfedge(face_of_point);
      const vertex_descriptor corner[3] = {a.source(fh), a.target(fh), a.target(a.next(fh))};
      for(int k = 0; k < 3; ++k) {
        if(corner[k] == a.source(h)) bary[k] = 0.7;
        if(corner[k] == a.target(h)) bary[k] = 0.3;
      }
      return bary;
    };
    const auto p = c.map_point(f, location_on(f)), q = c.map_point(g, location_on(g));
    ASSERT_TRUE(p.mapped() && q.mapped());
    EXPECT_EQ(CGAL::squared_distance(p.point, q.point), 0.);
  }
  EXPECT_GT(seam_edges, 100u);
  // A vertex given as a face corner maps as the vertex itself.
  for(auto f : faces(a)) {
    const auto images = c.map_point(f, {{1., 0., 0.}});
    const auto direct = c.map_vertex(a.source(a.halfedge(f)));
    EXPECT_EQ(images.point, direct.point);
  }
}

// A label that B lacks is reported; its vertices are not mapped, the rest are.
TEST(Correspondence, LabelInOneMeshOnlyIsReported)
{
  const Mesh& a = cow();
  std::vector<int> labels = segment_labels(a);
  const Moved_copy b = shuffled_moved_copy(a, 9, false);
  std::vector<int> labels_b = carry_labels(labels, b);
  // B merges region 3 into the region next to it: label 3 is only in A.
  int neighbour = -1;
  for(auto h : halfedges(a))
    if(!a.is_border(h) && !a.is_border(a.opposite(h)) && labels[a.face(h).idx()] == 3 &&
       labels[a.face(a.opposite(h)).idx()] != 3) {
      neighbour = labels[a.face(a.opposite(h)).idx()];
      break;
    }
  ASSERT_GE(neighbour, 0);
  for(int& l : labels_b) if(l == 3) l = neighbour;
  Atlas atlas_a(a), atlas_b(b.mesh);
  build(a, labels, atlas_a);
  build(b.mesh, labels_b, atlas_b);
  const Correspondence c(atlas_a, atlas_b);
  EXPECT_EQ(c.report().labels_only_in_a, std::vector<int>{3});
  EXPECT_TRUE(c.report().labels_only_in_b.empty());
  const auto images = c.map_vertices();
  std::size_t inside_3 = 0;
  for(auto v : vertices(a)) {
    bool only_3 = true;
    for(auto f : CGAL::faces_around_target(a.halfedge(v), a))
      if(f != Mesh::null_face() && labels[f.idx()] != 3) only_3 = false;
    if(only_3) {
      ++inside_3;
      EXPECT_FALSE(images[v.idx()].mapped());
    } else {
      EXPECT_TRUE(images[v.idx()].mapped());
    }
  }
  EXPECT_GT(inside_3, 10u);
}

// B's labels as a person or a transfer makes them: islands and a jagged border.
// The cleaning brings most of them back to A's regions, and B follows A's
// corners by name, so the map is far closer than without cleaning.
TEST(Correspondence, LabelsThatNeedCleaning)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  const Moved_copy b = shuffled_moved_copy(a, 21, false);
  std::vector<int> noisy = carry_labels(labels, b);
  // Every 7th face that touches another region takes that region's label.
  std::size_t changed = 0, k = 0;
  for(auto f : faces(a)) {
    const auto h0 = a.halfedge(f);
    for(auto h : CGAL::halfedges_around_face(h0, a)) {
      const auto g = a.face(a.opposite(h));
      if(g == Mesh::null_face() || labels[g.idx()] == labels[f.idx()]) continue;
      if(++k % 7 == 0) {
        noisy[b.face_of[f.idx()].idx()] = labels[g.idx()];
        ++changed;
      }
      break;
    }
  }
  ASSERT_GT(changed, 50u);
  Atlas atlas_a(a), clean_b(b.mesh), raw_b(b.mesh);
  build(a, labels, atlas_a);
  const auto follow = diffuv::atlas_to_follow(atlas_a);
  ASSERT_TRUE(diffuv::build_labelled_atlas(b.mesh, b.mesh.points(), noisy, follow, clean_b).ok());
  diffuv::Labelled_atlas_options no_cleaning;
  no_cleaning.clean = false;
  ASSERT_TRUE(diffuv::build_labelled_atlas(b.mesh, b.mesh.points(), noisy, follow, raw_b, no_cleaning).ok());
  EXPECT_FALSE(clean_b.cleaning.empty());

  auto mean_error = [&](const Atlas& atlas_b, std::size_t& unmapped) {
    const Correspondence c(atlas_a, atlas_b);
    const auto images = c.map_vertices();
    double sum = 0;
    unmapped = 0;
    for(auto v : vertices(a)) {
      if(!images[v.idx()].mapped()) { ++unmapped; continue; }
      sum += std::sqrt(CGAL::squared_distance(images[v.idx()].point, b.mesh.point(b.vertex_of[v.idx()])));
    }
    return sum / (num_vertices(a) - unmapped) / sqrt_area(b.mesh);
  };
  std::size_t unmapped_clean = 0, unmapped_raw = 0;
  const double clean_error = mean_error(clean_b, unmapped_clean);
  const double raw_error = mean_error(raw_b, unmapped_raw);
  // Measured: 0.013 cleaned, 0.019 raw (mean error / sqrt(area); 0.026 and
  // 0.056 before corners were placed so that no triangle is flat); every
  // seventh border face is a harsher noise than a transfer makes.
  EXPECT_EQ(unmapped_clean, 0u);
  EXPECT_LT(clean_error, 0.04);
  EXPECT_TRUE(unmapped_raw > 0 || raw_error > 1.3 * clean_error)
      << "raw: " << raw_error << " (" << unmapped_raw << " unmapped), cleaned: " << clean_error;
  // The cleaned patches took the corners of A's (named by their regions).
  for(const auto& patch : clean_b.patches) EXPECT_TRUE(patch.side_report.named);
}

// Per-vertex values of B pulled onto A: interpolating B's own coordinates gives
// back the mapped point, colours are rounded, points are affine mixes.
TEST(Correspondence, TransferInterpolatesBarycentrically)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  const Moved_copy b = shuffled_moved_copy(a, 2, true);
  Atlas atlas_a(a), atlas_b(b.mesh);
  build(a, labels, atlas_a);
  build(b.mesh, carry_labels(labels, b), atlas_b);
  const Correspondence c(atlas_a, atlas_b);
  const auto images = c.map_vertices();

  std::vector<double> x_of(num_vertices(b.mesh));
  std::vector<diffuv::Color> color_of(num_vertices(b.mesh));
  for(auto v : vertices(b.mesh)) {
    x_of[v.idx()] = b.mesh.point(v).x();
    color_of[v.idx()] = {static_cast<unsigned char>(v.idx() % 256), 200, 7};
  }
  const auto vindex = get(boost::vertex_index, b.mesh);
  const auto xs = diffuv::transfer_vertex_values(b.mesh, images, boost::make_iterator_property_map(x_of.begin(), vindex), -1.);
  const auto points = diffuv::transfer_vertex_values(b.mesh, images, b.mesh.points(), Point_3(0, 0, 0));
  const auto colors = diffuv::transfer_vertex_values(b.mesh, images, boost::make_iterator_property_map(color_of.begin(), vindex),
                                                     diffuv::Color{0, 0, 0});
  for(auto v : vertices(a)) {
    EXPECT_NEAR(xs[v.idx()], images[v.idx()].point.x(), 1e-9 * b.scale);
    EXPECT_LT(std::sqrt(CGAL::squared_distance(points[v.idx()], images[v.idx()].point)), 1e-9 * b.scale);
    // A vertex mapped onto a vertex of B takes its colour exactly.
    EXPECT_EQ(colors[v.idx()], color_of[b.vertex_of[v.idx()].idx()]);
    EXPECT_EQ(colors[v.idx()].g, 200);
  }
  // A point halfway along an edge of B: colour channels averaged and rounded.
  const face_descriptor f = *faces(b.mesh).begin();
  diffuv::Surface_point<Mesh, Point_3> mid;
  mid.face = f;
  mid.chart = 0;
  mid.barycentric = {{0.5, 0.5, 0.}};
  std::vector<diffuv::Color> two(num_vertices(b.mesh));
  const auto h = b.mesh.halfedge(f);
  two[b.mesh.source(h).idx()] = {10, 255, 0};
  two[b.mesh.target(h).idx()] = {11, 0, 0};
  const auto mixed = diffuv::interpolate_at(b.mesh, mid, boost::make_iterator_property_map(two.begin(), vindex));
  EXPECT_EQ(mixed, (diffuv::Color{11, 128, 0})); // 10.5 and 127.5 round away from zero
  // Arrays of bytes mix the same way, entry by entry.
  std::vector<std::array<unsigned char, 3>> bytes(num_vertices(b.mesh), {{0, 0, 0}});
  bytes[b.mesh.source(h).idx()] = {{10, 255, 0}};
  bytes[b.mesh.target(h).idx()] = {{11, 0, 0}};
  EXPECT_EQ(diffuv::interpolate_at(b.mesh, mid, boost::make_iterator_property_map(bytes.begin(), vindex)),
            (std::array<unsigned char, 3>{{11, 128, 0}}));
}

// Labels given to a copy by nearest face are the original labels.
TEST(Correspondence, NearestFaceLabelsOfAnExactCopy)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  const Moved_copy b = shuffled_moved_copy(a, 4, false);
  EXPECT_EQ(diffuv::nearest_face_labels(a, labels, b.mesh), carry_labels(labels, b));
}

// Runs of neighbours around a patch, counted here from its border halfedges
// (not through patch_loops()): the rule of split_regions_into_quads() is
// "split a region whose border changes neighbour k != 4 times and has k = 3
// or 5..9 runs of at least a tenth of its perimeter (same-neighbour runs
// joined across shorter ones)". Returns 0 for a patch whose border is not one
// simple loop.
std::size_t runs_that_count(const Mesh& m, const diffuv::Segmentation<Mesh>& seg, std::size_t p, std::size_t& changes)
{
  using halfedge_descriptor = Mesh::Halfedge_index;
  const std::size_t border = std::numeric_limits<std::size_t>::max();
  std::map<vertex_descriptor, halfedge_descriptor> leaving;  // border halfedge of p by its source
  for(face_descriptor f : seg.patch_faces[p])
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
      const face_descriptor g = m.face(m.opposite(h));
      if(g != Mesh::null_face() && seg.face_patch[g.idx()] == p) continue;
      if(!leaving.emplace(m.source(h), h).second) return 0;  // the border touches itself
    }
  std::vector<std::size_t> neighbour;
  std::vector<double> length;
  halfedge_descriptor h = leaving.begin()->second;
  for(std::size_t steps = 0; steps < leaving.size(); ++steps) {
    const face_descriptor g = m.face(m.opposite(h));
    neighbour.push_back(g == Mesh::null_face() ? border : seg.face_patch[g.idx()]);
    length.push_back(std::sqrt(CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h)))));
    h = leaving.at(m.target(h));
  }
  if(h != leaving.begin()->second) return 0;  // more than one loop
  const std::size_t n = neighbour.size();
  std::vector<std::size_t> run_start;
  for(std::size_t i = 0; i < n; ++i)
    if(neighbour[i] != neighbour[(i + n - 1) % n]) run_start.push_back(i);
  changes = run_start.size();
  if(changes < 2) return changes;
  const double perimeter = std::accumulate(length.begin(), length.end(), 0.);
  std::vector<std::size_t> long_runs;  // their neighbours, in order
  for(std::size_t j = 0; j < run_start.size(); ++j) {
    double l = 0;
    for(std::size_t i = run_start[j]; i != run_start[(j + 1) % run_start.size()]; i = (i + 1) % n) l += length[i];
    if(l >= 0.1 * perimeter) long_runs.push_back(neighbour[run_start[j]]);
  }
  std::vector<std::size_t> joined;
  for(std::size_t q : long_runs)
    if(joined.empty() || joined.back() != q) joined.push_back(q);
  while(joined.size() > 1 && joined.front() == joined.back()) joined.pop_back();
  return joined.size();
}

// The sub-patches of labelled regions: each region with 3 or 5..9 runs of
// neighbours becomes that many discs, each with its four corners on its
// border, sharing one centre inside the region, the centre's sector keys
// numbered 100·part + 10·k + s + 1; every other region stays as it was.
TEST(SubPatches, RegionsOfThreeOrFiveToNineRunsBecomeFourSidedSectors)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  diffuv::Segmentation<Mesh> regions;
  ASSERT_TRUE(diffuv::disc_patches(a, a.points(), labels, regions, diffuv::Labelled_atlas_options().patching).ok());
  std::map<std::pair<int, int>, std::size_t> expected;  // (label, part) of a region -> its runs, if split
  std::size_t whole = 0;
  for(std::size_t p = 0; p < regions.number_of_patches(); ++p) {
    std::size_t changes = 0;
    const std::size_t k = runs_that_count(a, regions, p, changes);
    if(changes != 4 && (k == 3 || (k >= 5 && k <= 9))) expected[{regions.patch_label[p], regions.patch_part[p]}] = k;
    else ++whole;
  }
  ASSERT_GE(expected.size(), 3u) << "cow's 12 Voronoi regions should have several with 3 or 5+ runs";

  diffuv::Segmentation<Mesh> seg = regions;
  const diffuv::Sub_patch_report report = diffuv::split_regions_into_quads(a, a.points(), seg);
  EXPECT_EQ(report.regions_split + report.not_split, expected.size());
  EXPECT_LE(report.not_split, 1u);
  ASSERT_EQ(report.runs.size(), regions.number_of_patches());

  std::size_t sectors_seen = 0, whole_seen = 0;
  for(std::size_t p = 0; p < regions.number_of_patches(); ++p) {
    const auto it = expected.find({regions.patch_label[p], regions.patch_part[p]});
    std::vector<std::size_t> pieces;  // the patches of seg on region p's faces
    for(face_descriptor f : regions.patch_faces[p]) pieces.push_back(seg.face_patch[f.idx()]);
    std::sort(pieces.begin(), pieces.end());
    pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
    if(report.runs[p].empty()) {
      ASSERT_EQ(pieces.size(), 1u);
      EXPECT_EQ(seg.patch_faces[pieces[0]].size(), regions.patch_faces[p].size());
      EXPECT_EQ(seg.patch_part[pieces[0]], regions.patch_part[p]);
      ++whole_seen;
      continue;
    }
    ASSERT_NE(it, expected.end()) << "region " << p << " was split but has 4 runs or more than 9";
    const std::size_t k = it->second;
    EXPECT_EQ(report.runs[p].size(), k);
    ASSERT_EQ(pieces.size(), k);
    std::size_t faces_in_sectors = 0;
    vertex_descriptor centre = Mesh::null_vertex();
    for(std::size_t s = 0; s < k; ++s) {
      const std::size_t q = pieces[s];
      ++sectors_seen;
      faces_in_sectors += seg.patch_faces[q].size();
      EXPECT_EQ(seg.patch_label[q], regions.patch_label[p]);
      const int part = seg.patch_part[q] - 100 * regions.patch_part[p] - 10 * static_cast<int>(k);
      EXPECT_TRUE(part >= 1 && part <= static_cast<int>(k)) << seg.patch_part[q];
      // A disc: one border loop and Euler characteristic 1.
      std::size_t changes = 0;
      EXPECT_GT(runs_that_count(a, seg, q, changes), 0u) << "sector " << q << " has no simple border";
      std::set<vertex_descriptor> vs;
      std::set<std::pair<vertex_descriptor, vertex_descriptor>> es;
      for(face_descriptor f : seg.patch_faces[q])
        for(auto h : CGAL::halfedges_around_face(a.halfedge(f), a)) {
          vs.insert(a.source(h));
          es.insert(std::minmax(a.source(h), a.target(h)));
        }
      EXPECT_EQ(static_cast<long>(vs.size()) - static_cast<long>(es.size()) + static_cast<long>(seg.patch_faces[q].size()), 1);
      // Four distinct corners, all on the sector's border; the first is the shared centre.
      const auto* corners = seg.corners(q);
      ASSERT_NE(corners, nullptr);
      std::set<vertex_descriptor> distinct(corners->begin(), corners->end());
      EXPECT_EQ(distinct.size(), 4u);
      if(s == 0) centre = (*corners)[0];
      EXPECT_EQ((*corners)[0], centre);
      for(vertex_descriptor c : *corners) {
        bool on_border = false;
        for(auto h : CGAL::halfedges_around_target(c, a)) {
          const face_descriptor f1 = a.face(h), f2 = a.face(a.opposite(h));
          const bool in1 = f1 != Mesh::null_face() && seg.face_patch[f1.idx()] == q;
          const bool in2 = f2 != Mesh::null_face() && seg.face_patch[f2.idx()] == q;
          on_border = on_border || in1 != in2;
        }
        EXPECT_TRUE(on_border) << "corner " << c.idx() << " of sector " << q;
      }
    }
    EXPECT_EQ(faces_in_sectors, regions.patch_faces[p].size());
    // The centre lies inside the region: every face around it is the region's.
    for(face_descriptor f : CGAL::faces_around_target(a.halfedge(centre), a))
      EXPECT_TRUE(f != Mesh::null_face() && regions.face_patch[f.idx()] == p);
  }
  EXPECT_EQ(sectors_seen, report.sub_patches);
  EXPECT_EQ(whole_seen + report.regions_split, regions.number_of_patches());
  EXPECT_GE(whole_seen, whole);
}

// The split depends on the surface and the labels only: a shuffled copy gets
// (shuffled, or also rotated and scaled) gets the same sectors, face for
// face, with the same corners.
TEST(SubPatches, SameSectorsOnAShuffledCopy)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  for(bool move : {false, true}) {
  SCOPED_TRACE(move ? "moved copy" : "shuffled copy");
  const Moved_copy b = shuffled_moved_copy(a, 17, move);
  Atlas atlas_a(a), atlas_b(b.mesh);
  diffuv::Labelled_atlas_options options;
  options.sub_patches = true;
  build(a, labels, atlas_a, options);
  build(b.mesh, carry_labels(labels, b), atlas_b, options);
  ASSERT_GT(atlas_a.sub_patching.regions_split, 0u);
  EXPECT_EQ(atlas_a.split_runs, atlas_b.split_runs);
  const auto keys_a = diffuv::patch_keys(atlas_a.segmentation), keys_b = diffuv::patch_keys(atlas_b.segmentation);
  std::map<diffuv::Patch_key, std::size_t> patch_b;
  for(std::size_t q = 0; q < keys_b.size(); ++q) patch_b[keys_b[q]] = q;
  ASSERT_EQ(patch_b.size(), keys_a.size());
  const auto& seg_a = atlas_a.segmentation;
  const auto& seg_b = atlas_b.segmentation;
  for(std::size_t p = 0; p < keys_a.size(); ++p) {
    ASSERT_EQ(patch_b.count(keys_a[p]), 1u);
    const std::size_t q = patch_b[keys_a[p]];
    for(face_descriptor f : seg_a.patch_faces[p]) EXPECT_EQ(seg_b.face_patch[b.face_of[f.idx()].idx()], q);
    if(const auto* corners = seg_a.corners(p)) {
      ASSERT_NE(seg_b.corners(q), nullptr);
      for(int i = 0; i < 4; ++i) EXPECT_EQ((*seg_b.corners(q))[i], b.vertex_of[(*corners)[i].idx()]) << "patch " << p << " corner " << i;
    }
  }
  }
}

// Following: B splits as A did even where its own rule would not (here B's
// options would split nothing), and the shuffled pair still maps exactly.
TEST(SubPatches, AFollowingMeshSplitsAsTheOneItFollows)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  const Moved_copy b = shuffled_moved_copy(a, 23, false);
  Atlas atlas_a(a), atlas_b(b.mesh);
  diffuv::Labelled_atlas_options options;
  options.sub_patches = true;
  build(a, labels, atlas_a, options);
  ASSERT_GT(atlas_a.sub_patching.regions_split, 0u);
  diffuv::Labelled_atlas_options own = options;
  own.sub_patching.split_three = false;
  own.sub_patching.max_runs = 4;
  {
    Atlas alone(b.mesh);
    build(b.mesh, carry_labels(labels, b), alone, own);
    EXPECT_EQ(alone.sub_patching.regions_split, 0u) << "these options should split nothing on their own";
  }
  const diffuv::Atlas_to_follow follow = diffuv::atlas_to_follow(atlas_a);
  ASSERT_TRUE(diffuv::build_labelled_atlas(b.mesh, b.mesh.points(), carry_labels(labels, b), follow, atlas_b, own).ok());
  EXPECT_EQ(atlas_b.split_runs, atlas_a.split_runs);
  EXPECT_EQ(atlas_b.sub_patching.regions_split, atlas_a.sub_patching.regions_split);
  const Correspondence c(atlas_a, atlas_b);
  EXPECT_TRUE(c.report().unmatched_patches_a.empty());
  const auto images = c.map_vertices();
  double worst = 0;
  for(auto v : vertices(a)) {
    ASSERT_TRUE(images[v.idx()].mapped());
    worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(images[v.idx()].point, b.mesh.point(b.vertex_of[v.idx()]))));
  }
  EXPECT_LE(worst, 1e-9 * sqrt_area(b.mesh));
}

// The split is a rule of the surface and the region borders, not of the
// tessellation: on a Loop-subdivided and on an isotropically remeshed cow,
// labelled by nearness to the cow's regions, every region splits into sectors
// with the same keys, and each sector covers nearly the same surface as the
// cow's (the cow's sectors carried over by nearness; the cuts are edge paths
// of each mesh, so they may land a few faces apart).
TEST(SubPatches, SameSectorsOnARemeshedCopy)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  diffuv::Labelled_atlas_options options;
  options.sub_patches = true;
  Atlas atlas_a(a);
  build(a, labels, atlas_a, options);
  ASSERT_GT(atlas_a.sub_patching.regions_split, 2u);
  const auto keys_a = diffuv::patch_keys(atlas_a.segmentation);
  std::vector<int> sector_a(num_faces(a));  // the patch of each face of the cow
  for(auto f : faces(a)) sector_a[f.idx()] = static_cast<int>(atlas_a.segmentation.face_patch[f.idx()]);

  Mesh loop = a;
  CGAL::Subdivision_method_3::Loop_subdivision(loop, CGAL::parameters::number_of_iterations(1));
  Mesh remeshed = a;
  CGAL::Polygon_mesh_processing::isotropic_remeshing(faces(remeshed), 0.012 * sqrt_area(a), remeshed,
                                                     CGAL::parameters::number_of_iterations(3));
  remeshed.collect_garbage();
  for(const Mesh* b : {&loop, &remeshed}) {
    SCOPED_TRACE(b == &loop ? "Loop subdivision" : "isotropic remeshing");
    ASSERT_NE(num_faces(*b), num_faces(a));
    Atlas atlas_b(*b);
    build(*b, diffuv::nearest_face_labels(a, labels, *b), atlas_b, options);
    EXPECT_EQ(atlas_b.split_runs, atlas_a.split_runs);
    const auto keys_b = diffuv::patch_keys(atlas_b.segmentation);
    EXPECT_EQ(std::set<diffuv::Patch_key>(keys_b.begin(), keys_b.end()), std::set<diffuv::Patch_key>(keys_a.begin(), keys_a.end()));
    // Area of each of B's patches, and the part of it nearest the cow's patch of the same key.
    const std::vector<int> carried = diffuv::nearest_face_labels(a, sector_a, *b);
    std::map<diffuv::Patch_key, double> area, agreeing;
    double all = 0, all_agreeing = 0;
    for(auto f : faces(*b)) {
      const std::size_t q = atlas_b.segmentation.face_patch[f.idx()];
      const double fa = CGAL::Polygon_mesh_processing::face_area(f, *b);
      area[keys_b[q]] += fa;
      all += fa;
      if(keys_a[static_cast<std::size_t>(carried[f.idx()])] == keys_b[q]) {
        agreeing[keys_b[q]] += fa;
        all_agreeing += fa;
      }
    }
    // Measured (2026-12-03): 94.3 % of the area on the Loop copy, 91.2 % on
    // the remeshed one; the worst sectors 71 % (Loop: one of region 10's six)
    // and 64 % (remeshed: region 8), where a cut turns a little. A sector
    // matched to the wrong one would be near 0.
    EXPECT_GE(all_agreeing / all, 0.88);
    for(const auto& [key, b_area] : area) {
      if(std::get<1>(key) <= 10) continue;  // a region kept whole (part 0, or a piece of a region cut into discs)
      EXPECT_GE(agreeing[key] / b_area, 0.55) << "sector " << std::get<0>(key) << "/" << std::get<1>(key);
    }
  }
}

} // namespace
