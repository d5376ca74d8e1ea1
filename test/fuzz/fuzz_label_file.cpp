// libFuzzer entry point of the label_file target (see label_file.h).
#include "label_file.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  diffuv_fuzz::label_file(data, size);
  return 0;
}
