// Tests of parameterize_patches() (parameterization/parameterize_patches.h)
// and the compact copies of a patch it maps on (graph/patch_graph.h,
// patches/patch_mesh.h).
#include "test_data.h"

#include <diffuv/graph/patch_graph.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/layout/voronoi_discs.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/parameterize_disc.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/patches/flat_triangles.h>
#include <diffuv/patches/merge_small_patches.h>
#include <diffuv/patches/patch_mesh.h>
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
#include <stdexcept>
#include <random>
#include <set>
#include <string>

namespace {

using namespace diffuv_test;
using vertex_descriptor = Mesh::Vertex_index;
using face_descriptor = Mesh::Face_index;
using Seg = diffuv::Segmentation<Mesh>;

// ---------------------------------------------------------------------------
// The fast paths of parameterize_patches() (doc/performance.md): the compact
// patch graph of the paper's method, and patches mapped on several threads.

// Each patch of the automatic patches of `name`, with its sides.
struct Mapped_patches {
  Seg seg;
  std::vector<diffuv::Four_sides<vertex_descriptor>> sides;
};

Mapped_patches automatic_patches(const Mesh& m)
{
  Mapped_patches out;
  EXPECT_TRUE(diffuv::disc_patches(m, m.points(), {}, out.seg).ok());
  out.sides.resize(out.seg.number_of_patches());
  for(std::size_t p = 0; p < out.seg.number_of_patches(); ++p)
    EXPECT_TRUE(diffuv::region_sides(m, m.points(), out.seg, p, out.sides[p]).ok());
  return out;
}

TEST(PatchGraph, DistancesMatchBoostDijkstraOnTheFilteredPatch)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Mapped_patches mp = automatic_patches(cow);
  const auto lengths = diffuv::edge_length_map(cow, cow.points());
  auto findex = get(boost::face_index, cow);
  diffuv::Patch_graph<Mesh> pg; // one object for every patch, as parameterize_patches() uses it
  for(std::size_t p = 0; p < mp.seg.number_of_patches(); ++p) {
    pg.build(cow, mp.seg.patch_faces[p],
             [&](face_descriptor f) { return f != Mesh::null_face() && mp.seg.face_patch[get(findex, f)] == p; }, lengths);
    const CGAL::Face_filtered_graph<Mesh> patch(cow, mp.seg.patch_faces[p]);
    ASSERT_EQ(pg.number_of_vertices(), num_vertices(patch)) << "patch " << p;
    ASSERT_EQ(num_edges(pg.graph()), 2 * num_edges(patch)) << "patch " << p; // both directions of each edge
    for(std::size_t i = 0; i < pg.number_of_vertices(); ++i)
      ASSERT_EQ(pg.local(cow, pg.mesh_vertices()[i]), i);
    std::size_t outside = 0;
    for(vertex_descriptor v : vertices(cow))
      if(!patch.is_in_cc(v)) outside += pg.local(cow, v) == diffuv::Patch_graph<Mesh>::none;
    EXPECT_EQ(outside, num_vertices(cow) - num_vertices(patch)) << "patch " << p;

    // Reference: Boost's Dijkstra on the filtered patch, from side u1, with
    // the same edge lengths.
    auto pindex = get(boost::vertex_index, patch);
    std::vector<double> expected(num_vertices(patch));
    std::vector<boost::graph_traits<CGAL::Face_filtered_graph<Mesh>>::vertex_descriptor> pred(num_vertices(patch));
    boost::dijkstra_shortest_paths(
        patch, mp.sides[p].u1.begin(), mp.sides[p].u1.end(), boost::make_iterator_property_map(pred.begin(), pindex),
        boost::make_iterator_property_map(expected.begin(), pindex), lengths, pindex, std::less<double>(),
        boost::closed_plus<double>(), std::numeric_limits<double>::infinity(), 0.,
        boost::default_dijkstra_visitor());
    std::vector<std::uint32_t> sources;
    for(vertex_descriptor v : mp.sides[p].u1) sources.push_back(pg.local(cow, v));
    std::vector<double> got(pg.number_of_vertices());
    diffuv::Multi_source_dijkstra<diffuv::Patch_graph<Mesh>::Graph> dijkstra(pg.graph());
    ASSERT_TRUE(dijkstra.run(sources, pg.length_map(), boost::make_iterator_property_map(got.begin(), get(boost::vertex_index, pg.graph()))).ok());
    for(vertex_descriptor v : vertices(patch))
      EXPECT_NEAR(got[pg.local(cow, v)], expected[get(pindex, v)], 1e-12) << "patch " << p << " vertex " << v;
  }
}

