// Tests of the graph stage: multi-source Dijkstra and edge lengths.
// Reference: boost::dijkstra_shortest_paths with several sources (its
// positional overload), which must give bit-identical distances.
#include "test_data.h"

#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/multi_source_dijkstra.h>

#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/graph_traits_Surface_mesh.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using namespace diffuv_test;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
constexpr double inf = std::numeric_limits<double>::infinity();

// Boost's own multi-source Dijkstra: the independent reference.
template <class Graph, class WeightMap, class Sources>
std::vector<double> boost_reference(const Graph& g, WeightMap w, const Sources& sources)
{
  const auto n = num_vertices(g);
  auto index = get(boost::vertex_index, g);
  std::vector<double> dist(n);
  std::vector<typename boost::graph_traits<Graph>::vertex_descriptor> pred(n);
  auto dmap = boost::make_iterator_property_map(dist.begin(), index);
  auto pmap = boost::make_iterator_property_map(pred.begin(), index);
  std::vector<boost::default_color_type> color(n);
  boost::dijkstra_shortest_paths(g, sources.begin(), sources.end(), pmap, dmap, w, index,
                                 std::less<double>(), boost::closed_plus<double>(inf), inf, 0.,
                                 boost::default_dijkstra_visitor(),
                                 boost::make_iterator_property_map(color.begin(), index));
  return dist;
}

// Every k-th vertex of a mesh: a deterministic, scattered source set.
std::vector<vertex_descriptor> every_kth_vertex(const Mesh& m, std::size_t k)
{
  std::vector<vertex_descriptor> s;
  std::size_t i = 0;
  for(auto v : vertices(m))
    if(i++ % k == 0) s.push_back(v);
  return s;
}

template <class HeapTag>
void expect_same_as_boost_on(const std::string& name)
{
  const Mesh& mesh = cgal_mesh(name);
  ASSERT_GT(num_vertices(mesh), 0u);
  auto lengths = diffuv::edge_length_map(mesh);
  for(std::size_t k : {1u, 97u, 1000u}) {
    const auto sources = every_kth_vertex(mesh, k);
    const auto expected = boost_reference(mesh, lengths, sources);
    std::vector<double> dist(num_vertices(mesh), -1.);
    auto dmap = boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, mesh));
    ASSERT_TRUE(diffuv::multi_source_dijkstra<HeapTag>(mesh, sources, lengths, dmap).ok());
    std::size_t mismatches = 0;
    for(std::size_t i = 0; i < dist.size(); ++i)
      if(dist[i] != expected[i]) ++mismatches; // exact: same path sums
    EXPECT_EQ(mismatches, 0u) << name << " every " << k << "-th vertex as source";
  }
}

template <class HeapTag>
class Dijkstra_heaps : public ::testing::Test {};
using Heap_tags = ::testing::Types<diffuv::Fibonacci_heap_tag, diffuv::Pairing_heap_tag,
                                   diffuv::Binomial_heap_tag, diffuv::Quaternary_heap_tag>;
TYPED_TEST_SUITE(Dijkstra_heaps, Heap_tags);

TYPED_TEST(Dijkstra_heaps, SameDistancesAsBoostOnRealMeshes)
{
  for(const char* name : {"cow.off", "man.off", "mushroom.off"})
    expect_same_as_boost_on<TypeParam>(name);
}

TYPED_TEST(Dijkstra_heaps, SameDistancesAsBoostOnRandomGraphs)
{
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                      boost::property<boost::edge_weight_t, double>>;
  std::mt19937 rng(42);
  for(int trial = 0; trial < 20; ++trial) {
    const std::size_t n = 50 + 40 * trial;
    Graph g(n);
    std::uniform_int_distribution<std::size_t> pick(0, n - 1);
    std::uniform_real_distribution<double> weight(0., 10.);
    for(std::size_t e = 0; e < 2 * n; ++e) { // sparse: some vertices stay unreachable
      const double w = (e % 17 == 0) ? 0. : weight(rng); // zero weights too
      boost::add_edge(pick(rng), pick(rng), w, g);
    }
    std::vector<std::size_t> sources = {pick(rng), pick(rng), pick(rng)};
    auto w = get(boost::edge_weight, g);
    const auto expected = boost_reference(g, w, sources);
    std::vector<double> dist(n);
    auto dmap = boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, g));
    ASSERT_TRUE(diffuv::multi_source_dijkstra<TypeParam>(g, sources, w, dmap).ok());
    for(std::size_t i = 0; i < n; ++i)
      ASSERT_EQ(dist[i], expected[i]) << "trial " << trial << " vertex " << i;
  }
}

