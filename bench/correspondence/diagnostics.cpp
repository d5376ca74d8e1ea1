// diffuv correspondence bench: where the errors of one pair come from
// (diagnostics.md): label cleaning, errors by distance from the seams, per
// chart, and the worst vertices.
#include "correspondence/correspondence_bench.h"

#include <diffuv/correspondence/nearest_face_labels.h>
#include <diffuv/patches/patch_names.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <map>
#include <numeric>
#include <sstream>
#include <tuple>

namespace diffuv_bench {

namespace {

std::string key_text(const Correspondence::Key& k)
{
  return "(" + std::to_string(std::get<0>(k)) + "," + std::to_string(std::get<1>(k)) + "," +
         std::to_string(std::get<2>(k)) + ")";
}

// The items of `r` separated by spaces, each written by `write(stream, item)`; "-" if none.
template <class Range, class Write>
std::string joined(const Range& r, Write&& write)
{
  std::ostringstream s;
  bool first = true;
  for(const auto& x : r) {
    s << (first ? "" : " ");
    write(s, x);
    first = false;
  }
  return first ? "-" : s.str();
}

template <class Range>
std::string list_text(const Range& r)
{
  return joined(r, [](std::ostream& s, const auto& x) { s << x; });
}

std::string patch_names_text(const std::vector<diffuv::Patch_key>& r)
{
  return joined(r, [](std::ostream& s, const diffuv::Patch_key& x) { s << diffuv::patch_name(x); });
}

} // namespace

std::string diagnose(const Mesh_case& a, const Variant& b, const Labelled& atlas_b, const Correspondence& ab,
                     const Correspondence& ba, const std::vector<Image>& images, const Pair_result& r)
{
  std::ostringstream out;
  const Mesh& ma = a.mesh;
  out << "### " << r.mesh << " / " << r.pair << "\n\n" << r.how << ".\n\n";
  out << "- patches: A " << a.atlas->segmentation.number_of_patches() << " (" << r.charts_a << " charts), B "
      << atlas_b.segmentation.number_of_patches() << " (" << r.charts_b << " charts); matched " << r.matched
      << "; labels only in A: " << list_text(r.match.labels_only_in_a) << "; only in B: "
      << list_text(r.match.labels_only_in_b) << "; unmatched patches of A: " << patch_names_text(r.match.unmatched_patches_a)
      << ", of B: " << patch_names_text(r.match.unmatched_patches_b) << "\n";
  out << "- label cleaning changed " << r.cleaned_a << " faces of A, " << r.cleaned_b << " of B; patching of B: "
      << atlas_b.patching.merged << " merged, " << atlas_b.patching.cut << " cut, " << atlas_b.patching.caps_split
      << " caps split (A: " << a.atlas->patching.merged << ", " << a.atlas->patching.cut << ", "
      << a.atlas->patching.caps_split << "); " << r.followed << " of B's " << atlas_b.patches.size()
      << " patches took their corners from A's names\n";
  out << "- regions of A that B lost (to its cleaning, its merging of small patches or the carrying of labels), "
         "joined to a neighbour on both meshes: "
      << r.joined << " (" << r.rounds << (r.rounds == 1 ? " build" : " builds") << " of both atlases)\n";

  // Faces of B whose cleaned label differs from the label of A's face nearest to them.
  {
    const std::vector<int> expected = diffuv::nearest_face_labels(ma, a.atlas->face_labels, b.mesh);
    std::size_t differ = 0;
    double differ_area = 0., total_area = 0.;
    for(auto f : b.mesh.faces()) {
      const double fa = PMP::face_area(f, b.mesh);
      total_area += fa;
      if(expected[f.idx()] != atlas_b.face_labels[f.idx()]) {
        ++differ;
        differ_area += fa;
      }
    }
    out << "- after cleaning, " << differ << " faces of B (" << format("%.2f", 100. * differ_area / total_area)
        << " % of the area) have another label than A's cleaned label at their centroid\n";
  }

  // Errors by distance (in edges) from the patch borders of A.
  struct Bucket {
    std::size_t n = 0, bad = 0, unmapped = 0;
    double sum = 0.;
  };
  const char* bucket_names[] = {"on a seam (2+ charts)", "1 edge from a seam", "2-3 edges", "4+ edges"};
  Bucket buckets[4];
  std::size_t truth_elsewhere = 0, truth_elsewhere_bad = 0;
  double truth_elsewhere_sum = 0.;
  std::map<std::size_t, Bucket> per_chart;
  for(auto v : ma.vertices()) {
    const int ring = a.ring[v.idx()];
    Bucket& bk = buckets[ring == 0 ? 0 : ring == 1 ? 1 : ring <= 3 ? 2 : 3];
    const double e = r.error[v.idx()];
    ++bk.n;
    if(!std::isfinite(e)) {
      ++bk.unmapped;
      continue;
    }
    bk.sum += e;
    if(e > 0.05) ++bk.bad;
    // The chart of B holding the true point, against the charts of v in A.
    const std::size_t truth_chart = atlas_b.atlas.chart_of(b.truth[v.idx()].first);
    bool same = false;
    const auto entries = a.atlas->atlas.entries(v);
    for(auto it = entries.first; it != entries.second; ++it)
      if(ab.chart_b(it->chart) == truth_chart) same = true;
    if(!same) {
      ++truth_elsewhere;
      truth_elsewhere_sum += e;
      if(e > 0.05) ++truth_elsewhere_bad;
    }
    Bucket& pc = per_chart[images[v.idx()].chart];
    ++pc.n;
    pc.sum += e;
    if(e > 0.05) ++pc.bad;
  }
  out << "\n| vertices of A | count | mean error | > 0.05 | unmapped |\n|---|---:|---:|---:|---:|\n";
  for(int k = 0; k < 4; ++k) {
    const Bucket& bk = buckets[k];
    const std::size_t finite = bk.n - bk.unmapped;
    out << "| " << bucket_names[k] << " | " << bk.n << " | " << format("%.4f", finite ? bk.sum / finite : 0.) << " | "
        << bk.bad << " | " << bk.unmapped << " |\n";
  }
  out << "\n- " << truth_elsewhere << " mapped vertices have their true point in a chart of B that is not the "
      << "counterpart of any of their charts (mean error " << format("%.4f", truth_elsewhere ? truth_elsewhere_sum / truth_elsewhere : 0.)
      << ", " << truth_elsewhere_bad << " above 0.05)\n";

  // Per chart: do the patches of A and B agree (corners, runs), was the map
  // re-solved by the fold repair, and how large are the errors.
  std::map<std::size_t, std::size_t> patch_of_chart_a, patch_of_chart_b;
  for(std::size_t p = 0; p < a.atlas->patches.size(); ++p) patch_of_chart_a[a.atlas->patches[p].chart] = p;
  for(std::size_t p = 0; p < atlas_b.patches.size(); ++p) patch_of_chart_b[atlas_b.patches[p].chart] = p;
  const double scale_b = 1. / std::sqrt(PMP::area(b.mesh));
  out << "\n| chart (label,part,rank) | faces A/B | neighbour runs A/B | corners moved (max, / sqrt area) | "
         "folded faces A/B | whole patch re-solved A/B | vertices | mean error | > 0.05 |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(std::size_t c = 0; c < r.charts_a; ++c) {
    const auto& pa = a.atlas->patches[patch_of_chart_a[c]];
    const std::size_t cb = ab.chart_b(c);
    out << "| " << key_text(ab.key_a(c)) << " | " << a.atlas->segmentation.patch_faces[patch_of_chart_a[c]].size();
    if(cb == diffuv::Uv_atlas<Mesh>::no_chart) {
      out << "/- | " << pa.side_report.runs << "/- | - | " << pa.repair.folded_faces << "/- | "
          << (pa.repair.whole_patch ? "yes" : "no") << "/- | ";
    } else {
      const auto& pb = atlas_b.patches[patch_of_chart_b[cb]];
      double moved = 0.;
      for(int k = 0; k < 4; ++k)
        moved = std::max(moved, std::sqrt(CGAL::squared_distance(ma.point(pa.sides.corners[k]),
                                                                 b.mesh.point(pb.sides.corners[k]))) * scale_b);
      out << "/" << atlas_b.segmentation.patch_faces[patch_of_chart_b[cb]].size() << " | " << pa.side_report.runs << "/"
          << pb.side_report.runs << " | " << format("%.3f", moved) << " | " << pa.repair.folded_faces << "/"
          << pb.repair.folded_faces << " | " << (pa.repair.whole_patch ? "yes" : "no") << "/"
          << (pb.repair.whole_patch ? "yes" : "no") << " | ";
    }
    const auto it = per_chart.find(cb);
    if(cb == diffuv::Uv_atlas<Mesh>::no_chart || it == per_chart.end()) out << "- | - | - |\n";
    else out << it->second.n << " | " << format("%.4f", it->second.sum / it->second.n) << " | " << it->second.bad << " |\n";
  }
  out << "\nWorst vertices:\n\n| vertex of A | error | charts of A | edges to seam | image chart key | truth chart key | inside | uv distance | round trip |\n|---:|---:|---|---:|---|---|---|---:|---:|\n";
  std::vector<std::size_t> order(ma.number_of_vertices());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return r.error[i] > r.error[j]; });
  for(std::size_t k = 0; k < std::min<std::size_t>(8, order.size()); ++k) {
    const vertex_descriptor v(static_cast<Mesh::size_type>(order[k]));
    const Image& img = images[v.idx()];
    std::string charts;
    const auto entries = a.atlas->atlas.entries(v);
    for(auto it = entries.first; it != entries.second; ++it)
      charts += (charts.empty() ? "" : " ") + key_text(ab.key_a(it->chart));
    const std::size_t truth_chart = atlas_b.atlas.chart_of(b.truth[v.idx()].first);
    out << "| " << v.idx() << " | " << format("%.4f", r.error[v.idx()]) << " | " << charts << " | " << a.ring[v.idx()]
        << " | " << (img.mapped() ? key_text(ba.key_a(img.chart)) : std::string("unmapped")) << " | "
        << (truth_chart == diffuv::Uv_atlas<Mesh>::no_chart ? std::string("none") : key_text(ba.key_a(truth_chart)))
        << " | " << (img.inside ? "yes" : "no") << " | " << format("%.3g", img.uv_distance) << " | "
        << format("%.4f", r.round_trip[v.idx()]) << " |\n";
  }
  out << "\n";
  return out.str();
}

} // namespace diffuv_bench
