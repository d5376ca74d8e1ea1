// Tests of patches/: patches from labels (patches_from_labels.h), canonical
// sides (region_sides.h), the disc check, border smoothing, small pieces, non-disc regions, caps (split_cap.h), junction cuts (split_at_junctions.h).
#include "test_data.h"

#include <diffuv/graph/patch_graph.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/layout/voronoi_discs.h>
#include <diffuv/parameterization/parameterize_disc.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/patches/flat_triangles.h>
#include <diffuv/patches/merge_small_patches.h>
#include <diffuv/patches/patches_from_labels.h>
#include <diffuv/patches/region_sides.h>
#include <diffuv/patches/smooth_region_borders.h>
#include <diffuv/patches/split_at_junctions.h>
#include <diffuv/patches/split_cap.h>

#include <CGAL/boost/graph/Face_filtered_graph.h>

#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <string>

namespace {

using namespace diffuv_test;
using vertex_descriptor = Mesh::Vertex_index;
using face_descriptor = Mesh::Face_index;
using Seg = diffuv::Segmentation<Mesh>;

Point_3 face_centroid(const Mesh& m, face_descriptor f)
{
  auto h = m.halfedge(f);
  return CGAL::centroid(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
}

// A 3x3 block labelling of a 9x9 grid: block (bx, by) has label 3 * by + bx.
std::vector<int> block_labels(const Mesh& grid)
{
  std::vector<int> labels(num_faces(grid));
  for(auto f : faces(grid)) {
    const Point_3 c = face_centroid(grid, f);
    labels[f.idx()] = 3 * std::min(2, int(c.y() * 3)) + std::min(2, int(c.x() * 3));
  }
  return labels;
}

// A closed round mesh of CGAL's data set (812 vertices).
const Mesh& sphere() { return cgal_mesh("larger_sphere.off"); }

// Labels of a closed round mesh by height: caps above and below, a band between.
std::vector<int> banded_labels(const Mesh& m, double cap)
{
  std::vector<int> labels(num_faces(m));
  double zmin = 1e300, zmax = -1e300;
  for(auto v : vertices(m)) { zmin = std::min(zmin, m.point(v).z()); zmax = std::max(zmax, m.point(v).z()); }
  for(auto f : faces(m)) {
    const double t = (face_centroid(m, f).z() - zmin) / (zmax - zmin);
    labels[f.idx()] = t > 1 - cap ? 2 : (t < cap ? 0 : 1);
  }
  return labels;
}

TEST(Patches, ComponentsOfLabelsInCanonicalOrder)
{
  const Mesh grid = make_grid(9, 9);
  std::vector<int> labels = block_labels(grid);
  // Give blocks 0 and 8 (opposite corners, not adjacent) the same label 20:
  // two components of one label, ordered by decreasing area.
  for(auto f : faces(grid)) {
    if(labels[f.idx()] == 0) labels[f.idx()] = 20;
  }
  // Make block 8 larger by also relabelling block 7 -> 20 (adjacent to 8: one component of 2 blocks).
  for(auto f : faces(grid))
    if(labels[f.idx()] == 8 || labels[f.idx()] == 7) labels[f.idx()] = 20;
  const Seg seg = diffuv::patches_from_labels(grid, grid.points(), labels);
  ASSERT_EQ(seg.number_of_patches(), 8u); // labels 1..6 and two components of 20
  for(std::size_t p = 0; p < 6; ++p) EXPECT_EQ(seg.patch_label[p], int(p) + 1);
  EXPECT_EQ(seg.patch_label[6], 20);
  EXPECT_EQ(seg.patch_label[7], 20);
  EXPECT_EQ(seg.patch_faces[6].size(), 36u); // blocks 7 and 8, larger first
  EXPECT_EQ(seg.patch_faces[7].size(), 18u); // block 0
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
    for(auto f : seg.patch_faces[p]) EXPECT_EQ(seg.face_patch[f.idx()], p);
}

TEST(Patches, BordersBetweenRegionsAreTheSides)
{
  const Mesh grid = make_grid(9, 9);
  const Seg seg = diffuv::patches_from_labels(grid, grid.points(), block_labels(grid));
  const std::size_t centre = 4; // label 4: neighbours 1 (below), 5 (right), 7 (above), 3 (left)
  ASSERT_EQ(seg.patch_label[centre], 4);
  diffuv::Four_sides<vertex_descriptor> sides;
  diffuv::Side_report report;
  ASSERT_TRUE(diffuv::region_sides(grid, grid.points(), seg, centre, sides, {}, &report).ok());
  EXPECT_EQ(report.runs, 4u);
  EXPECT_EQ(report.merged + report.split, 0u);
  // Junctions are the block's corners; the side towards the smallest label (1, below) is v1.
  EXPECT_EQ(sides.corners[0], grid_vertex(9, 3, 3));
  EXPECT_EQ(sides.corners[1], grid_vertex(9, 6, 3));
  EXPECT_EQ(sides.corners[2], grid_vertex(9, 6, 6));
  EXPECT_EQ(sides.corners[3], grid_vertex(9, 3, 6));
  EXPECT_EQ(sides.v1.size(), 4u);

  // A corner block: two neighbours and the mesh border (first in the order).
  diffuv::Four_sides<vertex_descriptor> corner_sides;
  ASSERT_TRUE(diffuv::region_sides(grid, grid.points(), seg, 0, corner_sides, {}, &report).ok());
  EXPECT_EQ(report.runs, 3u); // border, label 1, label 3 -> the border run is split
  EXPECT_EQ(report.split, 1u);
}

TEST(Patches, SideOrderDependsOnLabelsNotOnVertexOrFaceOrder)
{
  // Cow, cut automatically; then the same labelled surface with vertices and
  // faces shuffled must give every vertex the same (patch, u, v).
  const Mesh& cow = cgal_mesh("cow.off");
  std::vector<int> labels(num_faces(cow), 0);
  diffuv::voronoi_discs(cow, cow.points(), std::vector<face_descriptor>(faces(cow).begin(), faces(cow).end()), labels, 0);

  std::mt19937 rng(11);
  std::vector<std::size_t> vperm(num_vertices(cow)), fperm(num_faces(cow));
  std::iota(vperm.begin(), vperm.end(), 0);
  std::iota(fperm.begin(), fperm.end(), 0);
  std::shuffle(vperm.begin(), vperm.end(), rng);
  std::shuffle(fperm.begin(), fperm.end(), rng); // new face k is old face fperm[k]
  Mesh shuffled;
  std::vector<std::size_t> vinv(vperm.size());
  for(std::size_t i = 0; i < vperm.size(); ++i) vinv[vperm[i]] = i; // old i -> new vperm[i]
  for(std::size_t k = 0; k < vperm.size(); ++k) shuffled.add_vertex(cow.point(vertex_descriptor(Mesh::size_type(vinv[k]))));
  std::vector<int> shuffled_labels;
  for(std::size_t k = 0; k < fperm.size(); ++k) {
    std::vector<vertex_descriptor> fv;
    for(auto v : vertices_around_face(cow.halfedge(face_descriptor(Mesh::size_type(fperm[k]))), cow))
      fv.push_back(vertex_descriptor(Mesh::size_type(vperm[v.idx()])));
    shuffled.add_face(fv);
    shuffled_labels.push_back(labels[fperm[k]]);
  }

  Seg a, b;
  ASSERT_TRUE(diffuv::disc_patches(cow, cow.points(), labels, a).ok());
  ASSERT_TRUE(diffuv::disc_patches(shuffled, shuffled.points(), shuffled_labels, b).ok());
  ASSERT_EQ(a.number_of_patches(), b.number_of_patches());
  diffuv::Uv_atlas<Mesh> atlas_a(cow), atlas_b(shuffled);
  const auto ra = diffuv::parameterize_patches(cow, cow.points(), a, atlas_a);
  const auto rb = diffuv::parameterize_patches(shuffled, shuffled.points(), b, atlas_b);
  std::size_t compared = 0;
  for(std::size_t p = 0; p < a.number_of_patches(); ++p) {
    ASSERT_EQ(a.patch_label[p], b.patch_label[p]);
    ASSERT_TRUE(ra[p].status.ok() && rb[p].status.ok()) << "patch " << p;
    const auto uva = atlas_a.chart_uv_map(ra[p].chart);
    const auto uvb = atlas_b.chart_uv_map(rb[p].chart);
    for(auto v : atlas_a.chart(ra[p].chart).vertices) {
      const Point_2 x = get(uva, v), y = get(uvb, vertex_descriptor(Mesh::size_type(vperm[v.idx()])));
      EXPECT_NEAR(x.x(), y.x(), 1e-12) << "patch " << p << " vertex " << v;
      EXPECT_NEAR(x.y(), y.y(), 1e-12) << "patch " << p << " vertex " << v;
      ++compared;
    }
  }
  EXPECT_GE(compared, num_vertices(cow));
}

TEST(Patches, FastDiscCheckAgreesWithTheFilteredGraphCheck)
{
  // check_patch_disc works on the patch alone; check_disc on a Face_filtered_graph is the reference.
  auto compare = [](const Mesh& m, const std::vector<int>& labels) {
    const Seg seg = diffuv::patches_from_labels(m, m.points(), labels);
    std::size_t bad = 0;
    for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
      const CGAL::Face_filtered_graph<Mesh> patch(m, seg.patch_faces[p]);
      const diffuv::Status reference = diffuv::check_disc(patch), fast = diffuv::check_patch_disc(m, seg, p);
      EXPECT_EQ(fast.ok(), reference.ok()) << "patch " << p << ": " << fast.what() << " / " << reference.what();
      if(!reference.ok()) ++bad;
    }
    return bad;
  };
  const Mesh& s = sphere();
  EXPECT_EQ(compare(s, banded_labels(s, 0.25)), 1u); // the band
  const Mesh& cow = cgal_mesh("cow.off");
  std::vector<int> raw(num_faces(cow));
  for(auto f : faces(cow)) raw[f.idx()] = int(4 * (face_centroid(cow, f).y() + 0.31) / 0.62); // height bands
  EXPECT_GT(compare(cow, raw), 0u);
}

TEST(Patches, DiscCheckGivesTheLoopsItWalked)
{
  // The form with loops answers as the plain one, and its loops are
  // patch_loops()' own: disc or not, once the patch is connected.
  auto same_loops = [](const std::vector<diffuv::Patch_loop<Mesh>>& a, const std::vector<diffuv::Patch_loop<Mesh>>& b) {
    if(a.size() != b.size()) return false;
    for(std::size_t i = 0; i < a.size(); ++i)
      if(a[i].vertices != b[i].vertices || a[i].halfedges != b[i].halfedges || a[i].neighbour != b[i].neighbour ||
         a[i].length != b[i].length)
        return false;
    return true;
  };
  auto compare = [&](const Mesh& m, const Seg& seg) {
    std::size_t not_discs = 0;
    std::vector<diffuv::Patch_loop<Mesh>> loops;
    for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
      const diffuv::Status plain = diffuv::check_patch_disc(m, seg, p);
      const diffuv::Status with_loops = diffuv::check_patch_disc(m, m.points(), seg, p, loops);
      EXPECT_EQ(with_loops.code, plain.code) << "patch " << p;
      EXPECT_TRUE(same_loops(loops, diffuv::patch_loops(m, m.points(), seg, p))) << "patch " << p;
      if(!plain.ok()) ++not_discs;
    }
    return not_discs;
  };
  const Mesh& s = sphere();
  Seg bands = diffuv::patches_from_labels(s, s.points(), banded_labels(s, 0.25));
  EXPECT_EQ(compare(s, bands), 1u);  // the band: two loops
  const Mesh& cow = cgal_mesh("cow.off");
  std::vector<int> raw(num_faces(cow));
  for(auto f : faces(cow)) raw[f.idx()] = int(4 * (face_centroid(cow, f).y() + 0.31) / 0.62); // height bands
  EXPECT_GT(compare(cow, diffuv::patches_from_labels(cow, cow.points(), raw)), 0u);

