// Regression tests of what the sweep over CGAL's data set found
// (doc/robustness.md, `ctest -L sweep`): one test per fix.
#include "test_data.h"

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/patches/merge_small_patches.h>
#include <diffuv/patches/patches_from_labels.h>

#include <string>
#include <vector>

namespace {

using namespace diffuv_test;
using Seg = diffuv::Segmentation<Mesh>;

// Every patch of `seg` is mapped, one-to-one, inside the unit square.
void expect_all_patches_mapped(const Mesh& m, const Seg& seg, const std::string& name)
{
  diffuv::Uv_atlas<Mesh> atlas(m);
  const auto results = diffuv::parameterize_patches(m, m.points(), seg, atlas);
  ASSERT_EQ(results.size(), seg.number_of_patches()) << name;
  for(std::size_t p = 0; p < results.size(); ++p) {
    ASSERT_TRUE(results[p].status.ok()) << name << " patch " << p << ": " << results[p].status.what();
    const auto& chart = atlas.chart(results[p].chart);
    const auto d = diffuv::measure_distortion(m, m.points(), chart.faces, atlas.chart_uv_map(results[p].chart));
    EXPECT_EQ(d.flipped, 0u) << name << " patch " << p;
    EXPECT_EQ(d.degenerate, 0u) << name << " patch " << p;
    for(auto v : chart.vertices) {
      const auto uv = get(atlas.chart_uv_map(results[p].chart), v);
      EXPECT_TRUE(uv.x() >= 0. && uv.x() <= 1. && uv.y() >= 0. && uv.y() <= 1.) << name << " patch " << p;
    }
  }
}

// A triangular bipyramid: apexes above and below a triangle (5 vertices, 6 faces),
// like the smallest closed components of CGAL's b9_mesh.off.
Mesh bipyramid()
{
  Mesh m;
  const auto n = m.add_vertex(Point_3(0, 0, 1)), s = m.add_vertex(Point_3(0, 0, -1));
  const auto a = m.add_vertex(Point_3(1, 0, 0)), b = m.add_vertex(Point_3(-0.5, 0.85, 0)),
             c = m.add_vertex(Point_3(-0.5, -0.85, 0));
  m.add_face(n, a, b);
  m.add_face(n, b, c);
  m.add_face(n, c, a);
  m.add_face(s, b, a);
  m.add_face(s, c, b);
  m.add_face(s, a, c);
  return m;
}

// tetrahedron.off, reference_tetrahedron.off (and b9_mesh.off's closed
// components of 4 and 6 faces): the automatic patches started from one seed
// per face, the one-face patches were merged one after the other into the
// neighbour sharing the longest border, and the whole closed mesh ended as one
// patch ("the mesh is closed, not a topological disc", exit 1). A small patch
// now goes to a neighbour with which it has at least four boundary vertices
// when one exists: a tetrahedron gives two two-triangle discs.
TEST(SweepRegressions, TinyClosedMeshesAreCutIntoDiscs)
{
  for(const std::string name : {"tetrahedron.off", "reference_tetrahedron.off"}) {
    const Mesh& m = cgal_mesh(name);
    ASSERT_EQ(num_faces(m), 4u) << name;
    // The Voronoi layout: two patches of two faces.
    Seg seg;
    diffuv::Patching_options voronoi;
    voronoi.layout = diffuv::Patch_layout::voronoi;
    const diffuv::Status status = diffuv::disc_patches(m, m.points(), std::vector<int>(), seg, voronoi);
    ASSERT_TRUE(status.ok()) << name << ": " << status.what();
    ASSERT_EQ(seg.number_of_patches(), 2u) << name;
    for(std::size_t p = 0; p < 2; ++p) EXPECT_EQ(seg.patch_faces[p].size(), 2u) << name;
    expect_all_patches_mapped(m, seg, name);
    // The four-sided layout (default): discs too, each of them mapped.
    Seg quads;
    ASSERT_TRUE(diffuv::disc_patches(m, m.points(), std::vector<int>(), quads).ok()) << name;
    expect_all_patches_mapped(m, quads, name + ", four-sided layout");
  }
  const Mesh m = bipyramid();
  Seg seg;
  const diffuv::Status status = diffuv::disc_patches(m, m.points(), std::vector<int>(), seg);
  ASSERT_TRUE(status.ok()) << status.what();
  expect_all_patches_mapped(m, seg, "bipyramid");
}

// colored_tetra.ply: one colour per face, so four one-face regions, merged
// into one closed patch as above. Now two regions of two faces each.
TEST(SweepRegressions, OneFaceRegionsOfATetrahedronMergeIntoTwoDiscs)
{
  const Mesh& m = cgal_mesh("tetrahedron.off");
  Seg seg;
  const diffuv::Status status = diffuv::disc_patches(m, m.points(), std::vector<int>{0, 1, 2, 3}, seg);
  ASSERT_TRUE(status.ok()) << status.what();
  ASSERT_EQ(seg.number_of_patches(), 2u);
  expect_all_patches_mapped(m, seg, "tetrahedron, labels 0 1 2 3");
}

// The rule only picks among neighbours when the usual one (the longest shared
// border) would leave too few boundary vertices: a lone triangle still joins
// the region it shares the most border with, not the other lone triangle of
// its cell, although both unions have four boundary vertices or more.
TEST(SweepRegressions, MergeStillPrefersTheLongestSharedBorder)
{
  const Mesh grid = make_grid(4, 4);
  // Cell (1, 1): its upper triangle (face 11) has label 1, its lower one (face
  // 10) label 2, the rest of the grid label 9. Face 11 shares two edges (0.5)
  // with label 9 and the diagonal (0.35) with face 10.
  std::vector<int> labels(num_faces(grid), 9);
  labels[11] = 1;
  labels[10] = 2;
  Seg seg = diffuv::patches_from_labels(grid, grid.points(), labels);
  ASSERT_EQ(seg.number_of_patches(), 3u);
  EXPECT_EQ(diffuv::merge_small_patches(grid, grid.points(), labels, seg), 2u);
  EXPECT_EQ(labels[11], 9);
  EXPECT_EQ(labels[10], 9);
  EXPECT_EQ(seg.number_of_patches(), 1u);
}

// cheese.off with --strict: `strict` is about given regions, but it also
// refused the tool's own automatic patches when voronoi_discs() left one that
// was not a disc ("patch 0 (label 0): 2 boundary loops", exit 1), where
// without --strict the patch is cut further. Here: one seed at most, so the
// automatic patch is the whole closed sphere, cut into discs afterwards.
TEST(SweepRegressions, StrictDoesNotRefuseAutomaticPatches)
{
  const Mesh& m = cgal_mesh("larger_sphere.off");
  diffuv::Patching_options options;
  options.layout = diffuv::Patch_layout::voronoi;  // the layout with automatic.patches
  options.automatic.patches = 1;
  options.automatic.max_patches = 1;
  Seg loose, strict;
  ASSERT_TRUE(diffuv::disc_patches(m, m.points(), std::vector<int>(), loose, options).ok());
  options.strict = true;
  diffuv::Patching_report report;
  const diffuv::Status status = diffuv::disc_patches(m, m.points(), std::vector<int>(), strict, options, &report);
  ASSERT_TRUE(status.ok()) << status.what();
  EXPECT_GE(report.cut, 1u);
  EXPECT_EQ(strict.face_patch, loose.face_patch);

  // Given regions are still refused: the whole sphere labelled as one region.
  Seg refused;
  EXPECT_FALSE(diffuv::disc_patches(m, m.points(), std::vector<int>(num_faces(m), 0), refused, options).ok());
}

} // namespace
