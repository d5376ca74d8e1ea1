// libFuzzer entry point of the mesh_param target (see mesh_param.h).
#include "mesh_param.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  diffuv_fuzz::mesh_param(data, size);
  return 0;
}
