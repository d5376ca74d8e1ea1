// libFuzzer entry point of the painted_colors target (see painted_colors.h).
#include "painted_colors.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  diffuv_fuzz::painted_colors(data, size);
  return 0;
}
