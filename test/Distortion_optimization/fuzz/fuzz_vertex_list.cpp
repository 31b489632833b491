// libFuzzer target for IO::read_vertex_list (the tool's --fix file), for a mesh of 1000 vertices,
// IO::read_vertex_weights (--vertex-weights), for 4 vertices, and IO::read_vertex_pairs (--seams),
// for 1000 vertices joined in a path (i to i + 1): any input must give one flag (one positive
// finite weight) per vertex, or pairs in range that are edges, or raise Invalid_input; anything
// else is a bug.

#include <CGAL/Distortion_optimization/IO/vertex_list.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream in(text), weights_in(text), pairs_in(text);
  try {
    if(CGAL::Distortion_optimization::IO::read_vertex_list(in, 1000, "fuzz").size() != 1000) std::abort();
  } catch(const CGAL::Distortion_optimization::Invalid_input&) {
  }
  try {
    const std::vector<double> w = CGAL::Distortion_optimization::IO::read_vertex_weights(weights_in, 4, "fuzz");
    if(w.size() != 4) std::abort();
    for(double x : w)
      if(!(x > 0) || !std::isfinite(x)) std::abort();
  } catch(const CGAL::Distortion_optimization::Invalid_input&) {
  }
  const auto is_edge = [](std::size_t i, std::size_t j) { return i + 1 == j || j + 1 == i; };
  try {
    for(const auto& [i, j] : CGAL::Distortion_optimization::IO::read_vertex_pairs(pairs_in, 1000, is_edge, "fuzz"))
      if(i >= 1000 || j >= 1000 || !is_edge(i, j)) std::abort();
  } catch(const CGAL::Distortion_optimization::Invalid_input&) {
  }
  return 0;
}
