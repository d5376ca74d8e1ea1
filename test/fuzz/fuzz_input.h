// diffuv fuzzing: what the libFuzzer targets share.
//
// diffuv's readers take a file name (the extension picks the format), so each
// input is written to one file per process and extension, rewritten for
// every input, in a folder diffuv-fuzz-<pid> of $DIFFUV_FUZZ_TMPDIR, else of
// /dev/shm when it exists (no disk traffic), else of the temporary folder.
// The folder is removed at a normal exit; libFuzzer leaves it behind when it
// stops on a crash, which is why scripts/fuzz.sh gives a folder of its own.
#ifndef DIFFUV_FUZZ_INPUT_H
#define DIFFUV_FUZZ_INPUT_H

#include <unistd.h>

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace diffuv_fuzz {

namespace detail {
inline std::filesystem::path& folder()
{
  static std::filesystem::path dir;
  return dir;
}
inline void remove_folder()
{
  std::error_code ec;
  std::filesystem::remove_all(folder(), ec);
}
} // namespace detail

/// Writes the input to `<folder>/input<extension>` and returns that path.
inline std::string write_input(const std::uint8_t* data, std::size_t size, const std::string& extension)
{
  namespace fs = std::filesystem;
  std::filesystem::path& dir = detail::folder();
  if(dir.empty()) {
    std::error_code ec;
    const char* const chosen = std::getenv("DIFFUV_FUZZ_TMPDIR");
    const fs::path base = chosen && *chosen                     ? fs::path(chosen)
                          : fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm")
                                                              : fs::temp_directory_path();
    dir = base / ("diffuv-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::atexit(detail::remove_folder);
  }
  const fs::path path = dir / ("input" + extension);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if(!out) {
    std::fprintf(stderr, "diffuv fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
  return path.string();
}

/// The mesh format of an input, from its content, so that a seed is a plain
/// mesh file and a mutation may turn one format into another:
/// ".ply" if it starts with "ply"; ".off" if its first word (after white
/// space and # comments) ends with "OFF"; ".stl" if it starts with "solid" or
/// has a byte that no text file has (binary STL); ".obj" otherwise.
inline std::string mesh_extension(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  if(text.compare(0, 3, "ply") == 0) return ".ply";
  std::size_t i = 0;
  while(i < size) {
    if(std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    else if(text[i] == '#') { while(i < size && text[i] != '\n') ++i; }
    else break;
  }
  std::size_t end = i;
  while(end < size && !std::isspace(static_cast<unsigned char>(text[end])) && text[end] != '#') ++end;
  if(end - i >= 3 && text.compare(end - 3, 3, "OFF") == 0) return ".off";
  if(text.compare(0, 5, "solid") == 0) return ".stl";
  for(unsigned char c : text)
    if(c == 0 || c >= 0x80 || (c < 0x20 && !std::isspace(c))) return ".stl";
  return ".obj";
}

/// With DIFFUV_FUZZ_VERBOSE set, targets print what the readers reject and
/// what they accept: `DIFFUV_FUZZ_VERBOSE=1 ./fuzz_mesh_param corpus/mesh_param/*`
/// shows what each seed reaches.
inline void note(const std::string& what)
{
  static const bool verbose = std::getenv("DIFFUV_FUZZ_VERBOSE") != nullptr;
  if(verbose) std::fprintf(stderr, "diffuv fuzz: %s\n", what.c_str());
}

/// A broken invariant: an exception that no target catches, so libFuzzer
/// reports a crash (std::terminate) and saves the input, and a regression
/// test fails with `what`.
struct Invariant_broken : std::logic_error {
  explicit Invariant_broken(const std::string& what) : std::logic_error("diffuv fuzz: invariant broken: " + what) {}
};

inline void check(bool ok, const char* what)
{
  if(!ok) throw Invariant_broken(what);
}

} // namespace diffuv_fuzz

#endif // DIFFUV_FUZZ_INPUT_H
