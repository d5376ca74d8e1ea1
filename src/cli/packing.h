// diffuv command line: the packing options `param` and `bake` share.
#ifndef DIFFUV_CLI_PACKING_H
#define DIFFUV_CLI_PACKING_H

#include "pipeline.h"

#include <diffuv/render/pack_charts.h>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

namespace diffuv_cli {

/// The library's packing options from the command line's.
inline diffuv::Chart_packing_options packing_options(const Param_options& o)
{
  diffuv::Chart_packing_options packing;
  packing.resolution = o.texture_size;
  packing.gutter = o.gutter;
  packing.packer = o.packer == "skyline" ? diffuv::Chart_packer::skyline : diffuv::Chart_packer::shelves;
  return packing;
}

/// The summary line of a packing: `atlas: N charts packed into ...`.
inline std::string packing_summary(std::size_t charts, const Param_options& o, const diffuv::Chart_packing& packing)
{
  const diffuv::Chart_packing_options used = packing_options(o);
  char within[64] = "";
  if(used.packer == diffuv::Chart_packer::shelves)
    std::snprintf(within, sizeof within, " (each chart's within %.3g %%)", 100. * used.density_tolerance);
  char line[300];
  std::snprintf(line, sizeof line,
                "atlas: %zu chart%s packed into %d x %d texels (gutter %d, %s): %.1f %% of the texels covered, %.4g "
                "texels per unit of length%s",
                charts, charts == 1 ? "" : "s", o.texture_size, o.texture_size, o.gutter, o.packer.c_str(), 100. * packing.coverage,
                packing.texels_per_unit, within);
  return line;
}

/// --packer shelves|skyline.
inline CLI::Option* add_packer_option(CLI::App* cmd, Param_options& o)
{
  return cmd
      ->add_option("--packer", o.packer,
                   "How the charts are packed: shelves (rows of charts of one height, each row filled to the "
                   "texture's edge by letting each chart's texel density give up to 4.5 % and its aspect 10 %) or "
                   "skyline (stb_rect_pack: every chart at exactly one density and its own aspect, more texels left "
                   "empty)")
      ->check(CLI::IsMember({"shelves", "skyline"}))
      ->capture_default_str();
}

} // namespace diffuv_cli

#endif // DIFFUV_CLI_PACKING_H