TEST(Dijkstra, UnreachableVerticesStayAtInfinity)
{
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                      boost::property<boost::edge_weight_t, double>>;
  Graph g(5); // 0-1-2 connected, 3-4 apart
  boost::add_edge(0, 1, 1.5, g);
  boost::add_edge(1, 2, 2.0, g);
  boost::add_edge(3, 4, 1.0, g);
  std::vector<double> dist(5);
  auto dmap = boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, g));
  std::vector<std::size_t> sources = {0};
  ASSERT_TRUE(diffuv::multi_source_dijkstra(g, sources, get(boost::edge_weight, g), dmap).ok());
  EXPECT_EQ(dist[0], 0.);
  EXPECT_EQ(dist[1], 1.5);
  EXPECT_EQ(dist[2], 3.5);
  EXPECT_EQ(dist[3], inf);
  EXPECT_EQ(dist[4], inf);
}

TEST(Dijkstra, EmptySourceRangeIsAnError)
{
  const Mesh& mesh = cgal_mesh("cow.off");
  std::vector<double> dist(num_vertices(mesh), 7.);
  auto dmap = boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, mesh));
  std::vector<vertex_descriptor> none;
  const diffuv::Status s = diffuv::multi_source_dijkstra(mesh, none, diffuv::edge_length_map(mesh), dmap);
  EXPECT_EQ(s.code, diffuv::Status_code::empty_source_range);
  EXPECT_FALSE(s.ok());
}

TEST(Dijkstra, NegativeWeightIsAnError)
{
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                      boost::property<boost::edge_weight_t, double>>;
  Graph g(3);
  boost::add_edge(0, 1, 1.0, g);
  boost::add_edge(1, 2, -1.0, g);
  std::vector<double> dist(3);
  auto dmap = boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, g));
  std::vector<std::size_t> sources = {0};
  EXPECT_EQ(diffuv::multi_source_dijkstra(g, sources, get(boost::edge_weight, g), dmap).code,
            diffuv::Status_code::negative_weight);
}

TEST(Dijkstra, SourcesAreAtZeroAndDuplicatesAreHarmless)
{
  const Mesh& mesh = cgal_mesh("mushroom.off");
  auto lengths = diffuv::edge_length_map(mesh);
  auto sources = every_kth_vertex(mesh, 50);
  auto doubled = sources;
  doubled.insert(doubled.end(), sources.begin(), sources.end());
  std::vector<double> a(num_vertices(mesh)), b(num_vertices(mesh));
  auto index = get(boost::vertex_index, mesh);
  ASSERT_TRUE(diffuv::multi_source_dijkstra(mesh, sources, lengths, boost::make_iterator_property_map(a.begin(), index)).ok());
  ASSERT_TRUE(diffuv::multi_source_dijkstra(mesh, doubled, lengths, boost::make_iterator_property_map(b.begin(), index)).ok());
  EXPECT_EQ(a, b);
  for(auto s : sources) EXPECT_EQ(a[s.idx()], 0.);
}

TEST(Dijkstra, ReusableObjectGivesSameResultsAcrossRuns)
{
  const Mesh& mesh = cgal_mesh("man.off");
  auto lengths = diffuv::edge_length_map(mesh);
  auto index = get(boost::vertex_index, mesh);
  diffuv::Multi_source_dijkstra<Mesh> dijkstra(mesh);
  for(std::size_t k : {7u, 1000u, 31u}) {
    const auto sources = every_kth_vertex(mesh, k);
    std::vector<double> dist(num_vertices(mesh));
    ASSERT_TRUE(dijkstra.run(sources, lengths, boost::make_iterator_property_map(dist.begin(), index)).ok());
    EXPECT_EQ(dist, boost_reference(mesh, lengths, sources)) << "every " << k;
  }
}