// The paper's method (graph distances, no repair) runs on the compact graph;
// the same coordinates as the four runs on a Face_filtered_graph of the patch.
TEST(PatchGraph, PaperMethodGivesTheCoordinatesOfTheFilteredGraph)
{
  const Mesh& man = cgal_mesh("man.off");
  const Mapped_patches mp = automatic_patches(man);
  diffuv::Uv_atlas<Mesh> atlas(man);
  const auto results = diffuv::parameterize_patches<diffuv::Graph_distance_tag>(man, man.points(), mp.seg, atlas, diffuv::Patch_parameterization_options{diffuv::Repair_options{false}});
  const auto lengths = diffuv::edge_length_map(man, man.points());
  for(std::size_t p = 0; p < mp.seg.number_of_patches(); ++p) {
    ASSERT_TRUE(results[p].status.ok()) << "patch " << p;
    const CGAL::Face_filtered_graph<Mesh> patch(man, mp.seg.patch_faces[p]);
    auto pindex = get(boost::vertex_index, patch);
    std::vector<Point_2> uv(num_vertices(patch));
    ASSERT_TRUE(diffuv::diffusion_coordinates<diffuv::Graph_distance_tag>(patch, mp.sides[p], lengths,
                                              boost::make_iterator_property_map(uv.begin(), pindex))
                    .ok());
    const auto& chart = atlas.chart(results[p].chart);
    ASSERT_EQ(chart.vertices.size(), uv.size());
    for(std::size_t i = 0; i < chart.vertices.size(); ++i) {
      const Point_2 want = uv[get(pindex, chart.vertices[i])];
      EXPECT_NEAR(chart.uv[i].x(), want.x(), 1e-12) << "patch " << p << " vertex " << chart.vertices[i];
      EXPECT_NEAR(chart.uv[i].y(), want.y(), 1e-12) << "patch " << p << " vertex " << chart.vertices[i];
    }
  }
}

// A patch copied as a mesh of its own is walked as the Face_filtered_graph of
// the patch is: the same vertices and faces in the same order, and each vertex
// and face with the same halfedge, so the turns around a vertex start alike.
TEST(PatchMesh, WalksThePatchAsTheFilteredGraphDoes)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Mapped_patches mp = automatic_patches(cow);
  ASSERT_GT(mp.seg.number_of_patches(), 20u);
  using Copy = diffuv::Patch_mesh<Mesh, decltype(cow.points())>;
  Copy copy;  // one object for every patch, as parameterize_patches() uses it
  std::size_t border_vertices = 0;
  for(std::size_t p = 0; p < mp.seg.number_of_patches(); ++p) {
    ASSERT_TRUE(copy.build(cow, cow.points(), mp.seg.patch_faces[p])) << "patch " << p;
    const Copy::Mesh& local = copy.mesh();
    const CGAL::Face_filtered_graph<Mesh> patch(cow, mp.seg.patch_faces[p]);
    ASSERT_EQ(num_vertices(local), num_vertices(patch)) << "patch " << p;
    ASSERT_EQ(num_faces(local), num_faces(patch)) << "patch " << p;
    ASSERT_EQ(num_edges(local), num_edges(patch)) << "patch " << p;
    std::vector<vertex_descriptor> order(vertices(patch).begin(), vertices(patch).end());
    ASSERT_EQ(copy.mesh_vertices(), order) << "patch " << p;
    for(vertex_descriptor v : vertices(cow)) ASSERT_EQ(copy.has(cow, v), patch.is_in_cc(v)) << "patch " << p;
    auto to_mesh = [&](Copy::vertex_descriptor v) { return copy.mesh_vertices()[v.idx()]; };
    for(vertex_descriptor v : vertices(patch)) {
      const Copy::vertex_descriptor lv = copy.local(cow, v);
      ASSERT_EQ(to_mesh(lv), v);
      ASSERT_EQ(local.is_border(lv), static_cast<bool>(CGAL::is_border(v, patch))) << "patch " << p;
      border_vertices += local.is_border(lv);
      // The turn around v, from its halfedge, as pairs of mesh vertices.
      std::vector<std::pair<vertex_descriptor, vertex_descriptor>> want, got;
      for(auto h : CGAL::halfedges_around_target(halfedge(v, patch), patch)) want.emplace_back(source(h, patch), face(h, patch) != boost::graph_traits<CGAL::Face_filtered_graph<Mesh>>::null_face() ? target(next(h, patch), patch) : vertex_descriptor());
      for(auto h : CGAL::halfedges_around_target(local.halfedge(lv), local))
        got.emplace_back(to_mesh(local.source(h)), local.face(h) != Copy::Mesh::null_face() ? to_mesh(local.target(local.next(h))) : vertex_descriptor());
      ASSERT_EQ(got, want) << "patch " << p << " vertex " << v;
    }
    std::size_t i = 0;
    for(face_descriptor f : faces(patch)) {
      const auto lf = *std::next(local.faces().begin(), static_cast<std::ptrdiff_t>(i++));
      const auto h = halfedge(f, patch), lh = local.halfedge(lf);
      ASSERT_EQ(to_mesh(local.source(lh)), source(h, patch)) << "patch " << p << " face " << f;
      ASSERT_EQ(to_mesh(local.target(lh)), target(h, patch)) << "patch " << p << " face " << f;
      ASSERT_EQ(to_mesh(local.target(local.next(lh))), target(next(h, patch), patch)) << "patch " << p << " face " << f;
    }
  }
  EXPECT_GT(border_vertices, 0u);
}