  // The two caps as one patch: not connected, so no loops (and any left from before cleared).
  ASSERT_EQ(bands.number_of_patches(), 3u);
  std::vector<diffuv::Patch_loop<Mesh>> loops(2);
  for(face_descriptor f : bands.patch_faces[2]) {
    bands.patch_faces[0].push_back(f);
    bands.face_patch[f.idx()] = 0;
  }
  bands.patch_faces[2].clear();
  EXPECT_EQ(diffuv::check_patch_disc(s, s.points(), bands, 0, loops).code, diffuv::Status_code::disconnected_mesh);
  EXPECT_TRUE(loops.empty());
}

TEST(Patches, ConnectedPartsAreThoseOfPatchesFromLabels)
{
  // A set of faces in several components (cow's faces in two height bands
  // and a scatter of lone faces), split with one marks array: the parts,
  // their order and their faces' order are patches_from_labels()' own.
  const Mesh& cow = cgal_mesh("cow.off");
  std::vector<std::size_t> marks;
  for(int band = 0; band < 3; ++band) {
    std::vector<face_descriptor> piece;
    for(auto f : faces(cow)) {
      const int b = int(4 * (face_centroid(cow, f).y() + 0.31) / 0.62);
      if(b == band || b == band + 2 || f.idx() % 97 == 0) piece.push_back(f);
    }
    std::reverse(piece.begin(), piece.end());  // the parts do not depend on the order given
    std::vector<int> labels(num_faces(cow), std::numeric_limits<int>::min());
    for(face_descriptor f : piece) labels[f.idx()] = 0;
    const Seg reference = diffuv::patches_from_labels(cow, cow.points(), labels);
    const auto parts = diffuv::connected_parts(cow, cow.points(), piece, marks);
    ASSERT_GT(reference.number_of_patches(), 2u) << "band " << band;
    ASSERT_EQ(parts.size(), reference.number_of_patches()) << "band " << band;
    for(std::size_t p = 0; p < parts.size(); ++p) EXPECT_EQ(parts[p], reference.patch_faces[p]) << "band " << band << " part " << p;
    EXPECT_TRUE(std::all_of(marks.begin(), marks.end(), [](std::size_t m) { return m == Seg::no_patch; }));
  }
}