// Farthest-point sampling adds sources one by one: add_source() after a run
// gives the distances of one run on all the sources (Boost's, the reference),
// and each vertex's origin is a source at exactly that distance.
TEST(Dijkstra, AddingSourcesOneByOneGivesTheRunOnAllOfThem)
{
  const Mesh& mesh = cgal_mesh("man.off");
  auto lengths = diffuv::edge_length_map(mesh);
  auto index = get(boost::vertex_index, mesh);
  const auto all = every_kth_vertex(mesh, 997);
  ASSERT_GT(all.size(), 10u);
  diffuv::Multi_source_dijkstra<Mesh> dijkstra(mesh);
  std::vector<double> dist(num_vertices(mesh));
  std::vector<std::size_t> origin(num_vertices(mesh));
  auto dmap = boost::make_iterator_property_map(dist.begin(), index);
  auto omap = boost::make_iterator_property_map(origin.begin(), index);
  ASSERT_TRUE(dijkstra.run(std::vector<vertex_descriptor>{all.front()}, lengths, dmap, omap).ok());
  for(std::size_t k = 1; k < all.size(); ++k)
    ASSERT_TRUE(dijkstra.add_source(all[k], k, lengths, dmap, omap).ok());
  ASSERT_TRUE(dijkstra.add_source(all[3], 99, lengths, dmap, omap).ok()); // a source again: nothing changes
  const std::vector<double> expected = boost_reference(mesh, lengths, all);
  for(auto v : vertices(mesh)) EXPECT_NEAR(dist[v.idx()], expected[v.idx()], 1e-12) << v;
  EXPECT_EQ(origin[all[3].idx()], 3u);
  // The origin is a nearest source: its own distance to v is the distance of v.
  for(std::size_t k : {0u, 5u}) {
    std::vector<double> from_k(num_vertices(mesh));
    ASSERT_TRUE(diffuv::multi_source_dijkstra(mesh, std::vector<vertex_descriptor>{all[k]}, lengths,
                                              boost::make_iterator_property_map(from_k.begin(), index))
                    .ok());
    std::size_t owned = 0;
    for(auto v : vertices(mesh))
      if(origin[v.idx()] == k) {
        ++owned;
        EXPECT_NEAR(from_k[v.idx()], dist[v.idx()], 1e-12) << v;
      }
    EXPECT_GT(owned, 0u);
  }
}

// The layout splits a cap by moving its seed and adding two: move_source()
// after a run gives the distances of one run on the moved sources (Boost's,
// the reference), the vertices of the old source's cell take their new
// nearest source, and a vertex whose origin is the moved source is exactly as
// far from it as its distance says.
TEST(Dijkstra, MovingASourceGivesTheRunOnTheMovedSources)
{
  const Mesh& mesh = cgal_mesh("man.off");
  auto lengths = diffuv::edge_length_map(mesh);
  auto index = get(boost::vertex_index, mesh);
  std::vector<vertex_descriptor> sources = every_kth_vertex(mesh, 997);
  ASSERT_GT(sources.size(), 10u);
  diffuv::Multi_source_dijkstra<Mesh> dijkstra(mesh);
  std::vector<double> dist(num_vertices(mesh));
  std::vector<std::size_t> origin(num_vertices(mesh));
  auto dmap = boost::make_iterator_property_map(dist.begin(), index);
  auto omap = boost::make_iterator_property_map(origin.begin(), index);
  ASSERT_TRUE(dijkstra.run(sources, lengths, dmap, omap).ok());
  // Move source 4 a few times: next door, far away (into another cell), onto
  // a vertex that is already a source's neighbour.
  const std::vector<vertex_descriptor> targets = {
      mesh.target(mesh.halfedge(sources[4])), vertex_descriptor(static_cast<std::uint32_t>(num_vertices(mesh) / 2 + 3)),
      mesh.target(mesh.halfedge(sources[7]))};
  for(vertex_descriptor to : targets) {
    sources[4] = to;
    ASSERT_TRUE(dijkstra.move_source(4, to, lengths, dmap, omap).ok());
    const std::vector<double> expected = boost_reference(mesh, lengths, sources);
    for(auto v : vertices(mesh)) ASSERT_NEAR(dist[v.idx()], expected[v.idx()], 1e-12) << v << " after moving to " << to;
    EXPECT_EQ(origin[to.idx()], 4u);
    std::vector<double> from_moved(num_vertices(mesh));
    ASSERT_TRUE(diffuv::multi_source_dijkstra(mesh, std::vector<vertex_descriptor>{to}, lengths,
                                              boost::make_iterator_property_map(from_moved.begin(), index))
                    .ok());
    std::size_t owned = 0;
    for(auto v : vertices(mesh))
      if(origin[v.idx()] == 4) {
        ++owned;
        EXPECT_NEAR(from_moved[v.idx()], dist[v.idx()], 1e-12) << v;
      }
    EXPECT_GE(owned, 1u);
  }
}

