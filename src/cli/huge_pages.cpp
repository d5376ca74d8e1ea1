// The tool's large allocations advised onto huge pages (reading a 1M-vertex
// mesh spent half of its time faulting fresh 4 KiB pages in).
#include <diffuv/core/huge_page_allocation.h>
