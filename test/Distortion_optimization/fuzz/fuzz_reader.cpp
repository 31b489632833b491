// libFuzzer target for the package's mesh readers. Build one binary per format with
// -DFUZZ_READER=read_OFF, read_OBJ, read_MEDIT_soup, read_TetGen_pair, read_PLY, read_STL or
// read_GOCAD (scripts/fuzz.sh does). Any input must either
// parse into a consistent soup or raise Invalid_input: another exception, a crash, a hang or a
// sanitizer report is a bug.

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/IO/triangle_soup.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <sstream>
#include <string>

#ifndef FUZZ_READER
#error "define FUZZ_READER as read_OFF, read_OBJ, read_MEDIT_soup, read_TetGen_pair, read_PLY, read_STL or read_GOCAD"
#endif

namespace IO = CGAL::Distortion_optimization::IO;

// read_TetGen reads two streams: the input is the .node text, a NUL byte, then the .ele text.
IO::Tetrahedron_soup read_TetGen_pair(std::istream& in, const std::string& name)
{
  std::string node, ele;
  std::getline(in, node, '\0');
  std::getline(in, ele, '\0');
  std::istringstream node_in(node), ele_in(ele);
  return IO::read_TetGen(node_in, ele_in, name + ".node", name + ".ele");
}

// PLY, STL and GOCAD files go through CGAL's readers after the package's checks of their bytes,
// as read_triangle_soup() reads them.
IO::Triangle_soup read_bytes(std::istream& in, const std::string& name, const std::string& extension)
{
  std::string bytes(std::istreambuf_iterator<char>(in), {});
  return IO::internal::read_with_CGAL(std::move(bytes), name, extension);
}
IO::Triangle_soup read_PLY(std::istream& in, const std::string& name) { return read_bytes(in, name, "ply"); }
IO::Triangle_soup read_STL(std::istream& in, const std::string& name) { return read_bytes(in, name, "stl"); }
IO::Triangle_soup read_GOCAD(std::istream& in, const std::string& name) { return read_bytes(in, name, "ts"); }

template <class Cells>
void check(const std::vector<std::array<double, 3>>& points, const Cells& cells)
{
  for(const auto& p : points)
    for(double x : p)
      if(!std::isfinite(x)) std::abort();
  for(const auto& cell : cells)
    for(std::size_t i : cell)
      if(i >= points.size()) std::abort();
}

void check(const IO::Triangle_soup& s) { check(s.points, s.cells); }
void check(const IO::Tetrahedron_soup& s) { check(s.points, s.cells); }

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    using namespace CGAL::Distortion_optimization::IO;   // the readers, and read_TetGen_pair above
    check(FUZZ_READER(in, "fuzz"));
  } catch(const CGAL::Distortion_optimization::Invalid_input&) {
  }
  return 0;
}
