// libFuzzer target: diffuv::read_face_labels(), the --labels file parser.
//
// The expected count is the number of white-space separated words outside
// # comments, so that valid files are read to the end. A file that reads
// must read back the same after write_face_labels() (round trip).
#ifndef DIFFUV_FUZZ_LABEL_FILE_H
#define DIFFUV_FUZZ_LABEL_FILE_H

#include "fuzz_input.h"

#include <diffuv/core/error.h>
#include <diffuv/io/read_labels.h>
#include <diffuv/output/write_labels.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace diffuv_fuzz {

/// Runs the target on one input.
inline void label_file(const std::uint8_t* data, std::size_t size)
{
  const std::string path = diffuv_fuzz::write_input(data, size, ".txt");

  std::size_t words = 0;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for(std::string line; std::getline(lines, line);) {
    std::istringstream tokens(line.substr(0, line.find('#')));
    for(std::string token; tokens >> token;) ++words;
  }

  std::vector<int> labels;
  try {
    labels = diffuv::read_face_labels(path, words);
  } catch(const diffuv::Input_error& e) {
    diffuv_fuzz::note(e.what());
    return; // a documented rejection
  }
  diffuv_fuzz::note(std::to_string(labels.size()) + " labels");
  diffuv_fuzz::check(labels.size() == words, "read_face_labels returned another count than asked for");
  for(int label : labels) diffuv_fuzz::check(label >= 0, "read_face_labels returned a negative label");

  const std::string copy = path + ".copy.txt";
  diffuv::write_face_labels(copy, labels);
  diffuv_fuzz::check(diffuv::read_face_labels(copy, labels.size()) == labels,
                     "write_face_labels then read_face_labels changes the labels");
}

} // namespace diffuv_fuzz

#endif // DIFFUV_FUZZ_LABEL_FILE_H
