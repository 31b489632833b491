// Mesh files: the strict Medit reader, the Medit writer and the VTU writer, and what the OFF,
// OBJ and Medit readers share (bounded lines and reserves, nothing left unread, clear messages).

#include "kuhn_block.h"
#include "test_files.h"

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/IO/svg.h>
#include <CGAL/Distortion_optimization/IO/triangle_soup.h>
#include <CGAL/Distortion_optimization/IO/vtu.h>

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <new>
#include <random>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
namespace IO = CGAL::Distortion_optimization::IO;

namespace {

std::string temp(const std::string& name) { return ::testing::TempDir() + "distortion_io_" + name; }

using test_files::exists;
using test_files::leftovers;

std::string contents(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

IO::Tetrahedron_soup read(const std::string& text, const std::string& name = "bad.mesh")
{
  std::istringstream in(text);
  return IO::read_MEDIT_soup(in, name);
}

// The message of the Invalid_input thrown by reading `in` as `format` ("off", "obj" or "mesh"),
// or "" if nothing was thrown.
std::string reader_error(std::istream& in, const std::string& format, const std::string& name)
{
  try {
    if(format == "off") IO::read_OFF(in, name);
    else if(format == "obj") IO::read_OBJ(in, name);
    else IO::read_MEDIT_soup(in, name);
  } catch(const DO::Invalid_input& e) {
    return e.what();
  }
  return "";
}

// The same for `text`, named "bad.<format>".
std::string reader_error(const std::string& text, const std::string& format)
{
  std::istringstream in(text);
  return reader_error(in, format, "bad." + format);
}

// A message cut for printing: a failing reader may quote a whole (huge) line.
std::string shown(const std::string& message) { return message.substr(0, 300); }

#define EXPECT_READER_REJECTED(format, text, fragment)                                                  \
  do {                                                                                                  \
    const std::string message = reader_error(text, format);                                             \
    EXPECT_NE(message.find(fragment), std::string::npos) << "message: '" << shown(message) << "'";      \
  } while(false)

#define EXPECT_REJECTED(text, fragment) EXPECT_READER_REJECTED("mesh", text, fragment)

// Two tetrahedra sharing the face (1, 2, 3) of a unit corner, with coordinates that need all 17
// digits to round-trip.
IO::Tetrahedron_soup two_tetrahedra()
{
  IO::Tetrahedron_soup s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1. / 3, 2. / 3, 0.1 + 0.2}};
  s.cells = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  s.labels = {7, -2};
  return s;
}

const std::string header = "MeshVersionFormatted 1\nDimension 3\n";
const std::string four_vertices = "Vertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n";

// A stream that cannot seek, as a pipe: the reader cannot bound counts by the file size.
class Unseekable_buffer : public std::streambuf
{
public:
  explicit Unseekable_buffer(const std::string& s) : data_(s) { setg(&data_[0], &data_[0], &data_[0] + data_.size()); }

private:
  std::string data_;
};

} // namespace

// ---------------------------------------------------------------------------------------------
// Medit
// ---------------------------------------------------------------------------------------------

TEST(Medit, WriteThenReadGivesTheSameSoup)
{
  const std::string path = temp("round_trip.mesh");
  const IO::Tetrahedron_soup s = two_tetrahedra();
  IO::write_MEDIT_soup(path, s);
  EXPECT_EQ(leftovers(path), 0u);
  const IO::Tetrahedron_soup r = IO::read_tetrahedron_soup(path);
  EXPECT_EQ(r.points, s.points); // exact: 17 digits
  EXPECT_EQ(r.cells, s.cells);
  EXPECT_EQ(r.labels, s.labels);
  const std::string text = contents(path);
  EXPECT_EQ(text.rfind("MeshVersionFormatted 1\nDimension 3\nVertices\n5\n0 0 0 0\n", 0), 0u) << text;
  EXPECT_NE(text.find("Tetrahedra\n2\n1 2 3 4 7\n2 3 4 5 -2\nEnd\n"), std::string::npos) << text;
  std::remove(path.c_str());
}

TEST(Medit, WriterWithoutLabelsWritesOne)
{
  const std::string path = temp("no_labels.mesh");
  IO::Tetrahedron_soup s = two_tetrahedra();
  s.labels.clear();
  IO::write_MEDIT_soup(path, s);
  EXPECT_EQ(IO::read_tetrahedron_soup(path).labels, std::vector<int>({1, 1}));
  std::remove(path.c_str());
}

TEST(Medit, WriterRejectsWhatTheReaderWouldRejectAndWritesNothing)
{
  const std::string path = temp("rejected.mesh");
  std::remove(path.c_str());
  IO::Tetrahedron_soup s = two_tetrahedra();
  s.labels = {1};
  EXPECT_THROW(IO::write_MEDIT_soup(path, s), DO::Invalid_input);
  s = two_tetrahedra();
  s.cells[1][3] = 5;
  EXPECT_THROW(IO::write_MEDIT_soup(path, s), DO::Invalid_input);
  s = two_tetrahedra();
  s.cells[1][3] = 1;
  EXPECT_THROW(IO::write_MEDIT_soup(path, s), DO::Invalid_input);
  s = two_tetrahedra();
  s.points[4][2] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(IO::write_MEDIT_soup(path, s), DO::Invalid_input);
  s = two_tetrahedra();   // boundary triangles: an index out of range, a repeated vertex
  s.triangles = {{0, 1, 5}};
  EXPECT_THROW(IO::write_MEDIT_soup(path, s), DO::Invalid_input);
  s.triangles = {{0, 1, 1}};
  EXPECT_THROW(IO::write_MEDIT_soup(path, s), DO::Invalid_input);
  EXPECT_FALSE(exists(path));
  EXPECT_EQ(leftovers(path), 0u);
}

// sphere.mesh, written by CGAL (Vertices, Triangles, Tetrahedra, End). Its header says: 757
// vertices, the first "-0.00017958008027845786 -0.29158438056560654 -0.3988195263311396 2";
// 694 triangles; 3586 tetrahedra, all with reference 1, the first "669 309 483 629 1" and the
// last "231 407 95 756 1".
TEST(Medit, ReadsCGALSphere)
{
  const IO::Tetrahedron_soup s = IO::read_tetrahedron_soup(DISTORTION_OPTIMIZATION_DATA_DIR "/sphere.mesh");
  ASSERT_EQ(s.points.size(), 757u);
  ASSERT_EQ(s.cells.size(), 3586u);
  ASSERT_EQ(s.labels.size(), 3586u);
  EXPECT_EQ(s.points.front()[0], -0.00017958008027845786);
  EXPECT_EQ(s.points.front()[1], -0.29158438056560654);
  EXPECT_EQ(s.points.front()[2], -0.3988195263311396);
  EXPECT_EQ(s.points.back()[2], 0.42226421765882671);
  EXPECT_EQ(s.cells.front(), (std::array<std::size_t, 4>{668, 308, 482, 628}));
  EXPECT_EQ(s.cells.back(), (std::array<std::size_t, 4>{230, 406, 94, 755}));
  for(int label : s.labels) EXPECT_EQ(label, 1);
  // The vertices' references and the boundary triangles (CGAL's surface patches) are kept, and
  // written back: a map's output keeps them.
  ASSERT_EQ(s.point_labels.size(), 757u);
  EXPECT_EQ(s.point_labels.front(), 2);
  ASSERT_EQ(s.triangles.size(), 694u);
  ASSERT_EQ(s.triangle_labels.size(), 694u);
  const std::string copy = temp("sphere_copy.mesh");
  IO::write_MEDIT_soup(copy, s);
  const IO::Tetrahedron_soup t = IO::read_tetrahedron_soup(copy);
  EXPECT_EQ(t.points, s.points);
  EXPECT_EQ(t.cells, s.cells);
  EXPECT_EQ(t.labels, s.labels);
  EXPECT_EQ(t.point_labels, s.point_labels);
  EXPECT_EQ(t.triangles, s.triangles);
  EXPECT_EQ(t.triangle_labels, s.triangle_labels);
}

TEST(Medit, SkipsOtherSectionsAcceptsAnyCaseCommentsAndValuesSplitOverLines)
{
  const IO::Tetrahedron_soup s = read(
    "# written by hand\n"
    "meshversionformatted\n2\n"
    "DIMENSION 3\n"
    "Corners 1 1\n"
    "vertices 5\n"
    "0 0 0 1   1 0 0 1\n"  // two entries on one line
    "0 1\n0\n1\n"          // one entry on three lines
    "0 0 1 1 # a comment\n"
    "\n"
    "0.5 0.5 0.5 3\n"
    "Edges\n2\n1 2 0\n2 3 0\n"
    "Triangles\n1\n1 2 3 4\n"
    "RequiredVertices 2 1 2\n"
    "Ridges 1 1\n"
    "Normals 1 0 0 1\n"
    "NormalAtVertices 1 1 1\n"
    "Quadrilaterals 1 1 2 3 4 0\n"
    "Hexahedra 0\n"
    "AngleOfCornerBound 45\n"
    "TETRAHEDRA\n2\n1 2 3 4 5\n2 3\n4 5 6\n"
    "Prisms 0\n"
    "end\n");
  ASSERT_EQ(s.points.size(), 5u);
  EXPECT_EQ(s.points[2], (std::array<double, 3>{0, 1, 0}));
  EXPECT_EQ(s.points[4], (std::array<double, 3>{0.5, 0.5, 0.5}));
  ASSERT_EQ(s.cells.size(), 2u);
  EXPECT_EQ(s.cells[0], (std::array<std::size_t, 4>{0, 1, 2, 3}));
  EXPECT_EQ(s.cells[1], (std::array<std::size_t, 4>{1, 2, 3, 4}));
  EXPECT_EQ(s.labels, std::vector<int>({5, 6}));
}

