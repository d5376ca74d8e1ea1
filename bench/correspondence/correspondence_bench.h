// diffuv benchmark: accuracy of the (region, u, v) correspondence where the
// truth is known. What the files of the correspondence bench share: the
// second meshes (B) of a mesh A, the atlases, the results of one pair, the
// statistics and the options. How it measures: main.cpp.
#ifndef DIFFUV_BENCH_CORRESPONDENCE_BENCH_H
#define DIFFUV_BENCH_CORRESPONDENCE_BENCH_H

#include "common.h"

#include <diffuv/correspondence/correspondence.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/core/error.h>

#include <CGAL/Polygon_mesh_processing/locate.h>

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace diffuv_bench {

namespace PMP = CGAL::Polygon_mesh_processing;
using Location = PMP::Face_location<Mesh, double>;  // (face, barycentric coordinates)
using Labelled = diffuv::Labelled_atlas<Mesh>;
using Correspondence = diffuv::Atlas_correspondence<Mesh, Mesh>;
using Image = Correspondence::Point;

// ---------------------------------------------------------------------------
// Mesh helpers (variants.cpp)

/// The three corners of triangle `f`, in Face_location order.
inline std::array<vertex_descriptor, 3> corners(face_descriptor f, const Mesh& m)
{
  const halfedge_descriptor h = m.halfedge(f);
  return {{m.source(h), m.target(h), m.target(m.next(h))}};
}

inline Point_3 point_at(const Location& loc, const Mesh& m) { return PMP::construct_point(loc, m); }

double mean_edge_length(const Mesh& m);
double bounding_diagonal(const Mesh& m);

// ---------------------------------------------------------------------------
// The second meshes (B) and their labels (variants.cpp)

struct Variant {
  std::string name;
  Mesh mesh;
  std::vector<int> labels;        // #F(B) entries
  std::vector<Location> truth;    // #V(A) entries: the true image of each vertex of A on B
  std::string how;                // how the labels and the truth were made
};

/// B of kind `name` (fine, coarse, shuffled, loop, noise) made from A (`a`, with `labels_a`).
Variant make_variant(const std::string& name, const Mesh& a, const std::vector<int>& labels_a, double mean_edge);

// ---------------------------------------------------------------------------
// Statistics (report.cpp)

struct Summary {
  double mean = 0., p95 = 0., max = 0.;
  std::size_t count = 0, infinite = 0;
};

/// Mean and max over the finite values, p95 (nearest rank) over all of them
/// (an infinite value is a failure: it sorts last).
Summary summarize(std::vector<double> values);
/// The percentage of `values` at most `r`.
double percent_within(const std::vector<double>& values, double r);

// ---------------------------------------------------------------------------
// Atlases, with the distance and the options chosen on the command line (pairs.cpp)

enum class Distance { fmm, graph, exact };

struct Atlas_recipe {
  Distance distance = Distance::fmm;
  // --repair / --no-repair: 1 / 0; -1 keeps the library's default (Labelled_atlas_options).
  int repair = -1;
  // --sub-patches: regions with 3 or 5..9 runs are split into four-sided sectors (split_regions_into_quads()).
  bool sub_patches = false;
  // --no-join: regions B lost are left unmapped instead of joined on both meshes (build_labelled_atlas_pair()).
  bool join = true;
};

/// Builds the labelled atlas `runs` times; returns the last one and the median
/// time. `follow`: the sub-patches and corners of another atlas to follow
/// (atlas_to_follow()), or null.
std::unique_ptr<Labelled> timed_atlas(const Mesh& m, const std::vector<int>& labels, const Atlas_recipe& recipe,
                                      int runs, double& median_ms, const diffuv::Atlas_to_follow* follow = nullptr);

// ---------------------------------------------------------------------------
// One mesh A and its pairs

struct Mesh_case {
  std::string name;
  Mesh mesh;
  std::vector<int> labels;           // automatic patches (what `diffuv segment` writes)
  std::size_t automatic_patches = 0;
  double area = 0., mean_edge = 0.;
  std::unique_ptr<Labelled> atlas;
  double param_ms = 0.;
  std::vector<int> ring;             // per vertex: edges to the nearest vertex in two or more charts
};

struct Pair_result {
  std::string mesh, pair, how;
  std::size_t vertices_a = 0, vertices_b = 0, faces_b = 0;
  std::size_t charts_a = 0, charts_b = 0, patches_a = 0, patches_b = 0, matched = 0;
  std::size_t cleaned_a = 0, cleaned_b = 0;
  std::size_t followed = 0;          // patches of B whose corners followed A's names
  std::size_t joined = 0;            // regions B lost, joined to a neighbour on both meshes
  int rounds = 1;                    // builds of both atlases (build_labelled_atlas_pair())
  diffuv::Region_match_report match;
  std::size_t unmapped = 0;
  std::vector<double> error;         // #V(A): geodesic on B / sqrt(area B), inf if unmapped
  std::vector<double> round_trip;    // #V(A): geodesic on A / sqrt(area A), inf if unmapped
  std::vector<double> seam;          // per vertex of A in two or more charts
  std::size_t seam_unmapped = 0;
  double param_a_ms = 0., param_b_ms = 0., map_ms = 0.;
  std::string diagnostics;           // markdown
  bool passed = false;
  std::string verdict;
};

class Geodesic_distance;

/// Edges from each vertex to the nearest vertex in two or more charts (pairs.cpp).
std::vector<int> seam_rings(const Mesh& m, const Labelled& la);

/// Mesh B of kind `pair` made from A, both atlases, the mapping, its errors
/// and the verdict against the targets (pairs.cpp).
Pair_result run_pair(Mesh_case& a, const std::string& pair, const Atlas_recipe& recipe, int runs, bool follow,
                     Geodesic_distance& geodesic_a);

/// Where the errors of one pair come from, in markdown (diagnostics.cpp).
std::string diagnose(const Mesh_case& a, const Variant& b, const Labelled& atlas_b, const Correspondence& ab,
                     const Correspondence& ba, const std::vector<Image>& images, const Pair_result& r);

/// --self-check: the local exact geodesics against Surface_mesh_shortest_path
/// on the whole mesh (self_check.cpp). True if they agree.
bool self_check(const std::string& path);

// ---------------------------------------------------------------------------
// Output (report.cpp)

struct Options {
  std::vector<std::string> meshes{"cow", "man", "elephant", "hand"};
  std::vector<std::string> pairs{"fine", "coarse", "shuffled", "loop", "noise"};
  int runs = 3;
  std::string output = "bench-out/correspondence";
  std::string distance = "fmm";
  bool self_check = false;
  bool follow = true;
  std::string labels = "quads";
  Atlas_recipe atlas;        // .distance from `distance`
};

/// The table of all pairs, with the targets under it (markdown).
std::string table(const std::vector<Pair_result>& results, const Options& o);

} // namespace diffuv_bench

#endif // DIFFUV_BENCH_CORRESPONDENCE_BENCH_H
