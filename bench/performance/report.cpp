// diffuv performance bench: the results. The row files a worker hands to the
// parent, the markdown tables, results.csv and the log-log plots.
#include "performance/performance_bench.h"

#include "plot_png.h"

#include <algorithm>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>

namespace diffuv_bench {

void write_row(const Row& row, const std::string& path)
{
  std::ofstream f(path);
  for(const auto& kv : row.values) f << kv.first << "=" << kv.second << "\n";
}

Row read_row(const std::string& path)
{
  Row row;
  std::ifstream f(path);
  std::string line;
  while(std::getline(f, line)) {
    const auto eq = line.find('=');
    if(eq != std::string::npos) row.values.emplace_back(line.substr(0, eq), line.substr(eq + 1));
  }
  return row;
}

std::string cell(const Row& r, const std::string& key, const char* f)
{
  const double x = r.number(key);
  if(std::isnan(x)) return r.get(key);
  return format(f, x);
}

namespace {

// One column of a markdown table: its header, its alignment and its cell of a row.
struct Column {
  std::string header;
  bool left = false;  // left-aligned ("---"), else right-aligned ("---:")
  std::function<std::string(const Row&)> text;
};

// A column showing the value of `key` as stored (left-aligned if `left`).
Column stored(const std::string& header, const std::string& key, bool left = false)
{
  return {header, left, [key](const Row& r) { return r.get(key); }};
}

// A column showing the number under `key` printed with `f`.
Column number(const std::string& header, const std::string& key, const char* f = "%.3g")
{
  return {header, false, [key, f](const Row& r) { return cell(r, key, f); }};
}

// A column showing two columns' cells as "a<between>b<after>".
Column joined(const std::string& header, const Column& a, const std::string& between, const Column& b,
              const std::string& after = "")
{
  return {header, false, [=](const Row& r) { return a.text(r) + between + b.text(r) + after; }};
}

// "a (b)".
Column with_paren(const std::string& header, const Column& a, const Column& b)
{
  return joined(header, a, " (", b, ")");
}

// The columns every table starts with.
std::vector<Column> size_columns(std::vector<Column> more)
{
  std::vector<Column> columns = {stored("mesh", "mesh", true), stored("level", "level"), stored("V", "V")};
  columns.insert(columns.end(), more.begin(), more.end());
  return columns;
}

void write_table(std::ostream& out, const std::vector<Row>& rows, const std::vector<Column>& columns)
{
  out << "|";
  for(const Column& c : columns) out << " " << c.header << " |";
  out << "\n|";
  for(const Column& c : columns) out << (c.left ? "---|" : "---:|");
  out << "\n";
  for(const Row& r : rows) {
    out << "|";
    for(const Column& c : columns) out << " " << c.text(r) << " |";
    out << "\n";
  }
}

} // namespace

std::string tables(const std::vector<Row>& rows, const Options& o)
{
  std::ostringstream out;
  out << "### (a) one multi-source Dijkstra, whole mesh, from one side of the largest patch (ms)\n\n";
  write_table(out, rows,
              size_columns({stored("E", "E"), stored("sources", "sources"), number("fibonacci", "dij_fib_ms"),
                            number("pairing", "dij_pairing_ms"), number("binomial", "dij_binomial_ms"),
                            number("4-ary", "dij_quaternary_ms"), number("fib / best", "dij_fib_over_best", "%.2f"),
                            number("fib ns/(E log2 V)", "dij_fib_ns_ElogV", "%.2f"),
                            with_paren("fib on largest patch (V)", number("", "dij_patch_fib_ms"),
                                       stored("", "dij_patch_V")),
                            number("fmm run", "fmm_run_ms"), number("fmm set-up", "fmm_setup_ms")}));
  out << "\n### (a') the same run, bench-local references on a compressed-row (CSR) graph (ms; not library code)\n\n";
  write_table(out, rows,
              size_columns({number("library fibonacci", "dij_fib_ms"), number("CSR + fibonacci", "dij_csr_fib_ms"),
                            number("CSR + fibonacci, pool allocator", "dij_csr_fib_pool_ms"),
                            number("CSR + 4-ary", "dij_csr_4ary_ms"),
                            number("CSR + binary heap, lazy deletion", "dij_csr_ref_ms"),
                            number("same, BFS-renumbered vertices", "dij_csr_bfs_ms"),
                            stored("max difference", "dij_csr_ref_maxdiff")}));

  out << "\n### (b, d) the whole parameterization from given patches, and CGAL on the same patches (ms)\n\n";
  write_table(out, rows,
              size_columns({stored("patches", "patches"), number("paper (graph, no repair)", "paper_ms"),
                            with_paren("floor: 4 Boost Dijkstra runs per patch (paper / floor)",
                                       number("", "floor_ms"), number("", "paper_over_floor", "%.2f")),
                            number("default (fmm + repair)", "default_ms"),
                            joined("same, 4-ary heap: paper / default", number("", "paper_4ary_ms"), " / ",
                                   number("", "default_4ary_ms")),
                            with_paren("automatic patches (#)", number("", "auto_ms"), stored("", "auto_patches")),
                            number("paper ns/(E log2 V)", "paper_ns_ElogV", "%.2f"),
                            number("default ns/(E log2 V)", "default_ns_ElogV", "%.2f"),
                            stored("2 threads: speed-up paper / default", "threads2_speedup"),
                            number("CGAL tutte", "tutte_ms"), number("CGAL mean value", "mean_value_ms"),
                            number("min CGAL / default", "cgal_over_default", "%.2f"),
                            number("min CGAL / paper", "cgal_over_paper", "%.2f"),
                            with_paren("repair: moved (whole-patch solves)", stored("", "default_moved"),
                                       stored("", "default_whole_patch"))}));

  out << "\n### (c, e) atlas queries and memory\n\n";
  write_table(
      out, rows,
      size_columns({stored("charts", "charts"), number("atlas build ms", "atlas_build_ms"),
                    number("kd-trees alone ms", "kd_build_ms"), number("nearest vertex /s", "nn_per_s"),
                    with_paren("locate /s (% inside)", number("", "locate_per_s"),
                               number("", "locate_inside_pct", "%.1f")),
                    number("k-NN reference /s", "knn_ref_per_s"),
                    with_paren("peak B/vertex default (extra)", number("", "mem_default_peak_Bpv", "%.0f"),
                               number("", "mem_default_extra_Bpv", "%.0f")),
                    with_paren("peak B/vertex paper (extra)", number("", "mem_paper_peak_Bpv", "%.0f"),
                               number("", "mem_paper_extra_Bpv", "%.0f")),
                    number("child ru_maxrss B/vertex", "child_maxrss_Bpv", "%.0f"), stored("status", "status", true)}));

  if(o.profile) {
    // A row per (mesh, size, method), holding that method's stage times.
    const char* const stages[] = {"total", "setup", "disc_check", "sides", "ffg", "engine", "distances", "repair",
                                  "chart", "engine_setup", "engine_runs", "scan_vertices", "scan_faces"};
    const char* const headers[] = {"total", "setup", "disc check", "sides", "patch graph", "engine", "distances",
                                   "repair", "chart + kd", "engine set-up*", "4 runs*", "one vertex pass*",
                                   "one face pass*"};
    std::vector<Row> by_method;
    for(const Row& r : rows)
      for(const char* method : {"paper", "default"}) {
        Row m;
        for(const char* key : {"mesh", "level", "V"}) m.set(key, r.get(key));
        m.set("method", std::string(method));
        for(const char* s : stages) m.set(s, r.get(std::string("prof_") + method + "_" + s));
        by_method.push_back(std::move(m));
      }
    std::vector<Column> columns = {stored("method", "method", true)};
    for(std::size_t k = 0; k < std::size(stages); ++k) columns.push_back(number(headers[k], stages[k]));
    out << "\n### pipeline stages (ms, sums over patches; --profile)\n\n";
    write_table(out, by_method, size_columns(columns));
    out << "\n*: measured apart, not part of the total (default method only). patch graph: the paper's method\n"
           "copies each patch into a compact graph (Patch_graph), the default walks a Face_filtered_graph.\n";
  }
  return out.str();
}

void write_csv(const std::vector<Row>& rows, const std::string& path)
{
  std::vector<std::string> keys;
  for(const Row& r : rows)
    for(const auto& kv : r.values)
      if(std::find(keys.begin(), keys.end(), kv.first) == keys.end()) keys.push_back(kv.first);
  std::ofstream f(path);
  for(std::size_t k = 0; k < keys.size(); ++k) f << (k ? "," : "") << keys[k];
  f << "\n";
  for(const Row& r : rows) {
    for(std::size_t k = 0; k < keys.size(); ++k) f << (k ? "," : "") << r.get(keys[k]);
    f << "\n";
  }
}

namespace {

using Points = std::vector<std::pair<double, double>>;

// A plot against log10 vertices, legend upper left.
diffuv_bench::Line_plot size_plot(const std::string& title, const std::string& y_label)
{
  diffuv_bench::Line_plot plot;
  plot.title = title;
  plot.x_label = "log10 vertices";
  plot.y_label = y_label;
  plot.legend = diffuv_bench::Line_plot::Legend::upper_left;
  return plot;
}

// A curve sorted by x, in the next colour; none if it has no points.
void add_series(diffuv_bench::Line_plot& plot, const std::string& name, Points points)
{
  if(points.empty()) return;
  std::sort(points.begin(), points.end());
  diffuv_bench::Plot_series s;
  s.name = name;
  s.color = diffuv_bench::series_color(plot.series.size());
  s.points = std::move(points);
  plot.series.push_back(std::move(s));
}

// The axes around the points, to half units (the plots are of logarithms).
void fit_bounds(diffuv_bench::Line_plot& plot)
{
  double x0 = infinity, x1 = -infinity, y0 = infinity, y1 = -infinity;
  for(const auto& s : plot.series)
    for(const auto& [x, y] : s.points) {
      x0 = std::min(x0, x); x1 = std::max(x1, x);
      y0 = std::min(y0, y); y1 = std::max(y1, y);
    }
  if(!(x1 > x0)) { x0 -= 0.5; x1 += 0.5; }
  if(!(y1 > y0)) { y0 -= 0.5; y1 += 0.5; }
  plot.x_min = std::floor(x0 * 2) / 2; plot.x_max = std::ceil(x1 * 2) / 2;
  plot.y_min = std::floor(y0 * 2) / 2; plot.y_max = std::ceil(y1 * 2) / 2;
}

} // namespace

// Log-log plots (log10 on both axes; the plot writer is linear).
void write_plots(const std::vector<Row>& rows, const std::vector<std::string>& names, const std::string& dir)
{
  // (log10 V, y) of each row of `mesh` (all meshes if empty) that has both;
  // y = f(row, value of key), or nothing where f gives NaN.
  auto points_of = [&](const std::string& mesh, const std::string& key, auto&& f) {
    Points points;
    for(const Row& r : rows) {
      if(!mesh.empty() && r.get("mesh") != mesh) continue;
      const double v = r.number("V"), y = r.number(key);
      if(std::isnan(v) || std::isnan(y)) continue;
      const double fy = f(r, y);
      if(!std::isnan(fy)) points.emplace_back(std::log10(v), fy);
    }
    return points;
  };
  const auto log_of_positive = [](const Row&, double y) { return y > 0 ? std::log10(y) : std::nan(""); };
  const auto as_is = [](const Row&, double y) { return y; };

  // Time against size, per mesh.
  for(const std::string& mesh : names) {
    diffuv_bench::Line_plot plot = size_plot(mesh + ": time against size", "log10 ms");
    const std::pair<const char*, const char*> curves[] = {
        {"paper (graph, raw)", "paper_ms"}, {"default (fmm + repair)", "default_ms"},
        {"automatic patches", "auto_ms"},   {"cgal tutte", "tutte_ms"},
        {"cgal mean value", "mean_value_ms"}, {"dijkstra (fibonacci)", "dij_fib_ms"}};
    for(const auto& [name, key] : curves) add_series(plot, name, points_of(mesh, key, log_of_positive));
    if(plot.series.empty()) continue;
    fit_bounds(plot);
    diffuv_bench::write_plot_png(dir + "/time_" + mesh + ".png", plot);
  }
  // ns / (E log2 V) against size: flat = O(E log V).
  diffuv_bench::Line_plot scaling = size_plot("time / (E log2 V)", "ns");
  for(const std::string& mesh : names) {
    add_series(scaling, mesh + " paper", points_of(mesh, "paper_ns_ElogV", as_is));
    add_series(scaling, mesh + " default", points_of(mesh, "default_ns_ElogV", as_is));
  }
  if(!scaling.series.empty()) {
    fit_bounds(scaling);
    scaling.y_min = 0;
    scaling.y_max = std::ceil(scaling.y_max / 10) * 10;
    diffuv_bench::write_plot_png(dir + "/scaling.png", scaling);
  }
  // Heaps: Dijkstra ns / (E log2 V), all meshes by size.
  diffuv_bench::Line_plot heaps = size_plot("one dijkstra run: ns / (E log2 V)", "ns");
  const std::pair<const char*, const char*> heap_curves[] = {
      {"fibonacci", "dij_fib_ms"}, {"pairing", "dij_pairing_ms"}, {"binomial", "dij_binomial_ms"},
      {"4-ary", "dij_quaternary_ms"}, {"csr + fibonacci (ref.)", "dij_csr_fib_ms"},
      {"csr + binary heap (ref.)", "dij_csr_ref_ms"}};
  const auto per_ElogV = [](const Row& r, double t) {
    const double v = r.number("V"), e = r.number("E");
    return t * 1e6 / (e * std::log2(v));
  };
  for(const auto& [name, key] : heap_curves) add_series(heaps, name, points_of("", key, per_ElogV));
  if(!heaps.series.empty()) {
    fit_bounds(heaps);
    heaps.y_min = 0;
    diffuv_bench::write_plot_png(dir + "/heaps.png", heaps);
  }
}

} // namespace diffuv_bench
