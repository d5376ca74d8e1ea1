// diffuv tool: the pictures of `param` and `render` — the rendered mesh (PNG)
// and each chart's uv layout (SVG).
#ifndef DIFFUV_CLI_PICTURES_H
#define DIFFUV_CLI_PICTURES_H

#include "pipeline.h"

#include <diffuv/io/atomic_file.h>
#include <diffuv/render/render_mesh.h>

#include <string>
#include <utility>
#include <vector>

namespace diffuv_cli {

/// `--size WxH` as (width, height).
/// \throws CLI::ValidationError (a usage error) for a size the tool cannot draw
std::pair<int, int> picture_size(const std::string& size);

/// The mesh's up axis that --up names (auto: `diffuv::guess_up_axis()`), for the picture and the glTF file.
diffuv::Up_axis up_axis(const Input_mesh& in, const Param_options& options);

/// The picture: the mesh with u, v isolines, faces coloured by patch or by a
/// distortion measure (a heat map on a log scale, flipped faces in magenta,
/// faces in no chart grey, and a colour bar).
diffuv::Image picture(const Input_mesh& in, const Parameterization& result, const std::vector<Chart_measure>& measures,
                      const Param_options& options);

/// Each mapped patch's uv layout, `<mesh>.patch<N>.svg` in `out`.
void write_uv_layouts(diffuv::Output_folder& out, const Input_mesh& in, const Parameterization& result);

} // namespace diffuv_cli

#endif // DIFFUV_CLI_PICTURES_H
