// libFuzzer target for IO::read_vertex_list (the tool's --fix file), for a mesh of 1000 vertices:
// any input must give one flag per vertex or raise Invalid_input; anything else is a bug.

#include <CGAL/Distortion_optimization/IO/vertex_list.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    if(CGAL::Distortion_optimization::IO::read_vertex_list(in, 1000, "fuzz").size() != 1000) std::abort();
  } catch(const CGAL::Distortion_optimization::Invalid_input&) {
  }
  return 0;
}