TEST(Patches, EarFacesMoveAcrossRegionBorders)
{
  const Mesh grid = make_grid(4, 4);
  std::vector<int> labels(num_faces(grid), 0);
  // One face of label 1 sticking into region 0 along two of its edges... the
  // reverse: a label-0 face surrounded on two sides by label 1.
  for(auto f : faces(grid)) if(face_centroid(grid, f).x() > 0.5) labels[f.idx()] = 1;
  // The lower triangle of cell (1, 1) has edges towards cell (2,1) [label 1] only on one side:
  // flip a face inside region 1 to label 0 so that it has two label-1 neighbours.
  face_descriptor island;
  for(auto f : faces(grid)) {
    const Point_3 c = face_centroid(grid, f);
    if(c.x() > 0.75 && c.y() > 0.25 && c.y() < 0.5 && c.x() - 0.75 > c.y() - 0.25) { island = f; break; }
  }
  labels[island.idx()] = 0;
  const std::size_t changed = diffuv::smooth_region_borders(grid, labels);
  EXPECT_GE(changed, 1u);
  EXPECT_EQ(labels[island.idx()], 1);
}

TEST(Patches, SmallPiecesAreMergedIntoANeighbour)
{
  const Mesh grid = make_grid(6, 6);
  std::vector<int> labels(num_faces(grid), 0);
  labels[17] = 5; // a lone triangle: three boundary vertices, cannot have four sides
  Seg seg = diffuv::patches_from_labels(grid, grid.points(), labels);
  ASSERT_EQ(seg.number_of_patches(), 2u);
  EXPECT_EQ(diffuv::merge_small_patches(grid, grid.points(), labels, seg), 1u);
  EXPECT_EQ(seg.number_of_patches(), 1u);
  EXPECT_EQ(labels[17], 0);
}

