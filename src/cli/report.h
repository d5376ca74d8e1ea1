// diffuv tool: what `param` and `render` print — the summary lines, the table
// of patches with their totals, the warnings, the times.
#ifndef DIFFUV_CLI_REPORT_H
#define DIFFUV_CLI_REPORT_H

#include "pipeline.h"

#include <cstddef>
#include <string>
#include <vector>

namespace diffuv_cli {

/// A finished run, as the report needs it.
struct Param_run {
  const Input_mesh& in;
  const Parameterization& result;
  const std::vector<Chart_measure>& measures;  ///< by patch
  double total_ms = 0;                         ///< the median time of the runs
  std::size_t failed = 0;                      ///< patches without a chart
  const Stage_clock& stages;
  const std::vector<std::string>& written;     ///< the files written
  bool measured = true;                        ///< false: --no-measure, `measures` are empty
  std::string atlas_line = {};                 ///< how the charts were packed, or empty
};

/// Prints the summary and the table on stdout, the warnings on stderr.
void print_param_report(const Param_run& run, const Param_options& options);

/// The warnings of the report alone (--quiet): zero-area faces, patches not mapped.
void print_param_warnings(const Param_run& run);

} // namespace diffuv_cli

#endif // DIFFUV_CLI_REPORT_H
