// libFuzzer entry point of the selection_file target (see selection_file.h).
#include "selection_file.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  diffuv_fuzz::selection_file(data, size);
  return 0;
}