TEST(Medit, EndIsOptional)
{
  const IO::Tetrahedron_soup s = read(header + four_vertices + "Tetrahedra 1 1 2 3 4 0\n");
  EXPECT_EQ(s.cells.size(), 1u);
  EXPECT_EQ(s.labels, std::vector<int>({0}));
}

TEST(Medit, RejectsAMissingOrWrongHeader)
{
  EXPECT_REJECTED("", "bad.mesh:0: empty file");
  EXPECT_REJECTED("Dimension 3\n", "bad.mesh:1: not a Medit file");
  EXPECT_REJECTED("MeshVersionFormatted 9\nDimension 3\n", "bad.mesh:1: unsupported MeshVersionFormatted 9");
  EXPECT_REJECTED("MeshVersionFormatted\n", "bad.mesh:1: missing value after MeshVersionFormatted");
  EXPECT_REJECTED("MeshVersionFormatted 1\nDimension 2\nVertices 0\n", "bad.mesh:2: Dimension 2: only 3D");
  EXPECT_REJECTED("MeshVersionFormatted 1\nDimension\n3.5\n", "bad.mesh:3: '3.5' is not an integer");
  EXPECT_REJECTED("MeshVersionFormatted 1\n" + four_vertices, "bad.mesh:2: section Vertices before Dimension");
  EXPECT_REJECTED(header + "Dimension 3\n", "bad.mesh:3: Dimension repeated");
  // Other volume cells: the mesh would be read as its tetrahedra alone.
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 1 1 2 3 4 0\nHexahedra 1\n1 2 3 4 1 2 3 4 0\n",
                  "bad.mesh:10: 1 Hexahedra: only tetrahedral meshes are supported");
}

TEST(Medit, RejectsMissingSections)
{
  EXPECT_REJECTED(header + "End\n", "bad.mesh:3: no Vertices section");
  EXPECT_REJECTED(header + four_vertices + "End\n", "bad.mesh:9: no Tetrahedra section");
  EXPECT_REJECTED(header + four_vertices + "Triangles 1 1 2 3 0\n", "bad.mesh:9: no Tetrahedra section");
  EXPECT_REJECTED(header + four_vertices + four_vertices, "bad.mesh:9: second Vertices section");
}

// Sections come in any order (libMeshb finds them by keyword): tetrahedra before their vertices
// are read as after them (they were refused), their indices checked once the vertices are known.
TEST(Medit, TetrahedraMayComeBeforeTheirVertices)
{
  const IO::Tetrahedron_soup first = read(header + "Tetrahedra 1 1 2 3 4 7\n" + four_vertices),
                             after = read(header + four_vertices + "Tetrahedra 1 1 2 3 4 7\n");
  EXPECT_EQ(first.points, after.points);
  EXPECT_EQ(first.cells, after.cells);
  EXPECT_EQ(first.labels, after.labels);
  EXPECT_REJECTED(header + "Tetrahedra 1 1 2 3 9 0\n" + four_vertices, "tetrahedron 0 has vertex index 9 out of range (1 to 4)");
  EXPECT_REJECTED(header + "Tetrahedra 1 1 2 2 3 0\n" + four_vertices, "bad.mesh:3: tetrahedron 0 repeats vertex 2");
}

TEST(Medit, RejectsTruncatedSections)
{
  // The next keyword comes before the announced entries.
  EXPECT_REJECTED(header + "Vertices\n5\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\nTetrahedra 1 1 2 3 4 0\n",
                  "bad.mesh:9: truncated Vertices section: 5 entries announced, 4 found");
  EXPECT_REJECTED(header + four_vertices + "Triangles\n2\n1 2 3 0\nTetrahedra 1 1 2 3 4 0\n",
                  "bad.mesh:12: truncated Triangles section: 2 entries announced, 1 found");
  // The file ends inside an entry (the count check lets it through: the file could hold it).
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra\n2\n1 2 3 4 0\n01 02 03\n",
                  "bad.mesh:12: truncated Tetrahedra section: 2 entries announced, 1 found");
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra\n", "bad.mesh:9: missing Tetrahedra count");
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra\nEnd\n", "bad.mesh:10: missing Tetrahedra count (found 'End')");
  // Too few entries announced: the extra values are where a keyword should be.
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 1 1 2 3 4 0\n1 2 3 4 0\n",
                  "bad.mesh:10: expected a section keyword, found '1'");
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 1 1 2 3 4 0\nEnd\nVertices 0\n", "bad.mesh:11: 'Vertices' after End");
}

TEST(Medit, RejectsBadCounts)
{
  EXPECT_REJECTED(header + "Vertices\n-4\n", "bad.mesh:4: negative Vertices count -4");
  EXPECT_REJECTED(header + four_vertices + "Edges -1\n", "bad.mesh:9: negative Edges count -1");
  EXPECT_REJECTED(header + "Vertices\nfour\n", "bad.mesh:4: 'four' is not an integer");
  // A corrupt count fails at once, before any allocation (the rest of the file is 24 bytes).
  EXPECT_REJECTED(header + "Vertices\n1000000000000\n0 0 0 1\n1 0 0 1\n0 1 0 1\n",
                  "bad.mesh:4: Vertices count 1000000000000 is more than the rest of the file can hold");
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 9223372036854775807\n1 2 3 4 0\n",
                  "bad.mesh:9: Tetrahedra count 9223372036854775807 is more than the rest of the file can hold");
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 99999999999999999999\n", "bad.mesh:9: integer '99999999999999999999' is out of range");
  EXPECT_REJECTED(header + four_vertices + "Triangles 3\n1 2 3 0\n1 2 4 0\n", "bad.mesh:9: Triangles count 3 is more than");
  // Exactly as many bytes as the entries need is fine.
  EXPECT_EQ(read(header + four_vertices + "Tetrahedra 1 1 2 3 4 0\nCorners 2\n1 2").cells.size(), 1u);
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 1 1 2 3 4 0\nCorners 3\n1 2",
                  "bad.mesh:10: Corners count 3 is more than the rest of the file can hold");
}

TEST(Medit, UnseekableStreamWithAHugeCountFailsAsTruncatedWithoutAllocating)
{
  Unseekable_buffer buffer(header + four_vertices + "Tetrahedra 1000000000000\n1 2 3 4 0\n");
  std::istream in(&buffer);
  try {
    IO::read_MEDIT_soup(in, "pipe");
    ADD_FAILURE() << "no exception";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("pipe:10: truncated Tetrahedra section: 1000000000000 entries announced, 1 found"),
              std::string::npos) << e.what();
  }
  // And a good file reads the same through such a stream.
  Unseekable_buffer good(header + four_vertices + "Tetrahedra 1 1 2 3 4 0\nEnd\n");
  std::istream in2(&good);
  EXPECT_EQ(IO::read_MEDIT_soup(in2, "pipe").cells.size(), 1u);
}

TEST(Medit, RejectsBadValues)
{
  EXPECT_REJECTED(header + "Vertices 1\n0 abc 0 1\n", "bad.mesh:4: 'abc' is not a number");
  EXPECT_REJECTED(header + "Vertices 1\n0 0 inf 1\n", "bad.mesh:4: coordinate 'inf' is not a finite number");
  EXPECT_REJECTED(header + "Vertices 1\nnan 0 0 1\n", "bad.mesh:4: coordinate 'nan' is not a finite number");
  EXPECT_REJECTED(header + "Vertices 1\n0 0\n1e999 1\n", "bad.mesh:5: coordinate '1e999' is not a finite number");
  EXPECT_REJECTED(header + "Vertices 1\n0 0 0 1.5\n", "bad.mesh:4: '1.5' is not an integer");
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 1\n1 2 3 x 0\n", "bad.mesh:10: 'x' is not an integer");
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 1\n1 2 3 4 99999999999\n",
                  "bad.mesh:10: tetrahedron 0 has reference 99999999999 out of range");
  EXPECT_REJECTED(header + four_vertices + "Triangles 1\n1 2 three 0\nTetrahedra 1 1 2 3 4 0\n",
                  "bad.mesh:10: 'three' in Triangles is not a number");
}

TEST(Medit, RejectsIndicesOutOfRangeAndRepeatedVertices)
{
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 1\n0 1 2 3 1\n",
                  "bad.mesh:10: tetrahedron 0 has vertex index 0 out of range (1 to 4)");
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 2\n1 2 3 4 1\n1 2 3 5 1\n",
                  "bad.mesh:11: tetrahedron 1 has vertex index 5 out of range (1 to 4)");
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 1\n1 2 -3 4 1\n", "bad.mesh:10: tetrahedron 0 has vertex index -3 out of range");
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 1\n1 2 3 2 1\n", "bad.mesh:10: tetrahedron 0 repeats vertex 2");
  // Triangles, kept for the output: checked against the vertices once all are read.
  EXPECT_REJECTED(header + four_vertices + "Triangles 1\n1 2 0 7\nTetrahedra 1 1 2 3 4 1\n",
                  "bad.mesh:10: triangle 0 has vertex index 0 out of range");
  EXPECT_REJECTED(header + four_vertices + "Triangles 1\n1 2 9 7\nTetrahedra 1 1 2 3 4 1\nEnd\n",
                  "triangle 0 has vertex index 9 out of range (1 to 4)");
  EXPECT_REJECTED(header + four_vertices + "Triangles 1\n1 2 3 1.5\nTetrahedra 1 1 2 3 4 1\n",
                  "bad.mesh:10: '1.5' is not an integer");
}