TEST(Dijkstra, RestrictedToAPatchOfFaceFilteredGraph)
{
  // A patch: the faces whose centroid has x below the median. Distances on the
  // filtered graph must equal Boost's on the same filtered graph, and never be
  // shorter than on the whole mesh (paths are confined to the patch).
  const Mesh& mesh = cgal_mesh("cow.off");
  std::vector<double> xs;
  for(auto v : vertices(mesh)) xs.push_back(mesh.point(v).x());
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  const double median = xs[xs.size() / 2];
  std::vector<boost::graph_traits<Mesh>::face_descriptor> patch_faces;
  for(auto f : faces(mesh))
    if(CGAL::centroid(mesh.point(source(halfedge(f, mesh), mesh)), mesh.point(target(halfedge(f, mesh), mesh)),
                      mesh.point(target(next(halfedge(f, mesh), mesh), mesh))).x() < median)
      patch_faces.push_back(f);
  using Patch = CGAL::Face_filtered_graph<Mesh>;
  Patch patch(mesh, patch_faces);
  ASSERT_GT(num_vertices(patch), 10u);
  ASSERT_LT(num_vertices(patch), num_vertices(mesh));

  auto lengths = diffuv::edge_length_map(mesh); // indexed by the mesh's edges, valid on the patch
  std::vector<boost::graph_traits<Patch>::vertex_descriptor> sources;
  for(auto v : vertices(patch)) { sources.push_back(v); break; }

  std::vector<double> dist(num_vertices(patch));
  auto pindex = get(boost::vertex_index, patch);
  ASSERT_TRUE(diffuv::multi_source_dijkstra(patch, sources, lengths, boost::make_iterator_property_map(dist.begin(), pindex)).ok());
  EXPECT_EQ(dist, boost_reference(patch, lengths, sources));

  std::vector<double> whole(num_vertices(mesh));
  ASSERT_TRUE(diffuv::multi_source_dijkstra(mesh, sources, lengths,
      boost::make_iterator_property_map(whole.begin(), get(boost::vertex_index, mesh))).ok());
  std::size_t longer = 0;
  for(auto v : vertices(patch)) {
    EXPECT_GE(dist[get(pindex, v)], whole[v.idx()]);
    if(dist[get(pindex, v)] > whole[v.idx()]) ++longer;
  }
  EXPECT_GT(longer, 0u) << "the patch should cut some shortest paths";
}

TEST(EdgeLengths, MatchEuclideanLengths)
{
  const Mesh& mesh = cgal_mesh("cow.off");
  auto lengths = diffuv::edge_length_map(mesh);
  for(auto e : edges(mesh)) {
    const auto& a = mesh.point(source(e, mesh));
    const auto& b = mesh.point(target(e, mesh));
    EXPECT_DOUBLE_EQ(get(lengths, e), std::sqrt(CGAL::squared_distance(a, b)));
  }
}

} // namespace

namespace {

using vertex_descriptor_of_mesh = diffuv_test::Mesh::Vertex_index;

TEST(Dijkstra, NearestSourceIsTheSourceThatGivesTheDistance)
{
  // The Voronoi origin of each vertex: running Dijkstra from that source alone
  // gives the multi-source distance.
  const diffuv_test::Mesh& m = diffuv_test::cgal_mesh("mushroom.off");
  auto lengths = diffuv::edge_length_map(m);
  std::vector<vertex_descriptor_of_mesh> sources = {vertex_descriptor_of_mesh(3), vertex_descriptor_of_mesh(400), vertex_descriptor_of_mesh(1500)};
  std::vector<double> dist(num_vertices(m));
  std::vector<std::size_t> origin(num_vertices(m), 99);
  auto index = get(boost::vertex_index, m);
  diffuv::Multi_source_dijkstra<diffuv_test::Mesh> dijkstra(m);
  ASSERT_TRUE(dijkstra.run(sources, lengths, boost::make_iterator_property_map(dist.begin(), index),
                           boost::make_iterator_property_map(origin.begin(), index)).ok());
  std::vector<std::vector<double>> single(3, std::vector<double>(num_vertices(m)));
  for(std::size_t s = 0; s < 3; ++s)
    ASSERT_TRUE(dijkstra.run(std::vector<vertex_descriptor_of_mesh>{sources[s]}, lengths,
                             boost::make_iterator_property_map(single[s].begin(), index)).ok());
  for(auto v : vertices(m)) {
    ASSERT_LT(origin[v.idx()], 3u);
    EXPECT_EQ(single[origin[v.idx()]][v.idx()], dist[v.idx()]) << v;
  }
}


} // namespace
