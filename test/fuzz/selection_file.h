// libFuzzer target: diffuv::read_selection_file(), the parser of CGAL's
// *.selection.txt files (--corners). Only the first line is read; the indices
// it returns must be the words of that line, as decimal numbers.
#ifndef DIFFUV_FUZZ_SELECTION_FILE_H
#define DIFFUV_FUZZ_SELECTION_FILE_H

#include "fuzz_input.h"

#include <diffuv/core/error.h>
#include <diffuv/io/selection_file.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace diffuv_fuzz {

/// Runs the target on one input.
inline void selection_file(const std::uint8_t* data, std::size_t size)
{
  const std::string path = diffuv_fuzz::write_input(data, size, ".selection.txt");
  std::vector<std::size_t> indices;
  try {
    indices = diffuv::read_selection_file(path);
  } catch(const diffuv::Input_error& e) {
    diffuv_fuzz::note(e.what());
    return; // a documented rejection
  }
  diffuv_fuzz::note(std::to_string(indices.size()) + " indices");
  diffuv_fuzz::check(!indices.empty(), "read_selection_file returned no index without an error");

  std::string text(reinterpret_cast<const char*>(data), size);
  if(text.compare(0, 3, "\xEF\xBB\xBF") == 0)
    text.erase(0, 3); // the reader skips a UTF-8 byte order mark
  std::istringstream first_line(text.substr(0, text.find('\n')));
  std::size_t k = 0;
  for(std::string word; first_line >> word; ++k) {
    diffuv_fuzz::check(k < indices.size(), "read_selection_file returned fewer indices than the line has words");
    const std::size_t digits = word.find_first_not_of('0');
    const std::string number = digits == std::string::npos ? "0" : word.substr(digits);
    diffuv_fuzz::check(std::to_string(indices[k]) == number, "an index differs from its word");
  }
  diffuv_fuzz::check(k == indices.size(), "read_selection_file returned more indices than the line has words");
}

} // namespace diffuv_fuzz

#endif // DIFFUV_FUZZ_SELECTION_FILE_H
