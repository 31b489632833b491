// Tetrahedral mesh files: the strict Medit reader, the Medit writer and the VTU writer.

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/IO/vtu.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
namespace IO = CGAL::Distortion_optimization::IO;

namespace {

std::string temp(const std::string& name) { return ::testing::TempDir() + "distortion_io_" + name; }

bool exists(const std::string& path) { return std::ifstream(path).good(); }

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
  return IO::read_MEDIT(in, name);
}

// The message of the Invalid_input thrown by reading `text`, or "" if nothing was thrown.
std::string error(const std::string& text)
{
  try {
    read(text);
  } catch(const DO::Invalid_input& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_REJECTED(text, fragment)                                                          \
  do {                                                                                           \
    const std::string message = error(text);                                                     \
    EXPECT_NE(message.find(fragment), std::string::npos) << "message: '" << message << "'";      \
  } while(false)

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
  IO::write_MEDIT(path, s);
  EXPECT_FALSE(exists(path + ".partial"));
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
  IO::write_MEDIT(path, s);
  EXPECT_EQ(IO::read_tetrahedron_soup(path).labels, std::vector<int>({1, 1}));
  std::remove(path.c_str());
}

TEST(Medit, WriterRejectsWhatTheReaderWouldRejectAndWritesNothing)
{
  const std::string path = temp("rejected.mesh");
  std::remove(path.c_str());
  IO::Tetrahedron_soup s = two_tetrahedra();
  s.labels = {1};
  EXPECT_THROW(IO::write_MEDIT(path, s), DO::Invalid_input);
  s = two_tetrahedra();
  s.cells[1][3] = 5;
  EXPECT_THROW(IO::write_MEDIT(path, s), DO::Invalid_input);
  s = two_tetrahedra();
  s.cells[1][3] = 1;
  EXPECT_THROW(IO::write_MEDIT(path, s), DO::Invalid_input);
  s = two_tetrahedra();
  s.points[4][2] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(IO::write_MEDIT(path, s), DO::Invalid_input);
  EXPECT_FALSE(exists(path));
  EXPECT_FALSE(exists(path + ".partial"));
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
}

TEST(Medit, RejectsMissingSections)
{
  EXPECT_REJECTED(header + "End\n", "bad.mesh:3: no Vertices section");
  EXPECT_REJECTED(header + four_vertices + "End\n", "bad.mesh:9: no Tetrahedra section");
  EXPECT_REJECTED(header + four_vertices + "Triangles 1 1 2 3 0\n", "bad.mesh:9: no Tetrahedra section");
  EXPECT_REJECTED(header + "Tetrahedra 0\n" + four_vertices, "bad.mesh:3: Tetrahedra before Vertices");
  EXPECT_REJECTED(header + four_vertices + four_vertices, "bad.mesh:9: second Vertices section");
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
  EXPECT_REJECTED(header + four_vertices + "Tetrahedra 99999999999999999999\n", "bad.mesh:9: '99999999999999999999' is not an integer");
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
    IO::read_MEDIT(in, "pipe");
    ADD_FAILURE() << "no exception";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("pipe:10: truncated Tetrahedra section: 1000000000000 entries announced, 1 found"),
              std::string::npos) << e.what();
  }
  // And a good file reads the same through such a stream.
  Unseekable_buffer good(header + four_vertices + "Tetrahedra 1 1 2 3 4 0\nEnd\n");
  std::istream in2(&good);
  EXPECT_EQ(IO::read_MEDIT(in2, "pipe").cells.size(), 1u);
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
  EXPECT_FALSE(exists(path + ".partial"));
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
  EXPECT_FALSE(exists(path + ".partial"));
}
