// diffuv: a generated checkerboard texture, and PNG files.
//
// A checkerboard on the unit square is the usual way to look at a
// parameterization: stretched, sheared or folded cells show where the map
// distorts. `write_obj(path, ..., "mesh.mtl", "checker")`, `write_mtl(...,
// "checker", "checker.png")` (output/write_obj.h) and
// `write_png_file("checker.png", ...)` give a textured OBJ that any viewer
// (MeshLab, Blender) opens.
//
// PNG encoding uses stb_image_write (Debian package libstb-dev), compiled into
// every translation unit that includes this header as static functions, so
// that no separate implementation file is needed and two headers of diffuv
// using it (see render/) can share one copy through the same guard.
#ifndef DIFFUV_RENDER_TEXTURE_H
#define DIFFUV_RENDER_TEXTURE_H

#include <diffuv/core/color.h>
#include <diffuv/core/error.h>
#include <diffuv/io/atomic_file.h>

#ifndef DIFFUV_STB_IMAGE_WRITE_INCLUDED
#define DIFFUV_STB_IMAGE_WRITE_INCLUDED
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-variable"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wtype-limits"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
// stb's implementation section has no guard of its own: a later plain include
// of stb_image_write.h (by the user) must not compile it a second time.
#undef STB_IMAGE_WRITE_IMPLEMENTATION
#undef STB_IMAGE_WRITE_STATIC
#pragma GCC diagnostic pop
#endif

#include <cstddef>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace diffuv {

/// The colours of `checker_texture()`.
struct Checker_colors {
  static constexpr Color light = {235, 235, 225}; ///< cells whose row + column is even (the top-left cell)
  static constexpr Color dark = {50, 90, 170};    ///< the other cells
  static constexpr Color grid = {20, 20, 20};     ///< the lines between cells and around the image
};

/// Returns a checkerboard image: `size` x `size` RGB pixels, `cells` x `cells`
/// cells of alternating `Checker_colors::light` and `Checker_colors::dark`,
/// with a thin `Checker_colors::grid` line along every cell border.
///
/// Pixels are row by row from the top (row 0 is v = 1 once mapped, as in
/// PNG), 3 bytes each: `3 * (y * size + x) + channel`. Pixel column x lies in
/// cell `x * cells / size` (integer division), likewise rows, so cells differ
/// by at most one pixel when `cells` does not divide `size`. A grid line is
/// `max(1, size / 512)` pixels wide on each side of a cell border, so it is
/// one pixel on the image's own border and two between cells at 512 pixels.
///
/// \param size the width and height in pixels
/// \param cells the number of cells along each side
/// \returns `3 * size * size` bytes
/// \throws std::invalid_argument unless `1 <= cells` and `cells <= size`
inline std::vector<unsigned char> checker_texture(int size = 512, int cells = 8)
{
  if(cells < 1 || size < cells)
    throw std::invalid_argument("checker_texture: need 1 <= cells <= size (cells " + std::to_string(cells) +
                                ", size " + std::to_string(size) + ")");
  const int line = size / 512 > 1 ? size / 512 : 1;
  // Per column (and row, the image is square): its cell, and whether it is on a grid line.
  std::vector<int> cell(size);
  std::vector<char> on_line(size);
  for(int x = 0; x < size; ++x) {
    const int k = static_cast<int>(static_cast<long long>(x) * cells / size);
    const int begin = static_cast<int>((static_cast<long long>(k) * size + cells - 1) / cells); // first column of cell k
    const int end = static_cast<int>((static_cast<long long>(k + 1) * size + cells - 1) / cells); // one past its last
    cell[x] = k;
    on_line[x] = (x - begin < line || end - 1 - x < line) ? 1 : 0;
  }
  std::vector<unsigned char> rgb(static_cast<std::size_t>(size) * size * 3);
  for(int y = 0; y < size; ++y)
    for(int x = 0; x < size; ++x) {
      const Color& c = (on_line[x] || on_line[y]) ? Checker_colors::grid
                       : ((cell[x] + cell[y]) % 2 == 0 ? Checker_colors::light : Checker_colors::dark);
      unsigned char* p = &rgb[3 * (static_cast<std::size_t>(y) * size + x)];
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
    }
  return rgb;
}

namespace internal {

// stb_image_write's output callback: appends to a std::ostream.
inline void stb_write_to_ostream(void* context, void* data, int size)
{
  static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
}

// Throws std::invalid_argument unless rgb holds a width x height RGB image.
inline void check_rgb_image(const char* function, int width, int height, const std::vector<unsigned char>& rgb)
{
  if(width <= 0 || height <= 0)
    throw std::invalid_argument(std::string(function) + ": the image size must be positive");
  if(rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)
    throw std::invalid_argument(std::string(function) + ": " + std::to_string(rgb.size()) + " bytes for a " +
                                std::to_string(width) + " x " + std::to_string(height) + " RGB image");
}

} // namespace internal

/// Writes an RGB image as PNG to `out`.
///
/// \param out the stream (opened in binary mode if it is a file)
/// \param width, height the size in pixels
/// \param rgb `3 * width * height` bytes, row by row from the top
/// \returns whether stb_image_write encoded the image (it fails only when out of memory);
///          the stream's state tells whether writing succeeded
/// \throws std::invalid_argument if a size is not positive or `rgb` has the wrong size
inline bool write_png(std::ostream& out, int width, int height, const std::vector<unsigned char>& rgb)
{
  internal::check_rgb_image("write_png", width, height, rgb);
  // No row filter and deflate level 2: stb's default tries all five filters
  // on every row and compresses at level 8. On diffuv's pictures this is
  // about twice as fast and the files no larger (cow's picture: 27 -> 14 ms,
  // 167 -> 128 KB; the checker texture: 13 -> 4 ms, 8.4 -> 10.6 KB). Set
  // once (thread-safe) since stb keeps them in globals.
  static const bool tuned = (stbi_write_force_png_filter = 0, stbi_write_png_compression_level = 2, true);
  (void)tuned;
  return stbi_write_png_to_func(&internal::stb_write_to_ostream, &out, width, height, 3, rgb.data(), width * 3) != 0;
}

/// Writes an RGB image as the PNG file `path`, through `Atomic_output_file`:
/// on error, an existing file at `path` is left as it was.
///
/// \param path the file; its folder must exist
/// \param width, height the size in pixels
/// \param rgb `3 * width * height` bytes, row by row from the top (as from `checker_texture()`)
/// \throws std::invalid_argument if a size is not positive or `rgb` has the wrong size
///         (nothing is written)
/// \throws Output_error naming `path` if the file cannot be created, encoded or written
inline void write_png_file(const std::string& path, int width, int height, const std::vector<unsigned char>& rgb)
{
  internal::check_rgb_image("write_png_file", width, height, rgb); // before the file is created
  Atomic_output_file file(path);
  if(!write_png(file.stream(), width, height, rgb))
    throw Output_error(path, "PNG encoding failed");
  file.commit();
}

} // namespace diffuv

#endif // DIFFUV_RENDER_TEXTURE_H
