// diffuv performance bench, (c): the atlas and its kd-trees built again from
// the default pipeline's charts, nearest-vertex queries and point locations
// per second (uniform random (u,v) in a random chart), against a reference
// k-NN search on a replica of the atlas's kd-tree.
#include "performance/performance_bench.h"

#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>

#include <boost/property_map/property_map.hpp>

#include <cstdint>
#include <numeric>
#include <random>

namespace diffuv_bench {

namespace {

volatile std::size_t query_sink = 0; // results of loops that are only timed

// The reference kd-tree over chart-local vertex ids, reading their (u,v) from the chart.
using Uv_ref_map = boost::iterator_property_map<const Point_2*, boost::typed_identity_property_map<std::uint32_t>,
                                                Point_2, const Point_2&>;
using Ref_base = CGAL::Search_traits_2<Kernel>;
using Ref_traits = CGAL::Search_traits_adapter<std::uint32_t, Uv_ref_map, Ref_base>;
using Ref_distance = CGAL::Distance_adapter<std::uint32_t, Uv_ref_map, CGAL::Euclidean_distance<Ref_base>>;
using Ref_knn = CGAL::Orthogonal_k_neighbor_search<Ref_traits, Ref_distance>;
using Ref_tree = Ref_knn::Tree;

std::unique_ptr<Ref_tree> build_ref_tree(const std::vector<Point_2>& uv)
{
  std::vector<std::uint32_t> ids(uv.size());
  std::iota(ids.begin(), ids.end(), 0u);
  auto tree = std::make_unique<Ref_tree>(ids.begin(), ids.end(), Ref_tree::Splitter(), Ref_traits(Uv_ref_map(uv.data())));
  tree->build();
  return tree;
}

} // namespace

void measure_atlas_queries(const Case& c, const Atlas& atlas, int runs, std::size_t queries_per_run,
                           const std::string& tag, Row& row)
{
  const Mesh& m = c.mesh;
  const std::size_t C = atlas.number_of_charts();
  std::vector<double> build, kd;
  for(int r = 0; r < runs; ++r) {
    std::vector<std::vector<face_descriptor>> fs(C);
    std::vector<std::vector<vertex_descriptor>> vs(C);
    std::vector<std::vector<Point_2>> uvs(C);
    for(std::size_t k = 0; k < C; ++k) {
      fs[k] = atlas.chart(k).faces;
      vs[k] = atlas.chart(k).vertices;
      uvs[k] = atlas.chart(k).uv;
    }
    auto t0 = Clock::now();
    {
      Atlas fresh(m);
      for(std::size_t k = 0; k < C; ++k) fresh.add_chart(std::move(fs[k]), std::move(vs[k]), std::move(uvs[k]));
      build.push_back(ms_since(t0));
    }
    t0 = Clock::now();
    std::vector<std::unique_ptr<Ref_tree>> trees;
    for(std::size_t k = 0; k < C; ++k) trees.push_back(build_ref_tree(atlas.chart(k).uv));
    kd.push_back(ms_since(t0));
  }
  row.set("charts", C);
  row.set("atlas_build_ms", median(build));
  row.set("kd_build_ms", median(kd));

  std::mt19937_64 random(12345);
  std::uniform_int_distribution<std::size_t> any_chart(0, C - 1);
  std::uniform_real_distribution<double> unit(0., 1.);
  std::vector<std::pair<std::size_t, Point_2>> queries(queries_per_run);
  for(auto& q : queries) q = {any_chart(random), Point_2(unit(random), unit(random))};
  std::vector<std::unique_ptr<Ref_tree>> trees;
  for(std::size_t k = 0; k < C; ++k) trees.push_back(build_ref_tree(atlas.chart(k).uv));

  std::vector<double> nn, loc, ref;
  std::size_t inside = 0, agree = 0, checked = 0;
  const int qruns = std::max(3, std::min(runs, 5));
  for(int r = 0; r < qruns; ++r) {
    std::size_t sum = 0;
    auto t0 = Clock::now();
    for(const auto& q : queries) sum += atlas.nearest_vertex(q.first, q.second);
    nn.push_back(double(queries.size()) / (ms_since(t0) / 1000.));
    t0 = Clock::now();
    std::size_t in = 0;
    for(const auto& q : queries) in += atlas.locate(q.first, q.second).inside;
    loc.push_back(double(queries.size()) / (ms_since(t0) / 1000.));
    inside = in;
    t0 = Clock::now();
    std::size_t sum_ref = 0;
    for(const auto& q : queries) {
      const std::vector<Point_2>& uv = atlas.chart(q.first).uv;
      Ref_knn search(*trees[q.first], q.second, 1, 0., true, Ref_distance(Uv_ref_map(uv.data())));
      sum_ref += search.begin()->first;
    }
    ref.push_back(double(queries.size()) / (ms_since(t0) / 1000.));
    query_sink = sum + sum_ref;
  }
  // The reference returns a nearest vertex too (ties aside): compare distances.
  for(std::size_t i = 0; i < std::min<std::size_t>(queries.size(), 2000); ++i) {
    const auto& q = queries[i];
    const std::vector<Point_2>& uv = atlas.chart(q.first).uv;
    Ref_knn search(*trees[q.first], q.second, 1, 0., true, Ref_distance(Uv_ref_map(uv.data())));
    const double a = CGAL::squared_distance(uv[atlas.nearest_vertex(q.first, q.second)], q.second);
    const double b = CGAL::squared_distance(uv[search.begin()->first], q.second);
    agree += a == b;
    ++checked;
  }
  row.set("nn_per_s", median(nn));
  row.set("locate_per_s", median(loc));
  row.set("locate_inside_pct", 100. * double(inside) / double(queries.size()));
  row.set("knn_ref_per_s", median(ref));
  row.set("knn_ref_agree_pct", 100. * double(agree) / double(checked));
  progress(tag + "atlas " + format("%.2f", median(build)) + " ms (kd-trees alone " + format("%.2f", median(kd)) +
           " ms), nearest vertex " + format("%.0f", median(nn)) + "/s, locate " + format("%.0f", median(loc)) + "/s");
}

} // namespace diffuv_bench