// The default pipeline (fast marching, then the repair) maps each patch on
// its copy: the coordinates are those of the same steps on the patch's
// Face_filtered_graph, bit for bit, repaired vertices included.
TEST(PatchMesh, DefaultPipelineGivesTheMapOfTheFilteredGraph)
{
  const Mesh& man = cgal_mesh("man.off");
  const Mapped_patches mp = automatic_patches(man);
  diffuv::Uv_atlas<Mesh> atlas(man);
  const auto results = diffuv::parameterize_patches(man, man.points(), mp.seg, atlas);
  const auto lengths = diffuv::edge_length_map(man, man.points());
  std::size_t moved = 0;
  for(std::size_t p = 0; p < mp.seg.number_of_patches(); ++p) {
    ASSERT_TRUE(results[p].status.ok()) << "patch " << p;
    const CGAL::Face_filtered_graph<Mesh> patch(man, mp.seg.patch_faces[p]);
    auto pindex = get(boost::vertex_index, patch);
    std::vector<Point_2> uv(num_vertices(patch));
    auto uv_map = boost::make_iterator_property_map(uv.begin(), pindex);
    ASSERT_TRUE(diffuv::diffusion_coordinates(patch, results[p].sides, lengths, uv_map).ok());
    diffuv::Repair_report report;
    diffuv::repair_folds(patch, man.points(), results[p].sides, uv_map, diffuv::Repair_options(), &report);
    moved += report.moved_vertices;
    EXPECT_EQ(report.moved_vertices, results[p].repair.moved_vertices) << "patch " << p;
    const auto& chart = atlas.chart(results[p].chart);
    ASSERT_EQ(chart.vertices.size(), uv.size());
    for(std::size_t i = 0; i < chart.vertices.size(); ++i) {
      const Point_2 want = uv[get(pindex, chart.vertices[i])];
      ASSERT_EQ(chart.uv[i].x(), want.x()) << "patch " << p << " vertex " << chart.vertices[i];
      ASSERT_EQ(chart.uv[i].y(), want.y()) << "patch " << p << " vertex " << chart.vertices[i];
    }
  }
  EXPECT_GT(moved, 0u);  // the repair ran somewhere, so its walks were compared too
}