TEST(Patches, NonDiscRegionsAreCutIntoDiscsOrReported)
{
  const Mesh& m = sphere();
  const std::vector<int> labels = banded_labels(m, 0.25); // caps 0 and 2 around band 1 (an annulus)
  Seg raw = diffuv::patches_from_labels(m, m.points(), labels);
  ASSERT_EQ(raw.number_of_patches(), 3u);
  EXPECT_EQ(diffuv::check_patch_disc(m, raw, 1).code, diffuv::Status_code::several_borders);

  // Strict: the annulus is reported, not cut.
  diffuv::Patching_options strict;
  strict.strict = true;
  Seg s;
  diffuv::Patching_report sr;
  EXPECT_EQ(diffuv::disc_patches(m, m.points(), labels, s, strict, &sr).code, diffuv::Status_code::several_borders);
  ASSERT_EQ(sr.not_discs.size(), 1u);
  EXPECT_EQ(s.patch_label[sr.not_discs.front()], 1);

  // Default: the annulus is cut into disc pieces, each of label 1, numbered
  // parts (no face handed across regions afterwards, to count them).
  Seg seg;
  diffuv::Patching_report report;
  diffuv::Patching_options cut;
  cut.hand_off_flat_triangles = false;
  ASSERT_TRUE(diffuv::disc_patches(m, m.points(), labels, seg, cut, &report).ok());
  EXPECT_EQ(report.cut, 1u);
  std::size_t band_faces = 0, pieces = 0;
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
    EXPECT_TRUE(diffuv::check_patch_disc(m, seg, p).ok()) << p;
    if(seg.patch_label[p] == 1) {
      ++pieces;
      band_faces += seg.patch_faces[p].size();
      EXPECT_EQ(seg.patch_part[p], int(pieces));
    }
  }
  EXPECT_GE(pieces, 2u);
  EXPECT_EQ(band_faces, raw.patch_faces[1].size()); // no face lost or taken from the caps
}

