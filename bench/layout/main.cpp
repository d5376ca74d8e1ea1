// diffuv bench: what the four-sided layout costs next to the map it serves
// (issue #18's "layout time <= map time"), and what the fallback patches'
// corner search buys for its time.
//
// Table 1, per mesh: disc_patches() with the default judge (the layout of
// `diffuv param`), of which choose_fallback_corners(), against
// parameterize_patches() of the patches it made (fast marching and the
// repair, all threads), medians of --runs runs.
//
// Table 2 (--corners), per mesh: the layout without the corner choice, then
// choose_fallback_corners() on the fallback patches only (every candidate
// mapped; candidates ranked by the quick estimate on large patches only, and
// on every patch, mapping 1, 2 or 3), and on the quads too (every candidate
// mapped, and the judge's default: ranked, 3 mapped, L2 above 1.5): the
// atlas's L2 stretch after the default pipeline, the vertices the repair
// moved, the patches given corners and the search's time (one run each).
//
// Usage: diffuv_layout_bench [--runs 3] [--meshes cow,man,...] [--corners] [-o DIR]
// Writes DIR/layout.md.
#include "common.h"

#include <diffuv/layout/disc_patches.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/layout_judge.h>
#include <diffuv/parameterization/parameterize_patches.h>

#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace diffuv_bench;
using Seg = diffuv::Segmentation<Mesh>;
using Vpm = decltype(std::declval<const Mesh&>().points());
using Judge = diffuv::Raw_map_judge<Mesh, Vpm>;

// The judge without choose_corners(): disc_patches() then leaves the
// fallback patches' corners to the rule.
struct Judge_without_corners {
  Judge judge;
  std::vector<std::size_t> operator()(const Seg& s, const std::vector<char>& candidates) const { return judge(s, candidates); }
};

struct Atlas_quality {
  double l2 = 0;
  std::size_t moved = 0;
};

// The default pipeline's atlas of `seg`: area-weighted L2 over the charts, vertices moved.
Atlas_quality map_and_measure(const Mesh& m, const Seg& seg)
{
  diffuv::Uv_atlas<Mesh> atlas(m);
  const auto results = diffuv::parameterize_patches(m, m.points(), seg, atlas);
  diffuv::Distortion_summary total;
  Atlas_quality q;
  for(const auto& r : results) {
    if(!r.status) continue;
    q.moved += r.repair.moved_vertices + r.repair.moved_border_vertices;
    total = diffuv::combined(total, diffuv::measure_distortion(m, m.points(), atlas.chart(r.chart).faces, atlas.chart_texture_map(r.chart)));
  }
  q.l2 = total.stretch_l2;
  return q;
}

} // namespace

int main(int argc, char** argv)
{
  CLI::App app{"diffuv layout bench: the four-sided layout's time next to the map's, and the corner search"};
  std::vector<std::string> meshes = {"cow", "man", "bull", "elephant", "lion-head", "mannequin-devil"};
  int runs = 3;
  bool corners = false;
  std::string output = "bench-out/layout";
  add_meshes_option(app, meshes, "Meshes");
  add_runs_option(app, runs, "Runs per time; the median is reported");
  app.add_flag("--corners", corners, "Also compare the settings of the fallback patches' corner search (table 2)");
  add_output_option(app, output);
  CLI11_PARSE(app, argc, argv);

  return exit_code_of([&] {
    std::filesystem::create_directories(output);
    std::ostringstream table;
    table << "| mesh | vertices | patches | layout ms | of which corner search ms | map ms | layout / map |\n"
          << "|---|---:|---:|---:|---:|---:|---:|\n";
    std::ostringstream search;
    search << "| mesh | setting | mapped per patch | L2 | moved | patches given corners | search ms |\n"
           << "|---|---|---:|---:|---:|---:|---:|\n";
    for(const std::string& name : meshes) {
      Mesh m;
      const std::string label = read_named_mesh(name, m);
      std::cerr << label << "\n";
      const Judge judge(m, m.points());
      Seg seg;
      diffuv::Patching_report report;
      const double layout_ms = median_time(runs, [&] {
        diffuv::disc_patches(m, m.points(), {}, seg, diffuv::Patching_options(), &report, Judge(m, m.points()));
      });
      // The corner search alone, on the layout it is given.
      Seg rule;
      diffuv::disc_patches(m, m.points(), {}, rule, diffuv::Patching_options(), nullptr, Judge_without_corners{judge});
      const double corners_ms = median_time(runs, [&] {
        Seg trial = rule;
        diffuv::choose_fallback_corners(m, m.points(), trial, diffuv::Raw_map_judge_options().corners);
      });
      const double map_ms = median_time(runs, [&] {
        diffuv::Uv_atlas<Mesh> atlas(m);
        diffuv::parameterize_patches(m, m.points(), seg, atlas);
      });
      table << "| " << label << " | " << num_vertices(m) << " | " << seg.number_of_patches() << " | " << format("%.0f", layout_ms)
            << " | " << format("%.0f", corners_ms) << " | " << format("%.0f", map_ms) << " | " << format("%.1f", layout_ms / map_ms)
            << " |\n";
      if(!corners) continue;
      const Atlas_quality by_rule = map_and_measure(m, rule);
      search << "| " << label << " | rule's corners | 0 | " << format("%.3f", by_rule.l2) << " | " << by_rule.moved << " | 0 | 0 |\n";
      struct Setting {
        const char* name;
        std::size_t from, mapped;
        bool quads;
        double min_stretch;
      };
      const std::size_t never = std::numeric_limits<std::size_t>::max();
      for(const Setting& s : {Setting{"fallback: every candidate mapped", never, 35, false, 2.0},
                              Setting{"fallback: ranked, large patches (before 2026-12-04)", 2000, 2, false, 2.0},
                              Setting{"fallback: ranked, every patch", 0, 1, false, 2.0},
                              Setting{"fallback: ranked, every patch", 0, 2, false, 2.0},
                              Setting{"fallback: ranked, every patch", 0, 3, false, 2.0},
                              Setting{"quads too, L2 > 1.5: every candidate mapped", never, 35, true, 1.5},
                              Setting{"quads too, L2 > 1.5: ranked, every patch (default)", 0, 3, true, 1.5}}) {
        diffuv::Fallback_corner_options o;
        o.estimate_from_faces = s.from;
        o.mapped_candidates = s.mapped;
        o.patches_with_corners = s.quads;
        o.min_stretch = s.min_stretch;
        Seg trial = rule;
        const auto t0 = Clock::now();
        const std::size_t set = diffuv::choose_fallback_corners(m, m.points(), trial, o);
        const double ms = ms_since(t0);
        const Atlas_quality q = map_and_measure(m, trial);
        search << "| " << label << " | " << s.name << " | " << s.mapped << " | " << format("%.3f", q.l2) << " | " << q.moved
               << " | " << set << " | " << format("%.0f", ms) << " |\n";
      }
    }
    std::cout << table.str();
    std::ofstream out(std::filesystem::path(output) / "layout.md");
    out << table.str();
    if(corners) {
      std::cout << "\n" << search.str();
      out << "\n" << search.str();
    }
    return 0;
  });
}
