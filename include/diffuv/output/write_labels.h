// diffuv: a label file, one region label per face, which
// `read_face_labels()` (io/read_labels.h) reads back.
#ifndef DIFFUV_OUTPUT_WRITE_LABELS_H
#define DIFFUV_OUTPUT_WRITE_LABELS_H

#include <diffuv/core/error.h>
#include <diffuv/io/atomic_file.h>

#include <cstddef>
#include <string>
#include <vector>

namespace diffuv {

/// Writes labels one per line, readable by `read_face_labels()`, through
/// `Atomic_output_file`.
/// \throws Output_error naming `path` if the file cannot be written, or if a
///         label is negative ("face 3 has label -1; labels are non-negative
///         integers"); nothing is written then
inline void write_face_labels(const std::string& path, const std::vector<int>& labels)
{
  for(std::size_t j = 0; j < labels.size(); ++j)
    if(labels[j] < 0)
      throw Output_error(path, "face " + std::to_string(j) + " has label " + std::to_string(labels[j]) +
                                   "; labels are non-negative integers");
  Atomic_output_file file(path);
  for(int label : labels)
    file.stream() << label << '\n';
  file.commit();
}

} // namespace diffuv

#endif // DIFFUV_OUTPUT_WRITE_LABELS_H