// measure_distortion() counts overlapping pairs only where the chart's border
// cannot show it one-to-one: on the charts of real atlases, with the repair
// (every chart one-to-one) and without it (folds), the count is the pairwise
// test's, count_overlapping_pairs().
TEST(ParameterizePatches, OverlapsMeasuredAsThePairwiseTestCountsThem)
{
  for(const char* name : {"cow.off", "bull.off"}) {
    const Mesh& m = cgal_mesh(name);
    const Mapped_patches mp = automatic_patches(m);
    for(bool repair : {true, false}) {
      diffuv::Uv_atlas<Mesh> atlas(m);
      diffuv::Patch_parameterization_options options;
      options.repair.enabled = repair;
      const auto results = diffuv::parameterize_patches(m, m.points(), mp.seg, atlas, options);
      std::size_t shown_by_border = 0, overlapping = 0;
      for(std::size_t p = 0; p < results.size(); ++p) {
        ASSERT_TRUE(results[p].status.ok()) << name << " patch " << p;
        const auto& chart = atlas.chart(results[p].chart);
        const auto uv = atlas.chart_texture_map(results[p].chart);
        const auto s = diffuv::measure_distortion(m, m.points(), chart.faces, uv);
        const std::size_t pairs = diffuv::count_overlapping_pairs(m, chart.faces, uv);
        EXPECT_EQ(s.overlapping_pairs, pairs) << name << " patch " << p << (repair ? "" : " (no repair)");
        overlapping += pairs > 0;
        shown_by_border += s.flipped == 0 && s.degenerate == 0 && diffuv::internal::border_maps_to_simple_polygon(m, chart.faces, uv);
      }
      EXPECT_GT(shown_by_border, results.size() / 2) << name;
      if(!repair) EXPECT_GT(overlapping, 0u) << name << ": without the repair some charts fold";
    }
  }
}

// Patches mapped on 1, 2 or all threads: the same atlas, bit for bit, and the
// same results, with both pipelines.
TEST(ParallelPatches, ResultsDoNotDependOnTheNumberOfThreads)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Mapped_patches mp = automatic_patches(cow);
  for(bool paper : {true, false}) {
    std::vector<std::unique_ptr<diffuv::Uv_atlas<Mesh>>> atlases;
    std::vector<std::vector<diffuv::Patch_result<Mesh>>> results;
    for(std::size_t threads : {1u, 2u, 0u}) {
      atlases.push_back(std::make_unique<diffuv::Uv_atlas<Mesh>>(cow));
      results.push_back(paper ? diffuv::parameterize_patches<diffuv::Graph_distance_tag>(cow, cow.points(), mp.seg, *atlases.back(), diffuv::Patch_parameterization_options{diffuv::Repair_options{false}, nullptr, true, threads})
                              : diffuv::parameterize_patches<diffuv::Default_distance_tag>(cow, cow.points(), mp.seg, *atlases.back(), diffuv::Patch_parameterization_options{diffuv::Repair_options(), nullptr, true, threads}));
    }
    for(std::size_t k = 1; k < atlases.size(); ++k) {
      ASSERT_EQ(atlases[k]->number_of_charts(), atlases[0]->number_of_charts());
      for(std::size_t p = 0; p < results[0].size(); ++p) {
        EXPECT_EQ(results[k][p].status.code, results[0][p].status.code);
        EXPECT_EQ(results[k][p].chart, results[0][p].chart);
        EXPECT_EQ(results[k][p].repair.moved_vertices, results[0][p].repair.moved_vertices);
        EXPECT_EQ(results[k][p].sides.corners, results[0][p].sides.corners);
      }
      for(std::size_t c = 0; c < atlases[0]->number_of_charts(); ++c) {
        EXPECT_EQ(atlases[k]->chart(c).vertices, atlases[0]->chart(c).vertices) << (paper ? "paper" : "default");
        EXPECT_EQ(atlases[k]->chart(c).uv, atlases[0]->chart(c).uv) << (paper ? "paper" : "default");
      }
    }
  }
}

