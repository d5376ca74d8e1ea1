// diffuv performance bench, --profile: the pipeline's stages, each timed.
#include "performance/performance_bench.h"

#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/fast_marching.h>
#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/graph/patch_graph.h>
#include <diffuv/parameterization/diffusion_coordinates.h>
#include <diffuv/parameterization/repair_folds.h>
#include <diffuv/patches/region_sides.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <type_traits>

namespace diffuv_bench {

namespace {

volatile std::size_t stage_sink = 0; // results of loops that are only timed

// The same pipeline as parameterize_patches() (same calls, same order), with a
// timer per stage, and extra measurements that are not part of the pipeline
// (not in `total`): the distance engine alone (set-up, four runs) and one
// plain pass over the patch's vertices and faces through the
// Face_filtered_graph (the pipeline makes several such passes per patch).
struct Stages {
  double setup = 0, disc_check = 0, sides = 0, ffg = 0, engine = 0, distances = 0, repair = 0, chart = 0, total = 0;
  double engine_setup = 0, engine_runs = 0, scan_vertices = 0, scan_faces = 0;
};

const char* const stage_names[] = {"setup",  "disc_check", "sides",        "ffg",         "engine",
                                   "distances", "repair",  "chart",        "total",       "engine_setup",
                                   "engine_runs", "scan_vertices", "scan_faces"};

std::array<double, 13> stage_values(const Stages& s)
{
  return {s.setup, s.disc_check, s.sides, s.ffg, s.engine, s.distances, s.repair, s.chart, s.total,
          s.engine_setup, s.engine_runs, s.scan_vertices, s.scan_faces};
}

template <class DistanceTag>
Stages staged_pipeline(const Case& c, bool repair)
{
  using Heap = diffuv::Fibonacci_heap_tag;
  const Mesh& m = c.mesh;
  Stages s;
  const auto start = Clock::now();
  auto t = Clock::now();
  auto lap = [&](double& acc) {
    const auto now = Clock::now();
    acc += std::chrono::duration<double, std::milli>(now - t).count();
    t = now;
  };
  double outside = 0; // extra measurements, taken out of the total
  Atlas atlas(m);
  const auto lengths = diffuv::edge_length_map(m, m.points());
  diffuv::Patch_graph<Mesh> pgraph;
  lap(s.setup);
  for(std::size_t p = 0; p < c.seg.number_of_patches(); ++p) {
    diffuv::Patch_result<Mesh> r;
    r.status = diffuv::check_patch_disc(m, c.seg, p);
    lap(s.disc_check);
    if(r.status) r.status = diffuv::region_sides(m, m.points(), c.seg, p, r.sides, {}, &r.side_report);
    lap(s.sides);
    if(!r.status) continue;
    if(std::is_same_v<DistanceTag, diffuv::Graph_distance_tag> && !repair) {
      // The library's path for the paper's method: a compact graph per patch.
      auto findex = get(boost::face_index, m);
      pgraph.build(m, c.seg.patch_faces[p],
                   [&](face_descriptor f) { return f != Mesh::null_face() && c.seg.face_patch[get(findex, f)] == p; },
                   lengths);
      const auto ls = pgraph.local_sides(m, r.sides);
      lap(s.ffg);
      std::vector<Point_2> uv(pgraph.number_of_vertices());
      diffuv::Diffusion_coordinates<diffuv::Patch_graph<Mesh>::Graph, diffuv::Graph_distance_tag, Heap> coordinates(
          pgraph.graph());
      lap(s.engine);
      r.status = coordinates.compute(ls, pgraph.length_map(),
                                     boost::make_iterator_property_map(uv.begin(), get(boost::vertex_index, pgraph.graph())));
      lap(s.distances);
      if(!r.status) continue;
      atlas.add_chart(c.seg.patch_faces[p], pgraph.mesh_vertices(), std::move(uv));
      lap(s.chart);
      continue;
    }
    const Patch patch(m, c.seg.patch_faces[p]);
    auto pindex = get(boost::vertex_index, patch);
    lap(s.ffg);
    std::vector<Point_2> uv(num_vertices(patch));
    diffuv::Diffusion_coordinates<Patch, DistanceTag, Heap> coordinates(patch);
    lap(s.engine);
    r.status = coordinates.compute(r.sides, lengths, boost::make_iterator_property_map(uv.begin(), pindex));
    lap(s.distances);
    if(!r.status) continue;
    diffuv::repair_folds(patch, m.points(), r.sides, boost::make_iterator_property_map(uv.begin(), pindex), diffuv::Repair_options{repair},
                         &r.repair);
    lap(s.repair);
    std::vector<vertex_descriptor> chart_vertices(num_vertices(patch));
    for(vertex_descriptor v : vertices(patch)) chart_vertices[get(pindex, v)] = v;
    atlas.add_chart(c.seg.patch_faces[p], std::move(chart_vertices), std::move(uv));
    lap(s.chart);

    // Not part of the pipeline: the engine alone, and plain passes.
    const auto x0 = Clock::now();
    {
      std::vector<double> d(num_vertices(patch));
      auto dmap = boost::make_iterator_property_map(d.begin(), pindex);
      const std::array<const std::vector<vertex_descriptor>*, 4> sources = {&r.sides.u1, &r.sides.u2, &r.sides.v1,
                                                                            &r.sides.v2};
      auto e0 = Clock::now();
      if constexpr(std::is_same_v<DistanceTag, diffuv::Fmm_distance_tag>) {
        diffuv::Fast_marching<Patch, Heap> engine(patch);
        s.engine_setup += ms_since(e0);
        e0 = Clock::now();
        for(const auto* src : sources) engine.run(*src, dmap);
      } else {
        diffuv::Multi_source_dijkstra<Patch, Heap> engine(patch);
        s.engine_setup += ms_since(e0);
        e0 = Clock::now();
        for(const auto* src : sources) engine.run(*src, lengths, dmap);
      }
      s.engine_runs += ms_since(e0);
      e0 = Clock::now();
      std::size_t count = 0;
      for(vertex_descriptor v : vertices(patch)) count += v.idx() & 1u;
      s.scan_vertices += ms_since(e0);
      e0 = Clock::now();
      for(face_descriptor f : faces(patch)) count += f.idx() & 1u;
      s.scan_faces += ms_since(e0);
      stage_sink = count; // keep the loops
    }
    outside += ms_since(x0);
    t = Clock::now();
  }
  s.total = ms_since(start) - outside;
  return s;
}

} // namespace

void measure_stages(const Case& c, int runs, const std::string& tag, Row& row)
{
  std::vector<std::array<double, 13>> paper, dflt;
  for(int r = 0; r < runs; ++r) {
    paper.push_back(stage_values(staged_pipeline<diffuv::Graph_distance_tag>(c, false)));
    dflt.push_back(stage_values(staged_pipeline<diffuv::Default_distance_tag>(c, true)));
  }
  for(std::size_t k = 0; k < 13; ++k) {
    std::vector<double> a, b;
    for(const auto& s : paper) a.push_back(s[k]);
    for(const auto& s : dflt) b.push_back(s[k]);
    row.set(std::string("prof_paper_") + stage_names[k], median(a));
    row.set(std::string("prof_default_") + stage_names[k], median(b));
  }
  progress(tag + "profile: paper total " + format("%.2f", row.number("prof_paper_total")) + " ms, default total " +
           format("%.2f", row.number("prof_default_total")) + " ms");
}

} // namespace diffuv_bench