TEST(Patches, CapsAreSplitInTwo)
{
  // Two regions of a sphere: a cap (label 0) and the rest (label 1). Each has
  // one neighbour all around: both are caps.
  const Mesh& m = sphere();
  const std::vector<int> banded = banded_labels(m, 0.3);
  std::vector<int> labels(banded.size());
  for(std::size_t i = 0; i < banded.size(); ++i) labels[i] = banded[i] == 0 ? 0 : 1;
  Seg raw = diffuv::patches_from_labels(m, m.points(), labels);
  ASSERT_EQ(raw.number_of_patches(), 2u);
  EXPECT_TRUE(diffuv::is_cap(m, m.points(), raw, 0));
  EXPECT_TRUE(diffuv::is_cap(m, m.points(), raw, 1));

  // The Voronoi layout's rule (the four-sided layout cuts every region into cells).
  Seg seg;
  diffuv::Patching_report report;
  diffuv::Patching_options split;
  split.layout = diffuv::Patch_layout::voronoi;
  split.hand_off_flat_triangles = false;  // to count the faces of each cap's halves
  ASSERT_TRUE(diffuv::disc_patches(m, m.points(), labels, seg, split, &report).ok());
  EXPECT_EQ(report.caps_split, 2u);
  ASSERT_EQ(seg.number_of_patches(), 4u);
  const std::vector<int> expected_labels = {0, 0, 1, 1}, expected_parts = {1, 2, 1, 2};
  EXPECT_EQ(seg.patch_label, expected_labels);
  EXPECT_EQ(seg.patch_part, expected_parts);
  for(std::size_t p = 0; p < 4; ++p) {
    EXPECT_TRUE(diffuv::check_patch_disc(m, seg, p).ok()) << p;
    EXPECT_FALSE(diffuv::is_cap(m, m.points(), seg, p)) << p;
  }
  EXPECT_EQ(seg.patch_faces[0].size() + seg.patch_faces[1].size(), raw.patch_faces[0].size());

  // Without the split, the caps stay whole and get equal-arc corners.
  diffuv::Patching_options keep;
  keep.layout = diffuv::Patch_layout::voronoi;
  keep.split_caps = false;
  Seg whole;
  ASSERT_TRUE(diffuv::disc_patches(m, m.points(), labels, whole, keep).ok());
  EXPECT_EQ(whole.number_of_patches(), 2u);
  diffuv::Four_sides<vertex_descriptor> sides;
  diffuv::Side_report side_report;
  ASSERT_TRUE(diffuv::region_sides(m, m.points(), whole, 0, sides, {}, &side_report).ok());
  EXPECT_TRUE(side_report.equal_arcs);

  // A disc mesh as one patch gets the same corners as parameterize_disc(): the
  // sharpest boundary vertex at (0,0), then equal arcs.
  const Mesh& disc = cgal_mesh("nefertiti.off");
  Seg one;
  ASSERT_TRUE(diffuv::disc_patches(disc, disc.points(), {}, one).ok());
  ASSERT_EQ(one.number_of_patches(), 1u);
  diffuv::Four_sides<vertex_descriptor> by_region, by_disc;
  ASSERT_TRUE(diffuv::region_sides(disc, disc.points(), one, 0, by_region).ok());
  diffuv::Uv_atlas<Mesh> atlas(disc);
  diffuv::Disc_parameterization_report<Mesh> disc_report;
  ASSERT_TRUE(diffuv::parameterize_disc(disc, disc.points(), {}, atlas, {}, &disc_report).ok());
  by_disc = disc_report.sides;
  EXPECT_EQ(by_region.corners, by_disc.corners);
}

