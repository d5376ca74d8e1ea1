// The bench reads as the tool does: large allocations advised onto huge pages.
#include <diffuv/core/huge_page_allocation.h>