TEST(Medit, RejectsSectionsOfUnknownLayout)
{
  EXPECT_REJECTED(header + four_vertices + "SolAtVertices 1 1 1\n0.5\n",
                  "bad.mesh:9: unsupported Medit section 'SolAtVertices' (its layout is unknown)");
  EXPECT_REJECTED(header + four_vertices + "Geometry\nfoo.mesh\n", "bad.mesh:9: unsupported Medit section 'Geometry'");
}

TEST(Medit, ReadTetrahedronSoupChecksTheFile)
{
  EXPECT_THROW(IO::read_tetrahedron_soup(temp("missing.mesh")), DO::Invalid_input);
  EXPECT_THROW(IO::read_tetrahedron_soup(temp("sphere.off")), DO::Invalid_input);
  const std::string path = temp("empty.mesh");
  {
    std::ofstream out(path);
    out << header << four_vertices << "Tetrahedra 0\nEnd\n";
  }
  try {
    IO::read_tetrahedron_soup(path);
    ADD_FAILURE() << "no exception";
  } catch(const DO::Invalid_input& e) {
    EXPECT_EQ(std::string(e.what()), path + ": no tetrahedron");
  }
  {
    std::ofstream out(path);
    out << header << four_vertices << "Tetrahedra 1\n1 2 3 9 1\nEnd\n";
  }
  try {
    IO::read_tetrahedron_soup(path);
    ADD_FAILURE() << "no exception";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":10: tetrahedron 0 has vertex index 9"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

// ---------------------------------------------------------------------------------------------
// VTU
// ---------------------------------------------------------------------------------------------

namespace {

// The whitespace-separated values of the DataArray whose opening tag contains `attribute`.
std::vector<double> data_array(const std::string& xml, const std::string& attribute)
{
  const std::size_t tag = xml.find("<DataArray " + attribute);
  const std::size_t at = xml.find(attribute);
  EXPECT_NE(at, std::string::npos) << attribute;
  if(at == std::string::npos) return {};
  const std::size_t open = xml.rfind("<DataArray", at);
  const std::size_t begin = xml.find('>', at) + 1, end = xml.find("</DataArray>", begin);
  EXPECT_TRUE(tag == std::string::npos || tag == open);
  std::istringstream values(xml.substr(begin, end - begin));
  std::vector<double> v;
  for(double x; values >> x;) v.push_back(x);
  EXPECT_TRUE(values.eof()) << "a value of " << attribute << " is not a number";
  return v;
}

std::size_t occurrences(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

} // namespace

TEST(Vtu, TetrahedraWithCellArrays)
{
  const std::string path = temp("tets.vtu");
  const IO::Tetrahedron_soup s = two_tetrahedra();
  const double inf = std::numeric_limits<double>::infinity();
  IO::write_VTU(path, s.points, s.cells, {{"K", {1.25, inf}}, {"a<b & \"c\"", {-inf, 0.1}}});
  EXPECT_EQ(leftovers(path), 0u);
  const std::string xml = contents(path);

  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"", 0), 0u);
  EXPECT_NE(xml.find("NumberOfPoints=\"5\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfCells=\"2\""), std::string::npos);
  EXPECT_NE(xml.find("<CellData Scalars=\"K\">"), std::string::npos);
  EXPECT_NE(xml.find("Name=\"K\""), std::string::npos);
  EXPECT_NE(xml.find("Name=\"a&lt;b &amp; &quot;c&quot;\""), std::string::npos);
  // Balanced tags, every open DataArray closed.
  EXPECT_EQ(occurrences(xml, "<DataArray"), 6u);
  EXPECT_EQ(occurrences(xml, "</DataArray>"), 6u);
  for(const char* element : {"VTKFile", "UnstructuredGrid", "Piece", "Points", "Cells", "CellData"}) {
    EXPECT_EQ(occurrences(xml, std::string("<") + element + ">") + occurrences(xml, std::string("<") + element + " "), 1u) << element;
    EXPECT_EQ(occurrences(xml, std::string("</") + element + ">"), 1u) << element;
  }

  const std::vector<double> points = data_array(xml, "NumberOfComponents=\"3\"");
  ASSERT_EQ(points.size(), 15u);
  EXPECT_EQ(points[12], 1. / 3); // 17 digits: exact
  EXPECT_EQ(points[14], 0.1 + 0.2);
  EXPECT_EQ(data_array(xml, "Name=\"connectivity\""), std::vector<double>({0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_EQ(data_array(xml, "Name=\"offsets\""), std::vector<double>({4, 8}));
  EXPECT_EQ(data_array(xml, "Name=\"types\""), std::vector<double>({10, 10}));
  EXPECT_EQ(data_array(xml, "Name=\"K\""), std::vector<double>({1.25, 1e308}));
  EXPECT_EQ(data_array(xml, "Name=\"a&lt;b"), std::vector<double>({-1e308, 0.1}));
  EXPECT_EQ(IO::vtu_infinity, 1e308);
  std::remove(path.c_str());
}

TEST(Vtu, PointArraysOfVectors)
{
  const std::string path = temp("displaced.vtu");
  const IO::Tetrahedron_soup s = two_tetrahedra();
  std::vector<std::array<double, 3>> displacement(s.points.size(), {0.5, -1. / 3, 0});
  IO::write_VTU(path, s.points, s.cells, {{"K", {1, 2}}}, {{"displacement", displacement}});
  const std::string xml = contents(path);
  EXPECT_NE(xml.find("<PointData Vectors=\"displacement\">"), std::string::npos);
  const std::vector<double> values = data_array(xml, "Name=\"displacement\"");
  ASSERT_EQ(values.size(), 15u);
  EXPECT_EQ(values[13], -1. / 3);
  EXPECT_EQ(occurrences(xml, "<DataArray"), occurrences(xml, "</DataArray>"));
  displacement[2][1] = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<std::string, std::vector<std::array<double, 3>>>> bad[] = {
    {{"d", displacement}}, {{"d", {{0, 0, 0}}}}, {{"d", std::vector<std::array<double, 3>>(5)}, {"d", std::vector<std::array<double, 3>>(5)}}};
  const std::string messages[] = {path + ": point array 'd' is not finite at point 2", path + ": point array 'd' has 1 values for 5 points",
                                  path + ": point array 'd' given twice"};
  for(int i = 0; i < 3; ++i) {
    std::remove(path.c_str());
    try {
      IO::write_VTU(path, s.points, s.cells, {}, bad[i]);
      ADD_FAILURE() << messages[i];
    } catch(const DO::Invalid_input& e) {
      EXPECT_EQ(e.what(), messages[i]);
    }
    EXPECT_FALSE(exists(path));
  }
}

// Whether `xml` is one element whose tags nest (start, end and empty tags; no text checks): enough
// to catch a writer that forgets to close what it opened.
bool tags_nest(const std::string& xml)
{
  std::vector<std::string> open;
  std::size_t roots = 0;
  for(std::size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    const std::size_t end = xml.find('>', at);
    if(end == std::string::npos) return false;
    const std::string tag = xml.substr(at + 1, end - at - 1);
    if(tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
    if(tag[0] == '/') {
      if(open.empty() || open.back() != tag.substr(1)) return false;
      open.pop_back();
      continue;
    }
    if(open.empty()) ++roots;
    if(tag.back() != '/') open.push_back(tag.substr(0, tag.find_first_of(" \t\n")));
  }
  return open.empty() && roots == 1;
}

// The section of a 3 x 3 x 3 block of cubes (six tetrahedra each) by z = 1.5 covers the 3 x 3
// square once: its polygons' areas add up to 9, each is convex and counter-clockwise.
TEST(Svg, CrossSectionsCoverTheSectionAndPicturesCountTheirCells)
{
  const IO::Tetrahedron_soup block = kuhn_block(3);
  std::vector<double> values(block.cells.size(), 2.);
  values[54] = std::numeric_limits<double>::infinity();   // a tetrahedron of the cube at (0, 0, 1), cut
  const IO::Svg_panel section = IO::cross_section_panel("section", block.points, block.cells, values);
  double area = 0;
  for(const auto& polygon : section.polygons) {
    ASSERT_GE(polygon.size(), 3u);
    ASSERT_LE(polygon.size(), 4u);
    for(std::size_t i = 0; i < polygon.size(); ++i) {
      const auto &a = polygon[i], &b = polygon[(i + 1) % polygon.size()], &c = polygon[(i + 2) % polygon.size()];
      EXPECT_GE((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]), -1e-12);   // convex, counter-clockwise
      area += (a[0] * b[1] - a[1] * b[0]) / 2;
    }
  }
  EXPECT_NEAR(area, 9., 1e-12);
  EXPECT_EQ(section.values.size(), section.polygons.size());
  EXPECT_EQ(std::size_t(std::count(section.values.begin(), section.values.end(), 2.)), section.values.size() - 1);

  // A surface's triangles are drawn on the plane of its two largest extents: here y and z.
  const std::vector<std::array<double, 3>> wall = {{0, 0, 0}, {0.1, 2, 0}, {0, 0, 3}};
  const IO::Svg_panel side = IO::triangle_panel("wall", wall, {{{0, 1, 2}}}, {1.5});
  const std::vector<std::array<double, 2>> expected = {{0, 0}, {2, 0}, {0, 3}};
  EXPECT_EQ(side.polygons.front(), expected);

  const std::string path = temp("section.svg");
  IO::write_SVG(path, {section, side}, "K");
  const std::string svg = contents(path);
  EXPECT_TRUE(tags_nest(svg));
  EXPECT_FALSE(tags_nest("<svg><g><polygon/></svg>"));   // the checker itself
  EXPECT_EQ(occurrences(svg, "<polygon"), section.polygons.size() + 1);
  EXPECT_EQ(occurrences(svg, "fill=\"#d62728\"/>"), 1u);   // the infinite value, in red
  EXPECT_NE(svg.find(">K per cell, linear scale</text>"), std::string::npos);
  EXPECT_NE(svg.find("> 1 inverted or flat"), std::string::npos);
  std::remove(path.c_str());
  for(const auto& bad : {std::vector<IO::Svg_panel>{}, std::vector<IO::Svg_panel>{{"p", {{{0, 0}, {1, 0}, {0, 1}}}, {}}},
                         std::vector<IO::Svg_panel>{{"p", {{{0, 0}, {1, 0}, {0, std::nan("")}}}, {1}}}}) {
    EXPECT_THROW(IO::write_SVG(path, bad, "K"), DO::Invalid_input);
    EXPECT_FALSE(exists(path));
  }
  EXPECT_THROW(IO::write_energy_plot_SVG(path, {}, "E"), DO::Invalid_input);
  EXPECT_FALSE(exists(path));
  // Energies that are not finite (an inverted start, a run stopped before any evaluation) leave gaps.
  const double inf = std::numeric_limits<double>::infinity();
  IO::write_energy_plot_SVG(path, {inf, 2, 1.5, std::nan(""), 1.2}, "E");
  EXPECT_EQ(occurrences(contents(path), "<polyline"), 2u);
  EXPECT_NE(contents(path).find(">2 of 5 energies not finite, not drawn</text>"), std::string::npos);
  EXPECT_TRUE(tags_nest(contents(path)));
  IO::write_energy_plot_SVG(path, {inf}, "E");
  EXPECT_EQ(occurrences(contents(path), "<polyline"), 0u);
  EXPECT_TRUE(tags_nest(contents(path)));
  IO::write_energy_plot_SVG(path, {3, 2, 1.5}, "E <&> \"units\"");
  EXPECT_NE(contents(path).find("<polyline"), std::string::npos);
  EXPECT_TRUE(tags_nest(contents(path)));
  IO::write_energy_plot_SVG(path, {300, 2, 1.5}, "E");   // a log scale
  EXPECT_NE(contents(path).find("(energy on a log scale)"), std::string::npos);
  EXPECT_TRUE(tags_nest(contents(path)));
  std::remove(path.c_str());
}

TEST(Vtu, TrianglesWithoutCellArrays)
{
  const std::string path = temp("triangles.vtu");
  const std::vector<std::array<double, 3>> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const std::vector<std::array<std::size_t, 3>> triangles = {{0, 1, 2}, {1, 3, 2}};
  IO::write_VTU(path, points, triangles);
  const std::string xml = contents(path);
  EXPECT_NE(xml.find("NumberOfPoints=\"4\" NumberOfCells=\"2\""), std::string::npos);
  EXPECT_EQ(data_array(xml, "Name=\"connectivity\""), std::vector<double>({0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(data_array(xml, "Name=\"offsets\""), std::vector<double>({3, 6}));
  EXPECT_EQ(data_array(xml, "Name=\"types\""), std::vector<double>({5, 5}));
  EXPECT_NE(xml.find("<CellData>\n      </CellData>"), std::string::npos);
  std::remove(path.c_str());
}

TEST(Vtu, RejectsBadInputAndWritesNothing)
{
  const std::string path = temp("rejected.vtu");
  std::remove(path.c_str());
  const IO::Tetrahedron_soup s = two_tetrahedra();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto message = [&](const auto& points, const auto& cells, const std::vector<std::pair<std::string, std::vector<double>>>& data) {
    try {
      IO::write_VTU(path, points, cells, data);
    } catch(const DO::Invalid_input& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(s.points, s.cells, {{"K", {1}}}), path + ": cell array 'K' has 1 values for 2 cells");
  EXPECT_EQ(message(s.points, s.cells, {{"K", {1, nan}}}), path + ": cell array 'K' is NaN at cell 1");
  EXPECT_EQ(message(s.points, s.cells, {{"K", {1, 2}}, {"K", {1, 2}}}), path + ": cell array 'K' given twice");
  EXPECT_EQ(message(s.points, s.cells, {{"", {1, 2}}}), path + ": a cell array has an empty name");
  EXPECT_EQ(message(s.points, s.cells, {{"a\nb", {1, 2}}}), path + ": cell array name 'a\nb' has a control character");
  std::vector<std::array<std::size_t, 4>> out_of_range = s.cells;
  out_of_range[1][2] = 5;
  EXPECT_EQ(message(s.points, out_of_range, {}), path + ": tetrahedron 1 has vertex index 5 out of range");
  std::vector<std::array<double, 3>> infinite = s.points;
  infinite[3][0] = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(message(infinite, s.cells, {}), path + ": vertex 3 has a non-finite coordinate");
  const std::vector<std::array<std::size_t, 3>> triangles = {{0, 1, 7}};
  EXPECT_EQ(message(s.points, triangles, {}), path + ": triangle 0 has vertex index 7 out of range");
  EXPECT_FALSE(exists(path));
  EXPECT_EQ(leftovers(path), 0u);
}

// ---------------------------------------------------------------------------------------------
// What the OFF, OBJ and Medit readers share
// ---------------------------------------------------------------------------------------------

namespace {

// The largest single allocation since it was last reset: a count read from a file must not turn
// into a large reserve before it is checked, and a reserve costs no resident memory until it is
// used, so getrusage cannot see it.
std::atomic<std::size_t> largest_allocation{0};

} // namespace

// Replacing the global operator new is allowed and affects only this test binary. The default
// operator delete of libstdc++ and libc++ releases with std::free, so it stays.
void* operator new(std::size_t n)
{
  std::size_t seen = largest_allocation.load(std::memory_order_relaxed);
  while(n > seen && !largest_allocation.compare_exchange_weak(seen, n, std::memory_order_relaxed)) {
  }
  if(void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}

namespace {

using namespace std::string_literals; // for inputs with NUL bytes

long peak_rss_kb()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// An endless stream of NUL bytes, as /dev/zero, that gives up (end of stream) after `limit`
// bytes so that a reader without a line bound fails the test instead of filling the memory.
class Endless_buffer : public std::streambuf
{
public:
  explicit Endless_buffer(std::size_t limit) : limit_(limit), chunk_(4096, '\0') {}
  std::size_t delivered() const { return delivered_; }

protected:
  int_type underflow() override
  {
    if(delivered_ >= limit_) return traits_type::eof();
    delivered_ += chunk_.size();
    setg(&chunk_[0], &chunk_[0], &chunk_[0] + chunk_.size());
    return traits_type::to_int_type(chunk_[0]);
  }

private:
  std::size_t limit_, delivered_ = 0;
  std::string chunk_;
};

const std::string triangle_off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
const std::string triangle_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const std::string tetrahedron_mesh = header + four_vertices + "Tetrahedra 1 1 2 3 4 0\nEnd\n";

} // namespace

TEST(Readers, EndlessLineFailsFastWithBoundedMemory)
{
  // 64 MB without a line break, written a chunk at a time to keep this process small.
  const std::string path = temp("endless_line");
  {
    std::ofstream out(path, std::ios::binary);
    const std::string chunk(1 << 20, '1');
    for(int i = 0; i < 64; ++i) out << chunk;
  }
  const long before = peak_rss_kb();
  for(const std::string format : {"off", "obj", "mesh"}) {
    std::ifstream in(path, std::ios::binary);
    const std::string message = reader_error(in, format, path);
    EXPECT_EQ(message, path + ": line 1 longer than 1048576 bytes") << format << ": " << shown(message);
  }
  EXPECT_LT(peak_rss_kb() - before, 32 * 1024) << "peak resident memory grew by more than 32 MB";
  std::remove(path.c_str());
}

TEST(Readers, EndlessStreamIsReadNoFurtherThanTheLineBound)
{
  // As a link to /dev/zero: the reader stops after the first 1 MiB, whatever follows.
  for(const std::string format : {"off", "obj", "mesh"}) {
    Endless_buffer zeros(std::size_t(16) << 20);
    std::istream in(&zeros);
    EXPECT_EQ(reader_error(in, format, "zero"), "zero: line 1 longer than 1048576 bytes") << format;
    EXPECT_LE(zeros.delivered(), (std::size_t(1) << 20) + 4096) << format;
  }
  // The bound is on a line, not the file, and a line of exactly 1 MiB is fine.
  const std::string comment = "#" + std::string((1 << 20) - 1, 'x');
  EXPECT_EQ(reader_error(comment + "\n" + triangle_off + comment + "\n", "off"), "");
  EXPECT_EQ(reader_error(comment + "x\n" + triangle_off, "off"), "bad.off: line 1 longer than 1048576 bytes");
  EXPECT_EQ(reader_error(triangle_obj + comment + "x\n", "obj"), "bad.obj: line 5 longer than 1048576 bytes");
}

// The manifold check splits the vertices among threads: on a block of 6^3 cubes and on random
// damaged subsets of it (edges and vertices pinched, a cell repeated, a facet shared by three),
// one, two and three threads find the same adjacency and report the same first failure.
TEST(Complexes, ManifoldCheckIsTheSameOnAnyNumberOfThreads)
{
  const IO::Tetrahedron_soup block = kuhn_block(6);
  std::mt19937 random(11);
  std::size_t failures = 0;
  for(int trial = 0; trial < 60; ++trial) {
    const std::vector<std::array<std::size_t, 4>> cells = damaged_cells(block.cells, trial, random);
    std::vector<std::string> messages;
    std::vector<std::vector<std::uint32_t>> adjacencies;
    for(int threads : {1, 2, 3}) {
      std::vector<std::uint32_t> across;
      try {
        DO::internal::check_manifold_tetrahedra(cells, across, DO::internal::Workers(threads));
        messages.push_back("");
      } catch(const DO::Invalid_input& e) {
        messages.push_back(e.what());
      }
      adjacencies.push_back(messages.back().empty() ? across : std::vector<std::uint32_t>());
    }
    EXPECT_EQ(messages[1], messages[0]) << trial;
    EXPECT_EQ(messages[2], messages[0]) << trial;
    EXPECT_EQ(adjacencies[1], adjacencies[0]) << trial;
    EXPECT_EQ(adjacencies[2], adjacencies[0]) << trial;
    if(trial == 0) {
      EXPECT_EQ(messages[0], "");
      EXPECT_EQ(std::count(adjacencies[0].begin(), adjacencies[0].end(), DO::internal::no_tetrahedron), 2 * 6 * 6 * 6) << "boundary facets";
    }
    failures += !messages[0].empty();
  }
  EXPECT_GT(failures, 40u);
}

TEST(Readers, BoundedLinesAcrossTheBufferGrowth)
{
  // The line buffer starts at 4 KiB and doubles: lines about each size it takes, the bound on
  // either side of its last growth, a NUL and a carriage return kept, the last line without a
  // line break, and empty lines.
  const std::size_t bound = 20000;
  std::string text;
  std::vector<std::string> lines;
  for(std::size_t length : {0, 1, 4094, 4095, 4096, 4097, 8191, 8192, 8193, 16385, 19999, 20000, 0, 3}) {
    std::string line(length, 'a');
    for(std::size_t i = 0; i < length; ++i) line[i] = static_cast<char>('a' + i % 26);
    if(length == 3) line = "x\0\r"s;
    lines.push_back(line);
    text += line + (length == 3 ? "" : "\n");
  }
  std::istringstream in(text);
  std::string buffer;
  std::size_t length = 0;
  for(const std::string& expected : lines) {
    ASSERT_EQ(IO::internal::read_bounded_line(in, buffer, length, bound), IO::internal::Line_status::line) << expected.size();
    EXPECT_EQ(std::string(buffer.data(), length), expected) << expected.size();
  }
  EXPECT_EQ(IO::internal::read_bounded_line(in, buffer, length, bound), IO::internal::Line_status::end_of_stream);
  EXPECT_TRUE(in.fail());
  for(std::size_t length_over : {bound + 1, 2 * bound}) {
    std::istringstream over(std::string(length_over, 'b') + "\nnext\n");
    EXPECT_EQ(IO::internal::read_bounded_line(over, buffer, length, bound), IO::internal::Line_status::too_long);
    EXPECT_LE(buffer.size(), bound + 1);
  }
}

TEST(Readers, HeaderCountsReserveNoMoreThanTheInputCanHold)
{
  // 23 bytes announcing 16.7M vertices: the reader must find the file truncated without
  // reserving room for them.
  const std::string path = temp("reserve_bomb.off");
  std::ofstream(path, std::ios::binary) << "OFF\n16777216 1 0\n0 0 0\n";
  largest_allocation = 0;
  try {
    IO::read_triangle_soup(path);
    ADD_FAILURE() << "no exception";
  } catch(const DO::Invalid_input& e) {
    EXPECT_EQ(std::string(e.what()), path + ":3: truncated: 16777216 vertices announced, 1 found");
  }
  EXPECT_LT(largest_allocation.load(), std::size_t(1) << 20);
  std::remove(path.c_str());

  // Through streams that cannot tell their size (pipes), OFF faces and Medit sections alike.
  const std::pair<std::string, std::string> inputs[] = {
    {"off", "OFF\n3 16777216 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"}, {"mesh", header + "Vertices 16777216\n0 0 0 1\n"}};
  for(const auto& input : inputs) {
    Unseekable_buffer buffer(input.second);
    std::istream in(&buffer);
    largest_allocation = 0;
    const std::string message = reader_error(in, input.first, "pipe");
    EXPECT_NE(message.find("16777216"), std::string::npos) << message;
    EXPECT_NE(message.find(" announced, 1 found"), std::string::npos) << message;
    EXPECT_LT(largest_allocation.load(), std::size_t(1) << 20) << input.first;
  }
}

TEST(Off, RejectsAFaceBeyondTheCount)
{
  const std::string fewer = "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n";
  EXPECT_EQ(reader_error(fewer, "off"), "bad.off:11: '3' after the 3 faces the header announces");
}

TEST(Readers, RejectBytesAfterANul)
{
  // The bytes after a NUL were ignored: "0.5\0garbage" read as 0.5, "5\077" as 5.
  EXPECT_READER_REJECTED("off", "OFF\n3 1 0\n0 0 0\n0.5\0garbage 0 0\n0 1 0\n3 0 1 2\n"s,
                         "bad.off:4: '0.5\\x00garbage' is not a number");
  EXPECT_READER_REJECTED("off", "OFF\n3\0" "77 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"s, "bad.off:2: '3\\x0077' is not an integer");
  EXPECT_READER_REJECTED("off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\0 9\n"s, "bad.off:6: '2\\x00' is not an integer");
  EXPECT_READER_REJECTED("obj", "v 0 0 0\nv 1 0 0\0junk\nv 0 1 0\nf 1 2 3\n"s, "bad.obj:2: '0\\x00junk' is not a number");
  EXPECT_READER_REJECTED("obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\0\n"s, "bad.obj:4: '3\\x00' is not an integer");
  EXPECT_READER_REJECTED("obj", "v 0 0 0\nv\0 1 0 0\n"s, "bad.obj:2: 'v\\x00' is not an OBJ statement");
  EXPECT_READER_REJECTED("mesh", header + "Vertices 1\n0 0 0\0x 1\n"s, "bad.mesh:4: '0\\x00x' is not a number");
  EXPECT_READER_REJECTED("mesh", header + four_vertices + "Triangles 1\n1 2 3\0 0\nTetrahedra 1 1 2 3 4 0\n"s,
                         "bad.mesh:10: '3\\x00' in Triangles is not a number");
}

TEST(Readers, RejectTrailingGarbage)
{
  EXPECT_READER_REJECTED("off", triangle_off + "garbage\n", "bad.off:7: 'garbage' after the 1 faces the header announces");
  EXPECT_READER_REJECTED("off", triangle_off + "3 0 1 2\n", "bad.off:7: '3' after the 1 faces");
  EXPECT_READER_REJECTED("off", "OFF\n3 1 0\n0 0 0 junk\n1 0 0\n0 1 0\n3 0 1 2\n", "bad.off:3: 'junk' is not a number");
  EXPECT_READER_REJECTED("off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 red\n", "bad.off:6: 'red' is not a number");
  EXPECT_READER_REJECTED("obj", triangle_obj + "garbage 1 2\n", "bad.obj:5: 'garbage' is not an OBJ statement");
  EXPECT_READER_REJECTED("obj", "v 0 0 0 1 junk\n", "bad.obj:1: 'junk' is not a number");
  EXPECT_READER_REJECTED("obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n", "bad.obj:4: 'x' is not an integer");
  EXPECT_READER_REJECTED("obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", "bad.obj:4: face vertex '1/1/1/1' has more than three parts");
  EXPECT_READER_REJECTED("obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//99 3//1\n", "bad.obj:5: face 0 has normal index 2//99 out of range");
  EXPECT_READER_REJECTED("obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//0 2 3\n", "bad.obj:4: face vertex '1//0' has normal index 0 (OBJ counts from 1)");
  EXPECT_READER_REJECTED("mesh", tetrahedron_mesh + "garbage\n", "bad.mesh:11: 'garbage' after End");
  EXPECT_READER_REJECTED("mesh", header + four_vertices + "Tetrahedra 1 1 2 3 4 0\ngarbage\n",
                         "bad.mesh:10: unsupported Medit section 'garbage'");
  // What the formats allow after the required values stays accepted: colors, w, the other
  // statements of OBJ, texture and normal indices.
  EXPECT_EQ(reader_error("OFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0\n0 1 0\n3 0 1 2 0.5 0.5 0.5\n", "off"), "");
  EXPECT_EQ(reader_error("mtllib a.mtl\no x\nv 0 0 0 1\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\ng g\ns off\nusemtl m\n"
                         "f 1/1/1 2//1 -1/1\nl 1 2\n", "obj"), "");
}

TEST(Off, RejectsACountLineWithTheWrongNumberOfFields)
{
  EXPECT_READER_REJECTED("off", "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "bad.off:2: expected 3 counts (vertices, faces, edges), found 2");
  EXPECT_READER_REJECTED("off", "OFF\n3 1 0 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "bad.off:2: expected 3 counts (vertices, faces, edges), found 4");
  EXPECT_READER_REJECTED("off", "OFF 3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "bad.off:1: expected 3 counts (vertices, faces, edges), found 2");
  EXPECT_READER_REJECTED("off", "OFF 3 1 0 x\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "bad.off:1: expected 3 counts");
  EXPECT_READER_REJECTED("off", "OFF\n3 1 x\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "bad.off:2: 'x' is not an integer");
  EXPECT_READER_REJECTED("off", "OFF\n3\n", "bad.off:2: missing vertex and face counts");
  // Both layouts of a correct header.
  EXPECT_EQ(reader_error("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "off"), "");
  EXPECT_EQ(reader_error(triangle_off, "off"), "");
}

// The variants with values after x y z on the vertex lines (CGAL's demo data has COFF files):
// read as OFF. Homogeneous or n-dimensional coordinates are refused.
TEST(Off, ReadsTheVariantsWithColoursNormalsOrTextures)
{
  for(const std::string header : {"COFF", "NOFF", "CNOFF", "STOFF", "STCNOFF"}) {
    std::istringstream in(header + "\n3 1 0\n0 0 0 0.1 0.2 0.3 1\n1 0 0 0.1 0.2 0.3 1\n0 1 0.5 0.1 0.2 0.3 1\n3 0 1 2\n");
    const IO::Triangle_soup soup = IO::read_OFF(in);
    ASSERT_EQ(soup.points.size(), 3u) << header;
    EXPECT_EQ(soup.points[2], (std::array<double, 3>{0, 1, 0.5})) << header;
    EXPECT_EQ(soup.cells.size(), 1u) << header;
  }
  EXPECT_READER_REJECTED("off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n", "bad.off:1: '4OFF' is not supported");
  EXPECT_READER_REJECTED("off", "nOFF\n3\n3 1 0\n", "bad.off:1: 'nOFF' is not supported");
  EXPECT_READER_REJECTED("off", "CSTOFF\n3 1 0\n", "bad.off:1: 'CSTOFF' is not supported");
}

TEST(Readers, SkipAUtf8ByteOrderMark)
{
  const std::string bom = "\xEF\xBB\xBF";
  std::istringstream off(bom + triangle_off), obj(bom + triangle_obj), mesh(bom + tetrahedron_mesh);
  const IO::Triangle_soup from_off = IO::read_OFF(off), from_obj = IO::read_OBJ(obj);
  EXPECT_EQ(from_off.points.size(), 3u);
  ASSERT_EQ(from_obj.points.size(), 3u); // the first vertex was dropped
  EXPECT_EQ(from_obj.points, from_off.points);
  EXPECT_EQ(from_obj.cells, from_off.cells);
  EXPECT_EQ(IO::read_MEDIT_soup(mesh).cells.size(), 1u);
  // Only at the start of the file.
  EXPECT_READER_REJECTED("obj", triangle_obj + bom + "v 0 0 0\n", "bad.obj:5: '\xEF\xBB\xBFv' is not an OBJ statement");
}

TEST(Readers, EscapeControlBytesInMessages)
{
  // A terminal title and color change where the counts should be.
  const std::string message = reader_error("OFF\n\x1b]0;PWNED\a\x1b[31mRED 1 0\n", "off");
  EXPECT_EQ(message, "bad.off:2: '\\x1b]0;PWNED\\x07\\x1b[31mRED' is not an integer");
  for(char c : message) EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 || c == 0x7f) << shown(message);
  // C1 controls (CSI is U+009B) and bytes that are not UTF-8 too; the rest of UTF-8 is kept.
  EXPECT_READER_REJECTED("obj", "v 0 0 \xC2\x9B" "31m\n", "bad.obj:1: '\\xc2\\x9b31m' is not a number");
  EXPECT_READER_REJECTED("obj", "v 0 0 \xFF\x7F\n", "bad.obj:1: '\\xff\\x7f' is not a number");
  EXPECT_READER_REJECTED("obj", "v 0 0 \xC3\xA9t\xC3\xA9\n", "bad.obj:1: '\xC3\xA9t\xC3\xA9' is not a number");
  EXPECT_READER_REJECTED("mesh", header + "Vertices\x1b[2J 1\n", "bad.mesh:3: unsupported Medit section 'Vertices\\x1b[2J'");
  // The file name too.
  std::istringstream in("OFF\n1 x 0\n");
  EXPECT_EQ(reader_error(in, "off", "a\rb.off"), "a\\x0db.off:2: 'x' is not an integer");
}

TEST(Readers, AcceptSubnormalCoordinates)
{
  // strtod reports ERANGE for them, yet they are exact doubles (the writers produce them).
  std::istringstream off("OFF\n3 1 0\n0 0 1e-320\n1 0 0\n0 1 0\n3 0 1 2\n"), obj("v 0 0 1e-320\nv 1 0 0\nv 0 1 -4.9e-324\nf 1 2 3\n"),
    mesh(header + "Vertices\n4\n0 0 1e-320 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\nTetrahedra 1 1 2 3 4 0\n");
  EXPECT_EQ(IO::read_OFF(off).points[0][2], 1e-320);
  const IO::Triangle_soup from_obj = IO::read_OBJ(obj);
  EXPECT_EQ(from_obj.points[0][2], 1e-320);
  EXPECT_EQ(from_obj.points[2][2], -std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(IO::read_MEDIT_soup(mesh).points[0][2], 1e-320);
  // Below the smallest subnormal a coordinate rounds to zero; above the largest double it is refused.
  EXPECT_READER_REJECTED("off", "OFF\n3 1 0\n0 0 1e400\n1 0 0\n0 1 0\n3 0 1 2\n", "bad.off:3: coordinate '1e400' is not a finite number");

  // What the writers produce, the readers take back, bit for bit.
  IO::Triangle_soup triangles;
  triangles.points = {{0, 0, 1e-320}, {1, 0, 0}, {0, 1, std::numeric_limits<double>::denorm_min()}};
  triangles.cells = {{0, 1, 2}};
  for(const std::string name : {"subnormal.off", "subnormal.obj"}) {
    const std::string path = temp(name);
    IO::write_triangle_soup(path, triangles);
    EXPECT_EQ(IO::read_triangle_soup(path).points, triangles.points) << name;
    std::remove(path.c_str());
  }
  IO::Tetrahedron_soup tetrahedra = two_tetrahedra();
  tetrahedra.points[4][2] = 2.5e-315;
  const std::string path = temp("subnormal.mesh");
  IO::write_MEDIT_soup(path, tetrahedra);
  EXPECT_EQ(IO::read_tetrahedron_soup(path).points, tetrahedra.points);
  std::remove(path.c_str());
}

// Texture coordinates: kept per face corner by read_OBJ, written back by write_triangle_soup, and
// made one per vertex where the file has no seam.
TEST(Obj, TextureCoordinatesRoundTripAndSeamsAreRefused)
{
  namespace IO = CGAL::Distortion_optimization::IO;
  std::istringstream in("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 0.25 0\nvt 0.25 0.5\nvt 0 0.5\n"
                        "f 1/1 2/2 3/3\nf -4/-4 -2/-2 -1/-1\n");
  IO::Triangle_soup soup = IO::read_OBJ(in, "uv.obj");
  ASSERT_EQ(soup.texture_coordinates.size(), 4u);
  const std::vector<std::array<std::size_t, 3>> corners = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_EQ(soup.cell_texture_indices, corners);
  const std::vector<std::array<double, 2>> uv = IO::per_vertex_texture_coordinates(soup, "uv.obj");
  const std::vector<std::array<double, 2>> expected = {{0, 0}, {0.25, 0}, {0.25, 0.5}, {0, 0.5}};
  EXPECT_EQ(uv, expected);

  const std::string path = temp("uv.obj");
  IO::write_triangle_soup(path, soup);
  const IO::Triangle_soup back = IO::read_triangle_soup(path);
  EXPECT_EQ(back.points, soup.points);
  EXPECT_EQ(back.texture_coordinates, soup.texture_coordinates);
  EXPECT_EQ(back.cell_texture_indices, soup.cell_texture_indices);
  EXPECT_THROW(IO::write_triangle_soup(temp("uv.off"), soup), CGAL::Distortion_optimization::Invalid_input);

  // A file without texture: none kept; a seam and a face vertex without one are refused.
  std::istringstream plain("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_TRUE(IO::per_vertex_texture_coordinates(IO::read_OBJ(plain, "plain.obj"), "plain.obj").empty());
  soup.cell_texture_indices[1][0] = 2;   // vertex 0 has (0, 0) in face 0 and (0.25, 0.5) in face 1
  EXPECT_THROW(IO::per_vertex_texture_coordinates(soup, "seam.obj"), CGAL::Distortion_optimization::Invalid_input);
  std::istringstream mixed("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2 3/1\n");
  EXPECT_THROW(IO::per_vertex_texture_coordinates(IO::read_OBJ(mixed, "mixed.obj"), "mixed.obj"),
               CGAL::Distortion_optimization::Invalid_input);
}

// What read_triangle_soup() says of `text` written to a file named `name` (the extension picks
// the reader): its message without the path, or "no error".
std::string soup_file_message(const std::string& name, const std::string& text)
{
  const std::string path = temp(name);
  std::ofstream(path, std::ios::binary) << text;
  try {
    IO::read_triangle_soup(path);
  } catch(const DO::Invalid_input& e) {
    const std::string what = e.what();
    return what.substr(0, path.size()) == path ? what.substr(path.size()) : what;
  }
  return std::string("no error");
}

// PLY, STL and GOCAD go through CGAL's readers, then through the checks of the package's own.
TEST(Readers, PlyAndStlThroughCGALAreCheckedAsStrictly)
{
  const std::string data = DISTORTION_OPTIMIZATION_DATA_DIR;
  const IO::Triangle_soup ply = IO::read_triangle_soup(data + "/sphere.ply"), stl = IO::read_triangle_soup(data + "/sphere.stl");
  EXPECT_EQ(ply.points.size(), 162u);
  EXPECT_EQ(ply.cells.size(), 320u);
  EXPECT_EQ(stl.points.size(), 162u);   // an STL lists corners: equal points are one vertex
  EXPECT_EQ(stl.cells.size(), 320u);
  const IO::Triangle_soup pig = IO::read_triangle_soup(data + "/pig.stl");
  EXPECT_EQ(pig.cells.size(), 16848u);
  std::vector<bool> used(pig.points.size(), false);
  for(const auto& t : pig.cells)
    for(std::size_t v : t) used[v] = true;
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);

  const auto message = soup_file_message;
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string points = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  EXPECT_EQ(message("quad.ply", header + points + "4 0 1 2 3\n"), ": face 0 is not a triangle (4 vertices)");
  EXPECT_EQ(message("repeat.ply", header + points + "3 0 1 1\n"), ": face 0 repeats a vertex");
  EXPECT_EQ(message("range.ply", header + points + "3 0 1 9\n"), ": face 0 has vertex index 9 out of range");
  // A NaN cannot be written in ASCII PLY (CGAL's reader refuses the token) but can in binary.
  std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                       "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float coordinates[9] = {0, 0, std::numeric_limits<float>::quiet_NaN(), 1, 0, 0, 0, 1, 0};
  const unsigned char corners = 3;
  const std::int32_t face[3] = {0, 1, 2};
  binary.append(reinterpret_cast<const char*>(coordinates), sizeof coordinates);   // x86: little-endian
  binary.append(reinterpret_cast<const char*>(&corners), 1);
  binary.append(reinterpret_cast<const char*>(face), sizeof face);
  EXPECT_EQ(message("nan.ply", binary), ": vertex 0 has a non-finite coordinate");
  EXPECT_EQ(message("nan_text.ply", header + "0 0 nan\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n"),
            ": vertex 0 has 'nan' for z, not a number of type float");
  EXPECT_EQ(message("ok.ply", header + points + "3 0 1 2\n"), "no error");
  EXPECT_EQ(message("negative.ply", header + points + "3 0 1 -1\n"), ": face 0 has vertex index -1 out of range");
  // What CGAL's readers ignore: lines after the elements a header announces, or after the last END.
  EXPECT_EQ(message("more.ply", header + points + "3 0 1 2\n3 0 2 3\n"), ":15: content after the 5 elements the header announces");
  EXPECT_EQ(message("trailing.ply", header + points + "3 0 1 2\n\nthis is garbage\n"),
            ":16: content after the 5 elements the header announces");
  EXPECT_EQ(message("blank.ply", header + points + "3 0 1 2\n\n  \n"), "no error");
  // Headers that crash CGAL's reader, and one without x that it reads as flat.
  EXPECT_EQ(message("property_only.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n"),
            ":3: a property declared before any element");
  EXPECT_EQ(message("before_element.ply", "ply\nformat ascii 1.0\nproperty float x\n" + header.substr(header.find("element")) +
                                            points + "3 0 1 2\n"),
            ":3: a property declared before any element");
  std::string list_x = header;
  list_x.replace(list_x.find("property float x"), 16, "property list uchar float x");
  EXPECT_EQ(message("list_x.ply", list_x + "1 0 0 0\n1 1 0 0\n1 1 1 0\n1 0 1 0\n3 0 1 2\n"),
            ":4: the vertex coordinate x is declared as a list");
  std::string unknown = header, unknown_count = header;   // types CGAL's reader skips, misreading the rest
  unknown.replace(unknown.find("property float y"), 16, "property float16 y");
  unknown_count.replace(unknown_count.find("list uchar int"), 14, "list byte int");
  EXPECT_EQ(message("unknown.ply", unknown + points + "3 0 1 2\n"), ":5: a property of type float16, which is no PLY type");
  EXPECT_EQ(message("unknown_count.ply", unknown_count + points + "3 0 1 2\n"),
            ":8: a property of type byte, which is no PLY type");
  // What CGAL's reader took as a count it could not read (an uninitialized one, then room for that
  // many entries: gigabytes), or read from where no header ends (fuzzing, issue 66).
  std::string misspelt = header, float_count = header;
  misspelt.replace(misspelt.find("format"), 6, "ftrmat");
  float_count.replace(float_count.find("list uchar int"), 14, "list float int");
  EXPECT_EQ(message("misspelt.ply", misspelt + points + "3 0 1 2\n"),
            ":2: not the format line (format ascii, binary_little_endian or binary_big_endian, then a version)");
  EXPECT_EQ(message("no_end.ply", header.substr(0, header.find("end_header")) + points + "3 0 1 2\n"),
            ": the header has no end_header line");
  EXPECT_EQ(message("float_count.ply", float_count + points + "3 0 1 2\n"), ":8: a list counted by a float (a count is an integer)");
  EXPECT_EQ(message("ends.ply", header + points), ": the file ends before the 5 elements the header announces");
  EXPECT_EQ(message("letter_count.ply", header + points + "x 0 1 2\n"), ": face 0 has 'x' for the count of vertex_indices, not a number of type uchar");
  std::string no_x = header;
  no_x.erase(no_x.find("property float x\n"), 17);
  EXPECT_EQ(message("no_x.ply", no_x + "0 0\n0 0\n1 0\n1 0\n3 0 1 2\n"), ": the vertices have no property x");
  // List counts longer than the file, which CGAL's reader makes room for (gigabytes from a small
  // file), or negative; a coordinate too large for the computations.
  std::string uint_count = header;
  uint_count.replace(uint_count.find("list uchar int"), 14, "list uint int");
  EXPECT_EQ(message("huge_count.ply", uint_count + points + "4294967280 0 1 2\n"),
            ": face 0 has a list of 4294967280 entries, more than the file holds");
  EXPECT_EQ(message("negative_count.ply", header + points + "-5 0 1 2\n"), ": face 0 has a list of -5 entries");
  std::string minus_five = header, beyond = header;
  minus_five.replace(minus_five.find("vertex 4"), 8, "vertex -5");
  beyond.replace(beyond.find("vertex 4"), 8, "vertex 18446744073709551621");
  EXPECT_EQ(message("minus_five.ply", minus_five + points + "3 0 1 2\n"),
            ":3: element vertex has the count '-5', not a number of elements");
  EXPECT_EQ(message("beyond.ply", beyond + points + "3 0 1 2\n"),
            ":3: element vertex announces 18446744073709551621 instances, more than the file holds");
  std::string huge_binary = binary.substr(0, binary.find("end_header\n") + 11);
  huge_binary.replace(huge_binary.find("list uchar int"), 14, "list uint int");
  const float flat[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::uint32_t huge = 0xFFFFFFF0u;
  huge_binary.append(reinterpret_cast<const char*>(flat), sizeof flat);
  huge_binary.append(reinterpret_cast<const char*>(&huge), sizeof huge);
  huge_binary.append(reinterpret_cast<const char*>(face), sizeof face);
  EXPECT_EQ(message("huge_count_binary.ply", huge_binary), ": face 0 has a list of 4294967280 entries, more than the file holds");
  std::string signed_count = binary.substr(0, binary.find("end_header\n") + 11);   // a count of -5 in a char
  signed_count.replace(signed_count.find("list uchar int"), 14, "list char int");
  signed_count.append(reinterpret_cast<const char*>(flat), sizeof flat);
  signed_count += '\xfb';
  signed_count.append(reinterpret_cast<const char*>(face), sizeof face);
  EXPECT_EQ(message("signed_count.ply", signed_count), ": face 0 has a list of -5 entries");
  EXPECT_EQ(message("cut.ply", signed_count.substr(0, signed_count.size() - 13)),
            ": the file ends before the 4 elements the header announces");
  std::string doubles = header;
  for(std::size_t at; (at = doubles.find("float")) != std::string::npos;) doubles.replace(at, 5, "double");
  EXPECT_EQ(message("far.ply", doubles + "0 0 1e300\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n"),
            ": vertex 0 has a coordinate of magnitude beyond 1e100 (1e+300)");
  const std::string ts = "GOCAD TSurf 1\nHEADER {\nname:t\n}\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\nEND\n";
  EXPECT_EQ(message("ok.ts", ts), "no error");
  EXPECT_EQ(message("garbage.ts", ts + "garbage here\n"), ":11: content after the last surface's END");
  std::string four = ts;
  four.replace(four.find("TRGL 1 2 3"), 10, "TRGL 1 2 3 4");
  EXPECT_EQ(message("four.ts", four), ":9: TRGL with 4 indices (a triangle has 3)");
  EXPECT_EQ(message("dots.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 1.0.0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                                "endloop\nendfacet\nendsolid s\n"),
            ": facet 0 has the coordinate '1.0.0', not a number");
  std::string crlf;
  for(char c : ts) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_EQ(message("crlf.ts", crlf), "no error");   // Windows line ends
  // A NaN corner of an STL file would be merged with any other (it compares equal to every point).
  const float corner_values[12] = {0, 0, 1, 0, 0, 0, 1, 0, std::numeric_limits<float>::quiet_NaN(), 0, 1, 0};
  std::string nan_stl(80, ' ');
  const std::uint32_t one = 1;
  const std::uint16_t attributes = 0;
  nan_stl.append(reinterpret_cast<const char*>(&one), sizeof one);
  nan_stl.append(reinterpret_cast<const char*>(corner_values), sizeof corner_values);
  nan_stl.append(reinterpret_cast<const char*>(&attributes), sizeof attributes);
  EXPECT_EQ(message("nan.stl", nan_stl), ": facet 0 has a non-finite coordinate");
  EXPECT_EQ(message("nan_text.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 nan\nvertex 0 1 0\n"
                                    "endloop\nendfacet\nendsolid s\n"),
            ": facet 0 has a non-finite coordinate 'nan'");
  EXPECT_EQ(message("garbage.stl", "this is not an STL file\n").substr(0, 1), ":");
  EXPECT_EQ(message("empty.ts", ""), ": CGAL's TS reader could not read the file");
  EXPECT_EQ(message("x.vtp", "whatever"), ": unsupported extension (use .off, .obj, .ply, .stl or .ts)");
}

// What other writers produce and the formats allow: an OFF keyword in lower case, OBJ statements
// continued over lines, an ASCII STL in capitals. Each is read as its plain form.
TEST(Readers, LowerCaseOffContinuedObjLinesAndCapitalStl)
{
  for(const std::string text : {"off\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "COff 3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n"}) {
    std::istringstream in(text), plain(triangle_off);
    const IO::Triangle_soup soup = IO::read_OFF(in), expected = IO::read_OFF(plain);
    EXPECT_EQ(soup.points, expected.points) << text;
    EXPECT_EQ(soup.cells, expected.cells) << text;
  }
  EXPECT_READER_REJECTED("off", "offf 3 1 0\n", "bad.off:1: expected 3 counts (vertices, faces, edges), found 4");

  std::istringstream continued("v 0 0 \\\n 0\nv 1 0 0\nv 0 1\\\n0 # a comment\nf 1 \\\n\\\n2 3\n"), plain(triangle_obj);
  const IO::Triangle_soup soup = IO::read_OBJ(continued), expected = IO::read_OBJ(plain);
  EXPECT_EQ(soup.points, expected.points);
  EXPECT_EQ(soup.cells, expected.cells);
  EXPECT_READER_REJECTED("obj", triangle_obj + "f 1 2 \\\n", "bad.obj:5: a line continued ('\\' at its end) by no other line");

  const std::string facets = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  std::string capitals = "SOLID PART\n" + facets + "ENDSOLID PART\n";
  for(char& c : capitals) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  EXPECT_EQ(soup_file_message("capitals.stl", capitals), "no error");
  const std::string path = temp("capitals.stl");
  std::ofstream(path, std::ios::binary) << capitals;
  const IO::Triangle_soup stl = IO::read_triangle_soup(path);
  std::remove(path.c_str());
  EXPECT_EQ(stl.points, expected.points);
  EXPECT_EQ(stl.cells.size(), 1u);
  // Still strict: content after the first ENDSOLID.
  EXPECT_EQ(soup_file_message("capitals2.stl", capitals + "SOLID B\n"), ":10: content after endsolid");
}

// What CGAL's readers take without a word, each of which dropped or misplaced triangles: a binary
// PLY or STL longer than its header announces (the extra faces were dropped), text after an ASCII
// STL's endsolid, GOCAD vertex ids out of order (CGAL numbers vertices as they come, so triangles
// were joined to other vertices) or vertices repeated by ATOM; and face indices CGAL cannot read,
// which it told on std::cerr only.
TEST(Readers, FilesHoldExactlyWhatTheirHeadersAnnounce)
{
  const auto message = soup_file_message;
  const auto bytes = [](const auto& values) { return std::string(reinterpret_cast<const char*>(&values), sizeof values); };
  // Two triangles of a square, binary little-endian (x86's own order), with its faces announced.
  const auto binary_ply = [&](int announced, const std::string& index_type) {
    std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                      "property float z\nproperty uchar red\nelement face " + std::to_string(announced) +
                      "\nproperty list uchar " + index_type + " vertex_indices\nend_header\n";
    for(const auto& p : std::vector<std::array<float, 3>>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})
      ply += bytes(p) + std::string(1, '\x7f');
    for(const auto& f : std::vector<std::array<std::int32_t, 3>>{{0, 1, 2}, {0, 2, 3}}) ply += std::string(1, '\3') + bytes(f);
    return ply;
  };
  EXPECT_EQ(message("two.ply", binary_ply(2, "int")), "no error");
  EXPECT_EQ(message("space.ply", binary_ply(2, "int") + "\n"), "no error");
  EXPECT_EQ(message("fewer.ply", binary_ply(1, "int")), ": content after the 5 elements the header announces (byte 253 of 266)");
  EXPECT_EQ(message("short.ply", binary_ply(2, "ushort")), ": face vertex indices of type ushort (CGAL's PLY reader takes int or uint)");
  std::string unnamed = binary_ply(2, "int");
  unnamed.replace(unnamed.find("vertex_indices"), 14, "corners");
  EXPECT_EQ(message("unnamed.ply", unnamed), ": the faces have no list property vertex_indices (or vertex_index)");

  std::string stl(80, ' ');
  stl += bytes(std::uint32_t(1));
  stl += bytes(std::array<float, 12>{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}) + bytes(std::uint16_t(0));
  EXPECT_EQ(message("one.stl", stl), "no error");
  EXPECT_EQ(message("longer.stl", stl + stl.substr(84)),
            ": neither ASCII STL nor binary STL: the header announces 1 facets (134 bytes), the file has 184 bytes");
  const std::string text = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
                           "endsolid s\n";
  EXPECT_EQ(message("text.stl", text), "no error");
  EXPECT_EQ(message("second.stl", text + text), ":10: content after endsolid");
  EXPECT_EQ(message("last.stl", text + "\n  x"), ":11: content after endsolid");   // at the end: read out of bounds (fuzzing)

  const std::string ts = "GOCAD TSurf 1\nHEADER {\nname:t\n}\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\nEND\n";
  std::string swapped = ts;
  swapped.replace(swapped.find("VRTX 2 1 0 0\nVRTX 3 0 1 0"), 25, "VRTX 3 0 1 0\nVRTX 2 1 0 0");
  EXPECT_EQ(message("swapped.ts", swapped), ":7: vertex id 3 where 2 was expected (the ids must follow each other, as they are numbered in order)");
  std::string atom = ts;
  atom.replace(atom.find("TRGL"), 0, "ATOM 4 1\n");
  EXPECT_EQ(message("atom.ts", atom), ":9: ATOM (a vertex repeated by id) is not supported");
  std::string zero = ts;
  for(const char* id : {"VRTX 1", "VRTX 2", "VRTX 3"}) zero.replace(zero.find(id) + 5, 1, std::string(1, id[5] - 1));
  zero.replace(zero.find("TRGL 1 2 3"), 10, "TRGL 0 1 2");
  EXPECT_EQ(message("zero.ts", zero), "no error");   // ids from 0 are as good as from 1
}

TEST(TetGen, ReadsBothBasesQuadraticCellsAndRefusesMalformedPairs)
{
  const auto read = [](const std::string& node, const std::string& ele) {
    std::istringstream n(node), e(ele);
    return IO::read_TetGen(n, e, "n", "e");
  };
  const std::string node0 = "# TetGen\n5 3 1 1\n0 0 0 0 7 1\n1 1 0 0 7 1\n2 0 1 0 7 1\n3 0 0 1 7 1\n4 1 1 1 7 0\n";
  const IO::Tetrahedron_soup soup = read(node0, "2 4 1\n0 0 1 2 3 5\n1 1 2 3 4 -2\n");
  EXPECT_EQ(soup.points.size(), 5u);
  EXPECT_EQ(soup.points[4], (std::array<double, 3>{1, 1, 1}));
  EXPECT_EQ(soup.cells, (std::vector<std::array<std::size_t, 4>>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
  EXPECT_EQ(soup.labels, (std::vector<int>{5, -2}));
  const std::string node1 = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  const IO::Tetrahedron_soup quadratic = read(node1, "1 10 0\n1 1 2 3 4 1 2 3 4 1 2\n");
  EXPECT_EQ(quadratic.cells, (std::vector<std::array<std::size_t, 4>>{{0, 1, 2, 3}}));
  EXPECT_TRUE(quadratic.labels.empty());

  const auto message = [&](const std::string& node, const std::string& ele) {
    try {
      read(node, ele);
    } catch(const DO::Invalid_input& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string ele1 = "1 4 0\n1 1 2 3 4\n";
  EXPECT_EQ(message("4 2 0 0\n", ele1), "n:1: dimension 2: only 3D meshes are supported");
  EXPECT_EQ(message("0 3 0 0\n", ele1), "n:1: no point (points kept in a .poly file are not supported)");
  EXPECT_EQ(message("4 3 0 0\n1 0 0 0\n3 1 0 0\n", ele1), "n:3: point index 3 out of sequence (2 expected)");
  EXPECT_EQ(message("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n", ele1), "n:4: truncated: 4 points announced, 3 found");
  EXPECT_EQ(message("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 inf 0\n4 0 0 1\n", ele1), "n:4: coordinate 'inf' is not a finite number");
  EXPECT_EQ(message(node1 + "5 0 0 0\n", ele1), "n:6: '5' after the 4 points the header announces");
  EXPECT_EQ(message("4 3 0 1\n1 0 0 0\n", ele1), "n:2: point line with 4 values, the header announces 5");
  EXPECT_EQ(message(node1, "1 4 0\n1 1 2 3 5\n"), "e:2: tetrahedron 0 has node index 5 out of range");
  EXPECT_EQ(message(node1, "1 4 0\n1 1 2 3 3\n"), "e:2: tetrahedron 0 repeats a vertex");
  EXPECT_EQ(message(node1, "1 4 0\n0 1 2 3 4\n"), "e:2: tetrahedron index 0 out of sequence (1 expected)");
  EXPECT_EQ(message(node1, "1 4 1\n1 1 2 3 4 2.5\n"), "e:2: region attribute 2.5 is not an integer label");
  EXPECT_EQ(message(node1, "1 6 0\n"), "e:1: 6 nodes per tetrahedron (4 or 10 expected)");
  EXPECT_EQ(message(node1, "2 4 0\n1 1 2 3 4\n"), "e:2: truncated: 2 tetrahedra announced, 1 found");
  EXPECT_EQ(message(node1, "1 4 0\n1 1 2 3 x\n"), "e:2: 'x' is not an integer");
}