// Runs of neighbours (junctions) along the one boundary loop of patch p.
std::size_t runs_of(const Mesh& m, const Seg& seg, std::size_t p)
{
  const auto loops = diffuv::patch_loops(m, m.points(), seg, p);
  EXPECT_EQ(loops.size(), 1u);
  const auto& nb = loops.front().neighbour;
  std::size_t runs = 0;
  for(std::size_t i = 0; i < nb.size(); ++i) runs += nb[(i + nb.size() - 1) % nb.size()] != nb[i];
  return runs;
}

// The corners patch p needs: its junctions, and the tips of its ears (boundary
// vertices in one face of p), which are flat unless a corner is there.
std::size_t needed_corners(const Mesh& m, const Seg& seg, std::size_t p)
{
  const auto loop = diffuv::patch_loops(m, m.points(), seg, p).front();
  const std::size_t n = loop.vertices.size();
  std::size_t needed = 0;
  for(std::size_t i = 0; i < n; ++i) {
    std::size_t in_p = 0;
    for(auto f : CGAL::faces_around_target(m.halfedge(loop.vertices[i]), m))
      in_p += f != Mesh::null_face() && seg.face_patch[f.idx()] == p;
    needed += loop.neighbour[(i + n - 1) % n] != loop.neighbour[i] || in_p == 1;
  }
  return needed;
}

