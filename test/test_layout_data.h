// Helpers of the layout tests: what a layout should be, shuffled copies,
// automatic layouts and height bands (test_layout.cpp,
// test_parameterization_chart_rectangle.cpp).
#ifndef DIFFUV_TEST_LAYOUT_DATA_H
#define DIFFUV_TEST_LAYOUT_DATA_H

#include "test_data.h"

#include <diffuv/io/read_obj_charts.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/layout/fan_split.h>
#include <diffuv/layout/quad_layout.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/layout_judge.h>
#include <diffuv/parameterization/parameterize_disc.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/patches/flat_triangles.h>
#include <diffuv/patches/merge_small_patches.h>
#include <diffuv/patches/patches_from_labels.h>
#include <diffuv/patches/region_sides.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>


namespace {

using namespace diffuv_test;
using vertex_descriptor = Mesh::Vertex_index;
using face_descriptor = Mesh::Face_index;
using Seg = diffuv::Segmentation<Mesh>;

// What a layout should be, counted over its patches.
struct Layout_check {
  std::size_t quads = 0;          // patches with corners chosen by the layout
  std::size_t not_discs = 0;      // patches that are not discs
  std::size_t corners_off = 0;    // quads whose corners are not on their border, counter-clockwise
  std::size_t mixed_sides = 0;    // sides of a quad along two patches or more
  std::size_t t_junctions = 0;    // sides of a quad whose neighbour (a quad) has no corner at one of its ends
  std::size_t flat_triangles = 0;     // faces of a quad with their three vertices on one side
};

Layout_check check_layout(const Mesh& m, const Seg& seg)
{
  Layout_check c;
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
    if(!diffuv::check_patch_disc(m, seg, p)) { ++c.not_discs; continue; }
    const auto* corners = seg.corners(p);
    if(!corners) continue;
    ++c.quads;
    diffuv::Four_sides<vertex_descriptor> sides;
    if(!diffuv::region_sides(m, m.points(), seg, p, sides)) { ++c.corners_off; continue; }
    c.flat_triangles += diffuv::flat_triangles(m, seg, p, sides).size();
    const auto loop = diffuv::patch_loops(m, m.points(), seg, p).front();
    const std::size_t n = loop.vertices.size();
    std::array<std::size_t, 4> at{};
    for(std::size_t k = 0; k < 4; ++k)
      at[k] = static_cast<std::size_t>(std::find(loop.vertices.begin(), loop.vertices.end(), (*corners)[k]) - loop.vertices.begin());
    for(std::size_t k = 0; k < 4; ++k) {
      std::set<std::size_t> along;
      for(std::size_t i = at[k]; i != at[(k + 1) % 4]; i = (i + 1) % n) along.insert(loop.neighbour[i]);
      if(along.size() != 1) { ++c.mixed_sides; continue; }
      const std::size_t q = *along.begin();
      if(q == diffuv::Patch_loop<Mesh>::mesh_border || !seg.corners(q)) continue;
      const auto& theirs = *seg.corners(q);
      for(vertex_descriptor end : {(*corners)[k], (*corners)[(k + 1) % 4]})
        if(std::find(theirs.begin(), theirs.end(), end) == theirs.end()) ++c.t_junctions;
    }
  }
  return c;
}

// A copy of `m` with its vertices and faces in a random order; face k of the
// copy is face fperm[k] of `m`, vertex i of `m` is vertex vperm[i] of the copy.
struct Shuffled {
  Mesh mesh;
  std::vector<std::size_t> vperm, fperm;
};

Shuffled shuffled_copy(const Mesh& m, unsigned seed)
{
  Shuffled s;
  std::mt19937 rng(seed);
  s.vperm.resize(num_vertices(m));
  s.fperm.resize(num_faces(m));
  std::iota(s.vperm.begin(), s.vperm.end(), 0);
  std::iota(s.fperm.begin(), s.fperm.end(), 0);
  std::shuffle(s.vperm.begin(), s.vperm.end(), rng);
  std::shuffle(s.fperm.begin(), s.fperm.end(), rng);
  std::vector<std::size_t> inverse(s.vperm.size());
  for(std::size_t i = 0; i < s.vperm.size(); ++i) inverse[s.vperm[i]] = i;
  for(std::size_t k = 0; k < inverse.size(); ++k) s.mesh.add_vertex(m.point(vertex_descriptor(Mesh::size_type(inverse[k]))));
  for(std::size_t k = 0; k < s.fperm.size(); ++k) {
    std::vector<vertex_descriptor> fv;
    for(auto v : vertices_around_face(m.halfedge(face_descriptor(Mesh::size_type(s.fperm[k]))), m))
      fv.push_back(vertex_descriptor(Mesh::size_type(s.vperm[v.idx()])));
    s.mesh.add_face(fv);
  }
  return s;
}

Seg automatic_layout(const Mesh& m, diffuv::Patching_report* report = nullptr)
{
  Seg seg;
  EXPECT_TRUE(diffuv::disc_patches(m, m.points(), {}, seg, diffuv::Patching_options(), report).ok());
  return seg;
}

// The default mapping, its charts drawn on plain rectangles (no warps), as
// the layout's own searches and judge map patches: tests of the layout's
// choices measure them by the layout's own yardstick.
inline diffuv::Patch_parameterization_options as_the_layout_maps()
{
  diffuv::Patch_parameterization_options options;
  options.drawing.pieces = 0;
  return options;
}

// Each patch of `seg` mapped as the layout maps it and measured on its chart
// (an empty summary where the patch could not be mapped, which fails).
std::vector<diffuv::Distortion_summary> map_each_patch(const Mesh& m, const Seg& seg)
{
  diffuv::Uv_atlas<Mesh> atlas(m);
  const auto results = diffuv::parameterize_patches(m, m.points(), seg, atlas, as_the_layout_maps());
  std::vector<diffuv::Distortion_summary> d(results.size());
  for(std::size_t p = 0; p < results.size(); ++p) {
    EXPECT_TRUE(results[p].status.ok()) << p;
    if(results[p].status.ok())
      d[p] = diffuv::measure_distortion(m, m.points(), atlas.chart(results[p].chart).faces, atlas.chart_texture_map(results[p].chart));
  }
  return d;
}

double height(const Mesh& m, face_descriptor f, int axis)
{
  double sum = 0;
  for(auto v : vertices_around_face(m.halfedge(f), m)) sum += m.point(v)[axis];
  return sum / 3;
}

// Labels of m's faces by the height of their centroid along `axis`: `bands`
// bands of equal height, 0 at the bottom (scripts/height_labels.py).
std::vector<int> height_bands(const Mesh& m, int axis, int bands)
{
  double low = 1e300, high = -1e300;
  for(auto v : vertices(m)) { low = std::min(low, m.point(v)[axis]); high = std::max(high, m.point(v)[axis]); }
  std::vector<int> labels(num_faces(m));
  for(auto f : faces(m)) labels[f.idx()] = std::min(bands - 1, static_cast<int>(bands * (height(m, f, axis) - low) / (high - low)));
  return labels;
}

} // namespace

#endif // DIFFUV_TEST_LAYOUT_DATA_H