// A disc mesh is one patch: its four passes run on two threads instead (with
// fast marching, the second engine shares the first's tables); the same
// coordinates bit for bit, with the paper's graph distances and the default.
TEST(ParallelPatches, FourPassesOfOnePatchInParallelGiveTheSameCoordinates)
{
  const Mesh& disc = cgal_mesh("nefertiti.off");
  Seg seg;
  ASSERT_TRUE(diffuv::disc_patches(disc, disc.points(), {}, seg).ok());
  ASSERT_EQ(seg.number_of_patches(), 1u);
  auto map_on = [&](auto distance, std::size_t threads, bool repair = false) {
    auto atlas = std::make_unique<diffuv::Uv_atlas<Mesh>>(disc);
    const auto r = diffuv::parameterize_patches<decltype(distance)>(disc, disc.points(), seg, *atlas, diffuv::Patch_parameterization_options{diffuv::Repair_options{repair}, nullptr, true, threads});
    EXPECT_TRUE(r.front().status.ok()) << threads;
    return atlas;
  };
  const auto graph_1 = map_on(diffuv::Graph_distance_tag(), 1), graph_2 = map_on(diffuv::Graph_distance_tag(), 2);
  EXPECT_EQ(graph_2->chart(0).vertices, graph_1->chart(0).vertices);
  EXPECT_EQ(graph_2->chart(0).uv, graph_1->chart(0).uv);
  const auto fmm_1 = map_on(diffuv::Fmm_distance_tag(), 1), fmm_2 = map_on(diffuv::Fmm_distance_tag(), 2);
  EXPECT_EQ(fmm_2->chart(0).vertices, fmm_1->chart(0).vertices);
  EXPECT_EQ(fmm_2->chart(0).uv, fmm_1->chart(0).uv);
  EXPECT_NE(fmm_1->chart(0).uv, graph_1->chart(0).uv);  // two different distances were compared
  // Graph distances with the repair: the patch copied as a mesh, as with fast marching.
  const auto repaired_1 = map_on(diffuv::Graph_distance_tag(), 1, true), repaired_2 = map_on(diffuv::Graph_distance_tag(), 2, true);
  EXPECT_EQ(repaired_2->chart(0).uv, repaired_1->chart(0).uv);
}


// One patch holding every face of `m`, as `diffuv param --corners` makes it.
Seg whole_mesh_patch(const Mesh& m)
{
  Seg seg;
  seg.face_patch.assign(num_faces(m), 0);
  seg.patch_label = {0};
  seg.patch_part = {0};
  seg.patch_faces = {std::vector<face_descriptor>(faces(m).begin(), faces(m).end())};
  return seg;
}

TEST(ParameterizePatches, InputsThatDoNotFitTheMeshAreRefused)
{
  const Mesh small = make_grid(4, 4), large = make_grid(6, 6);
  auto refusal = [](auto call) -> std::string {
    try {
      call();
    } catch(const std::invalid_argument& e) {
      return e.what();
    }
    return "no exception";
  };
  {
    diffuv::Uv_atlas<Mesh> atlas(small);
    const auto results = diffuv::parameterize_patches(small, small.points(), whole_mesh_patch(small), atlas);
    ASSERT_EQ(results.size(), 1u);
    EXPECT_TRUE(results[0].status.ok()) << results[0].status.what();
  }
  diffuv::Uv_atlas<Mesh> other(large);
  EXPECT_EQ(refusal([&] { diffuv::parameterize_patches(small, small.points(), whole_mesh_patch(small), other); }),
            "parameterize_patches: the atlas maps another mesh");
  EXPECT_EQ(other.number_of_charts(), 0u);

  diffuv::Uv_atlas<Mesh> atlas(small);
  auto refusal_of = [&](const Seg& seg, const diffuv::Patch_parameterization_options& options = {}) {
    return refusal([&] { diffuv::parameterize_patches(small, small.points(), seg, atlas, options); });
  };
  EXPECT_EQ(refusal_of(whole_mesh_patch(large)), "parameterize_patches: the segmentation has 72 face entries, the mesh 32 faces");
  Seg unlabelled = whole_mesh_patch(small);
  unlabelled.patch_label.clear();
  EXPECT_EQ(refusal_of(unlabelled), "parameterize_patches: the segmentation has 1 patch but 0 labels and 1 part number");
  Seg corners = whole_mesh_patch(small);
  corners.patch_corners.assign(2, Seg::no_corners());
  EXPECT_EQ(refusal_of(corners), "parameterize_patches: the segmentation has 1 patch but 2 corner entries");
  Seg stray = whole_mesh_patch(small);
  stray.patch_faces[0].push_back(face_descriptor(Mesh::size_type(1000)));
  EXPECT_EQ(refusal_of(stray), "parameterize_patches: patch 0 lists a face that is not a face of the mesh");
  const std::vector<diffuv::Corner_names> names(2);
  diffuv::Patch_parameterization_options following;
  following.corner_names = &names;
  EXPECT_EQ(refusal_of(whole_mesh_patch(small), following),
            "parameterize_patches: options.corner_names has 2 entries, the segmentation 1 patch");
  EXPECT_EQ(atlas.number_of_charts(), 0u);
}


} // namespace
