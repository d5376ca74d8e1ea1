// libFuzzer target: the readers of regions and colours painted in a mesh
// file: diffuv::read_painted_labels() (with and without a property name) and
// diffuv::read_vertex_colors(), on PLY (text and binary) and text OFF input.
// An input starting with "ply" is read as PLY, anything else as OFF.
//
// Checked on success: labels are non-negative; colour sources, and only they,
// give `colors`, and their labels index it.
#ifndef DIFFUV_FUZZ_PAINTED_COLORS_H
#define DIFFUV_FUZZ_PAINTED_COLORS_H

#include "fuzz_input.h"

#include <diffuv/core/error.h>
#include <diffuv/io/painted_labels.h>
#include <diffuv/io/read_vertex_colors.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace diffuv_fuzz {
namespace detail {

inline void check_labels(const diffuv::Painted_labels& painted)
{
  using diffuv::Label_source;
  using diffuv_fuzz::check;
  diffuv_fuzz::note("source " + std::to_string(static_cast<int>(painted.source)) + " \"" + painted.property + "\", " +
                    std::to_string(painted.polygon_labels.size()) + " polygon labels, " +
                    std::to_string(painted.colors.size()) + " colours");
  if(painted.source == Label_source::none) {
    check(painted.polygon_labels.empty(), "source none with labels");
    return;
  }
  const bool colors = painted.source == Label_source::face_colors || painted.source == Label_source::vertex_colors;
  check(colors != painted.colors.empty() || painted.polygon_labels.empty(), "colours given for a non-colour source");
  for(int label : painted.polygon_labels) {
    check(label >= 0, "a negative label");
    if(colors) check(static_cast<std::size_t>(label) < painted.colors.size(), "a colour label without its colour");
  }
}

} // namespace detail

/// Runs the target on one input.
inline void painted_colors(const std::uint8_t* data, std::size_t size)
{
  const bool ply = size >= 3 && data[0] == 'p' && data[1] == 'l' && data[2] == 'y';
  const std::string path = diffuv_fuzz::write_input(data, size, ply ? ".ply" : ".off");

  try {
    detail::check_labels(diffuv::read_painted_labels(path));
  } catch(const diffuv::Error& e) {
    // Input_error, or Error from vertex_labels_to_polygons(): documented rejections
    diffuv_fuzz::note(e.what());
  }
  if(ply) {
    try {
      detail::check_labels(diffuv::read_painted_labels(path, "label"));
    } catch(const diffuv::Error& e) {
      diffuv_fuzz::note(e.what());
    }
  }
  try {
    diffuv_fuzz::note(std::to_string(diffuv::read_vertex_colors(path).size()) + " vertex colours");
  } catch(const diffuv::Error& e) {
    diffuv_fuzz::note(e.what());
  }
}

} // namespace diffuv_fuzz

#endif // DIFFUV_FUZZ_PAINTED_COLORS_H