TEST(Patches, APatchNeedingManyCornersIsCutBetweenJunctions)
{
  // A 12x12 grid: a central 6x6 block (label 0) inside a ring cut into k
  // wedges by angle around the centre, so the block has k runs of neighbours
  // (and ears at the two corners where the grid's diagonals leave one face).
  const std::size_t n = 12;
  const Mesh grid = make_grid(n, n);
  for(std::size_t k : {3u, 5u, 6u, 8u, 10u}) {
    SCOPED_TRACE("k = " + std::to_string(k));
    std::vector<int> labels(num_faces(grid));
    for(auto f : faces(grid)) {
      const Point_3 c = face_centroid(grid, f);
      const double x = c.x() - 0.5, y = c.y() - 0.5;
      if(std::abs(x) < 0.25 && std::abs(y) < 0.25) { labels[f.idx()] = 0; continue; }
      const double turn = (std::atan2(y, x) + CGAL_PI) / (2 * CGAL_PI);  // in [0, 1]
      labels[f.idx()] = 1 + std::min<int>(int(k) - 1, int(turn * double(k)));
    }
    Seg seg = diffuv::patches_from_labels(grid, grid.points(), labels);
    ASSERT_EQ(seg.patch_label.front(), 0);
    ASSERT_EQ(runs_of(grid, seg, 0), k);
    const std::size_t needed = needed_corners(grid, seg, 0);
    ASSERT_GE(needed, k);
    ASSERT_GT(needed, 4u);
    std::vector<std::size_t> wedge_runs;
    for(std::size_t p = 1; p < seg.number_of_patches(); ++p) wedge_runs.push_back(runs_of(grid, seg, p));
    const std::set<face_descriptor> block(seg.patch_faces[0].begin(), seg.patch_faces[0].end());

    // Cuts of any length here (the default refuses cuts longer than half the
    // arc they cut off, which most cuts across this square are).
    const double any_length = std::numeric_limits<double>::infinity();
    Seg unchanged = seg;
    EXPECT_EQ(diffuv::split_at_junctions(grid, grid.points(), unchanged, 0, 0.01), 1u);
    EXPECT_EQ(unchanged.face_patch, seg.face_patch);
    const std::size_t pieces = diffuv::split_at_junctions(grid, grid.points(), seg, 0, any_length);
    // Each cut makes its two ends corners of both pieces; every piece ends
    // with three or four, so the fewest pieces are ceil((needed - 2) / 2).
    EXPECT_EQ(pieces, (needed - 1) / 2);
    ASSERT_EQ(seg.number_of_patches(), pieces + k);
    std::set<face_descriptor> covered;
    std::size_t all_needed = 0;
    for(std::size_t p = 0; p < pieces; ++p) {
      EXPECT_EQ(seg.patch_label[p], 0);
      EXPECT_TRUE(diffuv::check_patch_disc(grid, seg, p).ok()) << "piece " << p;
      const std::size_t c = needed_corners(grid, seg, p);
      EXPECT_GE(c, 3u) << "piece " << p;
      EXPECT_LE(c, 4u) << "piece " << p;
      all_needed += c;
      covered.insert(seg.patch_faces[p].begin(), seg.patch_faces[p].end());
      // Its corners are its junctions: no run is merged into another.
      diffuv::Four_sides<vertex_descriptor> sides;
      diffuv::Side_report report;
      ASSERT_TRUE(diffuv::region_sides(grid, grid.points(), seg, p, sides, {}, &report).ok());
      EXPECT_EQ(report.merged, 0u);
    }
    EXPECT_EQ(covered, block);
    EXPECT_EQ(all_needed, needed + 2 * (pieces - 1));
    // No wedge gains a junction: the cuts end where its run ends.
    for(std::size_t p = pieces; p < seg.number_of_patches(); ++p)
      EXPECT_EQ(runs_of(grid, seg, p), wedge_runs[p - pieces]) << "wedge " << seg.patch_label[p];
    // A piece that needs four corners or fewer is left as it is.
    for(std::size_t p = 0; p < pieces; ++p) {
      const Seg before = seg;
      EXPECT_EQ(diffuv::split_at_junctions(grid, grid.points(), seg, p, any_length), 1u) << "piece " << p;
      EXPECT_EQ(seg.face_patch, before.face_patch);
    }
  }
}

// Every vertex of a closed mesh gets a (patch, u, v) with u, v in [0,1].
} // namespace
