// diffuv correspondence bench: the statistics of the errors and the table.
#include "correspondence/correspondence_bench.h"

#include <sstream>

namespace diffuv_bench {

Summary summarize(std::vector<double> values)
{
  Summary s;
  s.count = values.size();
  if(values.empty()) return s;
  std::sort(values.begin(), values.end());
  double sum = 0.;
  std::size_t finite = 0;
  for(double x : values)
    if(std::isfinite(x)) {
      sum += x;
      ++finite;
      s.max = x;
    }
  s.infinite = values.size() - finite;
  s.mean = finite ? sum / static_cast<double>(finite) : infinity;
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(values.size())));
  s.p95 = values[std::max<std::size_t>(rank, 1) - 1];
  return s;
}

double percent_within(const std::vector<double>& values, double r)
{
  if(values.empty()) return 0.;
  const auto n = std::count_if(values.begin(), values.end(), [r](double x) { return x <= r; });
  return 100. * static_cast<double>(n) / static_cast<double>(values.size());
}

std::string table(const std::vector<Pair_result>& results, const Options& o)
{
  std::ostringstream out;
  out << "Correspondence accuracy (errors: geodesic distance on B / sqrt(area B); round trip on A / sqrt(area A)); "
      << o.distance << " distances; "
      << (o.follow ? "B's atlas follows A's sub-patches and corners (atlas_to_follow)" : "B's atlas built on its own (--no-follow)")
      << "; A's regions: " << (o.labels == "voronoi" ? "diffuv 0.1's Voronoi patches" : "the four-sided layout's patches")
      << "; sub-patches " << (o.atlas.sub_patches ? "on (--sub-patches)" : "off")
      << "; regions B loses " << (o.atlas.join ? "joined to a neighbour on both meshes" : "left unmapped (--no-join)")
      << "; times in ms, median of " << o.runs << " run" << (o.runs > 1 ? "s" : "") << ".\n\n";
  out << "| mesh | pair | A verts | B verts | charts matched | cleaned faces A/B | unmapped | mean | p95 | max | "
         "% <= 0.01 | % <= 0.05 | round trip mean | round trip p95 | seam mean | seam p95 | seam max | t_param A | t_param B | "
         "t_map | target |\n";
  out << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for(const Pair_result& r : results) {
    const Summary e = summarize(r.error), rt = summarize(r.round_trip), s = summarize(r.seam);
    std::string charts = std::to_string(r.matched) + "/" + std::to_string(r.charts_a);
    if(r.charts_b != r.charts_a) charts += " (B " + std::to_string(r.charts_b) + ")";
    out << "| " << r.mesh << " | " << r.pair << " | " << r.vertices_a << " | " << r.vertices_b << " | " << charts << " | "
        << r.cleaned_a << "/" << r.cleaned_b << " | " << r.unmapped << " | " << format("%.3g", e.mean) << " | "
        << format("%.3g", e.p95) << " | " << format("%.3g", e.max) << " | "
        << format("%.1f", percent_within(r.error, 0.01)) << " | " << format("%.1f", percent_within(r.error, 0.05))
        << " | " << format("%.3g", rt.mean) << " | " << format("%.3g", rt.p95) << " | " << format("%.3g", s.mean)
        << (r.seam_unmapped ? " (" + std::to_string(r.seam_unmapped) + " unmapped)" : std::string()) << " | "
        << format("%.3g", s.p95) << " | " << format("%.3g", s.max) << " | " << format("%.1f", r.param_a_ms) << " | " << format("%.1f", r.param_b_ms)
        << " | " << format("%.1f", r.map_ms) << " | " << r.verdict << " |\n";
  }
  out << "\nTargets: shuffled: every vertex maps to itself (max <= 1e-9); other pairs: >= 95 % within 0.05 and mean <= "
         "0.01; man fine/coarse: t_map <= 50 ms. Mean and max are over mapped vertices; p95 and the percentages count "
         "unmapped vertices as failures. Round-trip mean/p95 likewise. Seam: for each vertex of A in two or more charts, "
         "the largest geodesic distance on B between its images from each chart (vertices with an unmapped image "
         "left out and counted). Charts matched: charts of A with a counterpart in B / charts of A (B's count if it "
         "differs). Cleaned faces: faces whose label the cleaning changed.\n";
  return out.str();
}

} // namespace diffuv_bench
