// diffuv correspondence bench: one pair. Both atlases (B's following A's
// corners unless --no-follow), the mapping of every vertex of A, its errors
// against the truth, the round trip, the seams and the verdict.
#include "correspondence/correspondence_bench.h"

#include "correspondence/geodesic_distance.h"

#include <diffuv/correspondence/labelled_atlas_pair.h>
#include <diffuv/graph/distance_tags.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <iostream>
#include <limits>
#include <stdexcept>

namespace diffuv_bench {

namespace {

// Calls build(tag) with the distance tag the recipe names.
template <class Build>
auto with_distance_tag(const Atlas_recipe& recipe, Build build)
{
  switch(recipe.distance) {
  case Distance::graph: return build(diffuv::Graph_distance_tag());
  case Distance::exact: return build(diffuv::Exact_distance_tag());
  case Distance::fmm: break;
  }
  return build(diffuv::Fmm_distance_tag());
}

diffuv::Labelled_atlas_options atlas_options(const Atlas_recipe& recipe)
{
  diffuv::Labelled_atlas_options options;
  if(recipe.repair >= 0) options.repair.enabled = recipe.repair == 1;
  options.sub_patches = recipe.sub_patches;
  return options;
}

// `follow`: the sub-patches and corners of another atlas to follow (atlas_to_follow()), or null.
diffuv::Status build_atlas(const Mesh& m, const std::vector<int>& labels, Labelled& out, const Atlas_recipe& recipe,
                           const diffuv::Atlas_to_follow* follow)
{
  const diffuv::Labelled_atlas_options options = atlas_options(recipe);
  return with_distance_tag(recipe, [&](auto tag) {
    using Tag = decltype(tag);
    return follow ? diffuv::build_labelled_atlas<Tag>(m, m.points(), labels, *follow, out, options)
                  : diffuv::build_labelled_atlas<Tag>(m, m.points(), labels, out, options);
  });
}

// Both atlases built together (build_labelled_atlas_pair()): regions B lost
// join their neighbour on both meshes. B's labels are carried from A's here.
diffuv::Labelled_atlas_pair<Mesh> build_pair(const Mesh& a, const std::vector<int>& labels_a, const Mesh& b,
                                             const std::vector<int>& labels_b, const Atlas_recipe& recipe, bool follow)
{
  diffuv::Labelled_atlas_pair_options options;
  options.atlas = atlas_options(recipe);
  options.follow = follow;
  options.join_labels_missing_in_b = true;
  if(!recipe.join) options.max_rounds = 1;
  return with_distance_tag(recipe, [&](auto tag) {
    return diffuv::build_labelled_atlas_pair<decltype(tag)>(a, a.points(), labels_a, b, b.points(), labels_b, options);
  });
}

// A's atlas (and its seam rings) replaced for one pair, put back after it.
class Atlas_of_a_for_this_pair {
public:
  Atlas_of_a_for_this_pair(Mesh_case& a, std::unique_ptr<Labelled> atlas) : a_(a)
  {
    if(!atlas) return;
    saved_ = std::move(a.atlas);
    saved_ring_ = std::move(a.ring);
    a.atlas = std::move(atlas);
    a.ring = seam_rings(a.mesh, *a.atlas);
  }
  ~Atlas_of_a_for_this_pair()
  {
    if(!saved_) return;
    a_.atlas = std::move(saved_);
    a_.ring = std::move(saved_ring_);
  }
  Atlas_of_a_for_this_pair(const Atlas_of_a_for_this_pair&) = delete;
  Atlas_of_a_for_this_pair& operator=(const Atlas_of_a_for_this_pair&) = delete;

private:
  Mesh_case& a_;
  std::unique_ptr<Labelled> saved_;
  std::vector<int> saved_ring_;
};

} // namespace

std::unique_ptr<Labelled> timed_atlas(const Mesh& m, const std::vector<int>& labels, const Atlas_recipe& recipe,
                                      int runs, double& median_ms, const diffuv::Atlas_to_follow* follow)
{
  std::vector<double> times;
  std::unique_ptr<Labelled> la;
  for(int run = 0; run < runs; ++run) {
    la = std::make_unique<Labelled>(m);
    const auto t0 = Clock::now();
    const diffuv::Status status = build_atlas(m, labels, *la, recipe, follow);
    times.push_back(ms_since(t0));
    if(!status.ok()) throw std::runtime_error("build_labelled_atlas failed: " + status.what());
  }
  median_ms = median(times);
  return la;
}

std::vector<int> seam_rings(const Mesh& m, const Labelled& la)
{
  std::vector<int> ring(m.number_of_vertices(), std::numeric_limits<int>::max());
  std::vector<vertex_descriptor> queue;
  for(auto v : m.vertices()) {
    const auto e = la.atlas.entries(v);
    if(e.second - e.first >= 2) {
      ring[v.idx()] = 0;
      queue.push_back(v);
    }
  }
  for(std::size_t i = 0; i < queue.size(); ++i)
    for(auto w : CGAL::vertices_around_target(m.halfedge(queue[i]), m))
      if(ring[w.idx()] == std::numeric_limits<int>::max()) {
        ring[w.idx()] = ring[queue[i].idx()] + 1;
        queue.push_back(w);
      }
  return ring;
}

Pair_result run_pair(Mesh_case& a, const std::string& pair, const Atlas_recipe& recipe, int runs, bool follow,
                     Geodesic_distance& geodesic_a)
{
  Pair_result r;
  r.mesh = a.name;
  r.pair = pair;
  const auto t_variant = Clock::now();
  const Variant b = make_variant(pair, a.mesh, a.labels, a.mean_edge);
  r.how = b.how;
  r.vertices_a = a.mesh.number_of_vertices();
  r.vertices_b = b.mesh.number_of_vertices();
  r.faces_b = b.mesh.number_of_faces();
  std::cerr << "[" << a.name << "/" << pair << "] B: " << r.vertices_b << " vertices, " << r.faces_b << " faces ("
            << format("%.0f", ms_since(t_variant)) << " ms to make)\n";

  // Both atlases as the `correspond` tool builds them with --transfer-labels:
  // regions B is too coarse to keep join their neighbour on both meshes, and
  // B follows A's corners unless told not to. A's atlas is then built again
  // for this pair only; B's is timed as A's was, from the joined labels.
  diffuv::Labelled_atlas_pair<Mesh> both = build_pair(a.mesh, a.labels, b.mesh, b.labels, recipe, follow);
  if(!both.status.ok()) throw std::runtime_error("build_labelled_atlas_pair failed: " + both.status.what());
  r.rounds = both.rounds;
  r.joined = both.joined.size();
  const Atlas_of_a_for_this_pair a_for_this_pair(a, both.joined.empty() ? nullptr : std::move(both.a));
  std::vector<int> labels_b = b.labels;
  diffuv::join_labels(labels_b, both.joined);
  const diffuv::Atlas_to_follow follow_a = diffuv::atlas_to_follow(*a.atlas);
  std::unique_ptr<Labelled> atlas_b =
      timed_atlas(b.mesh, labels_b, recipe, runs, r.param_b_ms, follow ? &follow_a : nullptr);
  for(const auto& patch : atlas_b->patches) r.followed += patch.side_report.named ? 1 : 0;
  r.param_a_ms = a.param_ms;

  // The mapping of every vertex: construction of the correspondence + map_vertices().
  std::vector<double> times;
  std::vector<Image> images;
  for(int run = 0; run < runs; ++run) {
    const auto t0 = Clock::now();
    const Correspondence c(*a.atlas, *atlas_b);
    images = c.map_vertices();
    times.push_back(ms_since(t0));
  }
  r.map_ms = median(times);
  const Correspondence ab(*a.atlas, *atlas_b);
  const Correspondence ba(*atlas_b, *a.atlas);
  r.match = ab.report();
  r.matched = r.match.matched_patches;
  r.charts_a = a.atlas->atlas.number_of_charts();
  r.charts_b = atlas_b->atlas.number_of_charts();
  r.patches_a = a.atlas->segmentation.number_of_patches();
  r.patches_b = atlas_b->segmentation.number_of_patches();
  r.cleaned_a = a.atlas->cleaning.changed_faces();
  r.cleaned_b = atlas_b->cleaning.changed_faces();
  std::cerr << "[" << a.name << "/" << pair << "] param B " << format("%.1f", r.param_b_ms) << " ms, map "
            << format("%.1f", r.map_ms) << " ms; " << r.matched << "/" << r.charts_a << " charts matched ("
            << r.charts_b << " in B); " << r.joined << " regions lost by B joined in " << r.rounds
            << (r.rounds == 1 ? " build" : " builds") << "; measuring errors\n";

  // Errors against the truth, and the round trip.
  const auto t_errors = Clock::now();
  Geodesic_distance geodesic_b(b.mesh);
  const double scale_b = 1. / std::sqrt(PMP::area(b.mesh)), scale_a = 1. / std::sqrt(a.area);
  r.error.assign(r.vertices_a, infinity);
  r.round_trip.assign(r.vertices_a, infinity);
  for(auto v : a.mesh.vertices()) {
    const Image& img = images[v.idx()];
    if(!img.mapped()) {
      ++r.unmapped;
      continue;
    }
    const Location mapped(img.face, img.barycentric);
    r.error[v.idx()] = geodesic_b(b.truth[v.idx()], mapped) * scale_b;
    const Image back = ba.map_point(img.face, img.barycentric);
    if(back.mapped())
      r.round_trip[v.idx()] = geodesic_a(PMP::locate_vertex<double>(v, a.mesh), Location(back.face, back.barycentric)) * scale_a;
  }

  // Seams: the images of a vertex taken from each of its charts.
  for(auto v : a.mesh.vertices()) {
    const auto entries = a.atlas->atlas.entries(v);
    if(entries.second - entries.first < 2) continue;
    std::vector<Location> points;
    bool all = true;
    for(auto it = entries.first; it != entries.second; ++it) {
      const Image img = ab.map_vertex(v, it->chart);
      if(!img.mapped()) all = false;
      else points.emplace_back(img.face, img.barycentric);
    }
    if(!all) {
      ++r.seam_unmapped;
      continue;
    }
    double worst = 0.;
    for(std::size_t i = 0; i < points.size(); ++i)
      for(std::size_t j = i + 1; j < points.size(); ++j) worst = std::max(worst, geodesic_b(points[i], points[j]));
    r.seam.push_back(worst * scale_b);
  }
  const auto& gs = geodesic_b.statistics();
  std::cerr << "[" << a.name << "/" << pair << "] errors measured in " << format("%.1f", ms_since(t_errors) / 1000.)
            << " s (" << gs.queries << " geodesics on B: " << gs.same_face << " in one face, " << gs.piece_runs
            << " runs on pieces of " << format("%.0f", gs.piece_runs ? double(gs.piece_faces) / gs.piece_runs : 0.)
            << " faces on average, " << gs.retries << " retries, " << gs.whole_mesh_runs << " on the whole mesh, "
            << gs.no_path << " without a path from p, retried from q)\n";

  // Verdict against the targets.
  const Summary e = summarize(r.error);
  std::vector<std::string> failures;
  if(pair == "shuffled") {
    if(r.unmapped > 0 || e.max > 1e-9) failures.push_back("max > 1e-9");
  } else {
    if(percent_within(r.error, 0.05) < 95.) failures.push_back("< 95 % within 0.05");
    if(e.mean > 0.01) failures.push_back("mean > 0.01");
  }
  if(a.name == "man" && (pair == "fine" || pair == "coarse") && r.map_ms > 50.) failures.push_back("t_map > 50 ms");
  r.passed = failures.empty();
  r.verdict = r.passed ? "ok" : "FAIL";
  for(std::size_t k = 0; k < failures.size(); ++k) r.verdict += (k ? ", " : " (") + failures[k] + (k + 1 == failures.size() ? ")" : "");
  r.diagnostics = diagnose(a, b, *atlas_b, ab, ba, images, r);
  return r;
}

} // namespace diffuv_bench
