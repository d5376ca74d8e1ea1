// diffuv command line: the packing options `param` and `bake` share.
#ifndef DIFFUV_CLI_PACKING_H
#define DIFFUV_CLI_PACKING_H

#include "pipeline.h"

#include <diffuv/render/pack_charts.h>

#include <CLI/CLI.hpp>

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
