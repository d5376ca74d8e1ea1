// diffuv: a generated checkerboard texture, and PNG files.
//
// A checkerboard on the unit square is the usual way to look at a
// parameterization: stretched, sheared or folded cells show where the map
// distorts. `write_obj(path, ..., "mesh.mtl", "checker")`, `write_mtl(...,
// "checker", "checker.png")` (output/write_obj.h) and
// `write_png_file("checker.png", ...)` give a textured OBJ that any viewer
// (MeshLab, Blender) opens.
//
// Indexed PNGs of a few colours (the checker) are deflated by zlib (Debian
// package zlib1g-dev) row by row; RGB ones use stb_image_write (libstb-dev), compiled into
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

#include <zlib.h>

#include <cstddef>
#include <cstdint>
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

namespace internal {

// The checkerboard's geometry along one axis (the image is square): each
// pixel column's cell, and whether it lies on a grid line. One definition for
// the RGB image and the indexed PNG, so that both show the same pixels.
class Checker_axis {
public:
  Checker_axis(int size, int cells) : cell_(static_cast<std::size_t>(size)), on_line_(static_cast<std::size_t>(size))
  {
    if(cells < 1 || size < cells)
      throw std::invalid_argument("checker_texture: need 1 <= cells <= size (cells " + std::to_string(cells) +
                                  ", size " + std::to_string(size) + ")");
    const int line = size / 512 > 1 ? size / 512 : 1;
    for(int x = 0; x < size; ++x) {
      const int k = static_cast<int>(static_cast<long long>(x) * cells / size);
      const int begin = static_cast<int>((static_cast<long long>(k) * size + cells - 1) / cells); // first column of cell k
      const int end = static_cast<int>((static_cast<long long>(k + 1) * size + cells - 1) / cells); // one past its last
      cell_[static_cast<std::size_t>(x)] = k;
      on_line_[static_cast<std::size_t>(x)] = (x - begin < line || end - 1 - x < line) ? 1 : 0;
    }
  }
  /// 0 for a light cell, 1 for a dark one, 2 for the grid: the palette of `checker_palette()`.
  unsigned char index(int x, int y) const
  {
    const auto X = static_cast<std::size_t>(x), Y = static_cast<std::size_t>(y);
    if(on_line_[X] || on_line_[Y]) return 2;
    return static_cast<unsigned char>((cell_[X] + cell_[Y]) % 2);
  }

private:
  std::vector<int> cell_;
  std::vector<char> on_line_;
};

inline std::vector<Color> checker_palette()
{
  return {Checker_colors::light, Checker_colors::dark, Checker_colors::grid};
}

} // namespace internal

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
/// `write_checker_png()` writes the same pixels without holding the image.
///
/// \param size the width and height in pixels
/// \param cells the number of cells along each side
/// \returns `3 * size * size` bytes
/// \throws std::invalid_argument unless `1 <= cells` and `cells <= size`
inline std::vector<unsigned char> checker_texture(int size = 512, int cells = 8)
{
  const internal::Checker_axis axis(size, cells);
  const std::vector<Color> palette = internal::checker_palette();
  std::vector<unsigned char> rgb(static_cast<std::size_t>(size) * size * 3);
  for(int y = 0; y < size; ++y)
    for(int x = 0; x < size; ++x) {
      const Color& c = palette[axis.index(x, y)];
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

namespace internal {

inline void png_be32(std::string& s, std::uint32_t v)
{
  for(int shift = 24; shift >= 0; shift -= 8) s.push_back(static_cast<char>((v >> shift) & 0xffu));
}

// Appends one PNG chunk to png: length, type, data, and the CRC of type and data.
inline void png_chunk(std::string& png, const char* type, const char* data, std::size_t size)
{
  png_be32(png, static_cast<std::uint32_t>(size));
  png.append(type, 4);
  png.append(data, size);
  uLong crc = crc32(0, reinterpret_cast<const Bytef*>(type), 4);
  crc = crc32(crc, reinterpret_cast<const Bytef*>(data), static_cast<uInt>(size));
  png_be32(png, static_cast<std::uint32_t>(crc));
}

// A zlib deflate stream, ended on every way out.
struct Deflate_stream {
  z_stream z{};
  bool live = false;
  explicit Deflate_stream(int level) { live = deflateInit(&z, level) == Z_OK; }
  ~Deflate_stream()
  {
    if(live) deflateEnd(&z);
  }
  Deflate_stream(const Deflate_stream&) = delete;
  Deflate_stream& operator=(const Deflate_stream&) = delete;
};

} // namespace internal

/// Writes an image of palette indices as an indexed-colour PNG (colour type 3,
/// 1, 2, 4 or 8 bits per pixel, the fewest the palette needs), streamed row by
/// row through zlib: the image is never held whole, only its compressed
/// bytes, written to `out` at the end. Every PNG reader expands it to the
/// palette's RGB colours.
///
/// Why: a texture of a few colours (the checker of `diffuv param`'s OBJ and
/// glb) then costs a row's memory and a fraction of the data to compress.
/// The 1024 x 1024 checker as RGB through stb took 11-15 ms to encode and
/// 10 ms more to fill (doc/performance.md); indexed, it takes about 2 ms.
///
/// \tparam RowIndices callable as `row(y, indices)`: fills `indices[0 .. width)`
///         with the palette indices of row y (rows from the top)
/// \param out the stream (opened in binary mode if it is a file)
/// \param width, height the size in pixels
/// \param palette 1 to 256 colours
/// \returns whether zlib compressed the image (it fails only when out of
///          memory; nothing is written then); the stream's state tells
///          whether writing succeeded
/// \throws std::invalid_argument if a size is not positive, the palette is
///         empty or longer than 256, or a row holds an index beyond it
///         (nothing is written); what `row` throws, likewise
template <class RowIndices>
bool write_indexed_png(std::ostream& out, int width, int height, const std::vector<Color>& palette, RowIndices row)
{
  if(width <= 0 || height <= 0) throw std::invalid_argument("write_indexed_png: the image size must be positive");
  if(palette.empty() || palette.size() > 256)
    throw std::invalid_argument("write_indexed_png: " + std::to_string(palette.size()) + " colours (need 1 to 256)");
  const int depth = palette.size() <= 2 ? 1 : palette.size() <= 4 ? 2 : palette.size() <= 16 ? 4 : 8;
  const std::size_t w = static_cast<std::size_t>(width);
  const std::size_t packed_bytes = (w * static_cast<std::size_t>(depth) + 7) / 8;

  // The whole file is made in memory (a few KB for a checker) and written
  // at the end, so a bad index or a throwing callback leaves `out` untouched.
  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  internal::png_be32(header, static_cast<std::uint32_t>(width));
  internal::png_be32(header, static_cast<std::uint32_t>(height));
  header += {static_cast<char>(depth), 3, 0, 0, 0}; // indexed colour, deflate, no filter method, no interlace
  internal::png_chunk(png, "IHDR", header.data(), header.size());
  std::string colours;
  for(const Color& c : palette) colours += {static_cast<char>(c.r), static_cast<char>(c.g), static_cast<char>(c.b)};
  internal::png_chunk(png, "PLTE", colours.data(), colours.size());

  // Deflate level 2, rows unfiltered (filter byte 0), as write_png(); an
  // IDAT chunk each time 64 KB of compressed data are ready.
  internal::Deflate_stream stream(2);
  if(!stream.live) return false;
  z_stream& z = stream.z;
  std::vector<unsigned char> indices(w), previous(w), packed(packed_bytes + 1, 0), block(1 << 16);
  for(int y = 0; y < height; ++y) {
    row(y, indices.data());
    if(y == 0 || indices != previous) { // a repeated row is packed once (a checker has three kinds)
      std::fill(packed.begin(), packed.end(), 0);
      for(std::size_t x = 0; x < w; ++x) {
        if(indices[x] >= palette.size())
          throw std::invalid_argument("write_indexed_png: index " + std::to_string(indices[x]) + " at pixel (" +
                                      std::to_string(x) + ", " + std::to_string(y) + ") beyond a palette of " +
                                      std::to_string(palette.size()));
        const std::size_t bit = x * static_cast<std::size_t>(depth);
        packed[1 + bit / 8] |= static_cast<unsigned char>(indices[x] << (8 - depth - static_cast<int>(bit % 8)));
      }
      previous.swap(indices);
    }
    z.next_in = packed.data();
    z.avail_in = static_cast<uInt>(packed.size());
    const int flush = y + 1 == height ? Z_FINISH : Z_NO_FLUSH;
    do {
      z.next_out = block.data();
      z.avail_out = static_cast<uInt>(block.size());
      const int status = deflate(&z, flush);
      if(status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR) return false;
      const std::size_t made = block.size() - z.avail_out;
      if(made > 0) internal::png_chunk(png, "IDAT", reinterpret_cast<const char*>(block.data()), made);
    } while(z.avail_out == 0);
  }
  internal::png_chunk(png, "IEND", "", 0);
  out.write(png.data(), static_cast<std::streamsize>(png.size()));
  return true;
}

/// Writes `checker_texture(size, cells)` as an indexed PNG (three colours, 2
/// bits per pixel) without making the RGB image: what `diffuv param` writes
/// beside its OBJ and into its glb.
///
/// \returns whether the image was encoded (see `write_indexed_png()`)
/// \throws std::invalid_argument unless `1 <= cells` and `cells <= size`
inline bool write_checker_png(std::ostream& out, int size = 512, int cells = 8)
{
  const internal::Checker_axis axis(size, cells);
  return write_indexed_png(out, size, size, internal::checker_palette(), [&](int y, unsigned char* indices) {
    for(int x = 0; x < size; ++x) indices[x] = axis.index(x, y);
  });
}

} // namespace diffuv

#endif // DIFFUV_RENDER_TEXTURE_H
