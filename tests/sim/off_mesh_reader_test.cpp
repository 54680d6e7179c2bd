// The OFF reader: the format's variants read to the same polygons, every line end counts the
// same, and each malformed file is refused on one line naming the file and its line.
#include "sim/off_mesh_reader.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/sim/mesh_file_fixture.hpp"

namespace cosmos {
namespace {

class OffMeshReader : public MeshFileFixture {
 protected:
  std::string read_error(const std::string& name, const std::string& text) const {
    const auto path = write(name, text);
    return error_of([&] { read_off_mesh(path); });
  }
};

// A square pyramid: 5 vertices, a quad base and 4 triangles.
constexpr const char* kPyramid =
    "OFF\n5 5 0\n0 0 0\n2 0 0\n2 2 0\n0 2 0\n1 1 3\n"
    "4 0 3 2 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

TEST_F(OffMeshReader, ReadsVerticesAndPolygonFacesAsTheFileHasThem) {
  expect_square_pyramid(read_off_mesh(write("pyramid.off", kPyramid)));
}

TEST_F(OffMeshReader, EveryLineEndReadsTheSame) {
  expect_square_pyramid(read_off_mesh(write("crlf.off", replaced(kPyramid, "\n", "\r\n"))));
  expect_square_pyramid(read_off_mesh(write("cr.off", replaced(kPyramid, "\n", "\r"))));
}

TEST_F(OffMeshReader, CommentsBlankLinesKeywordVariantsAndTrailingValuesAreSkipped) {
  // Counts on the keyword's line, a colour after each vertex (COFF) and after a face, comments.
  expect_square_pyramid(read_off_mesh(
      write("coff.off",
            "# a pyramid\n\nCOFF 5 5 10 # counts\n0 0 0 255 0 0 255\n2 0 0 255 0 0 255\n"
            "\t\n2 2 0 0 255 0 255\n0 2 0 0 0 255 255\n1 1 3 9 9 9 9\n"
            "4 0 3 2 1 0.5 0.5 0.5\n3 0 1 4\n3 1 2 4 # side\n3 2 3 4\n3 3 0 4\n")));
  // The keyword is optional in the format.
  expect_square_pyramid(read_off_mesh(write("bare.off", kPyramid + 4)));
  expect_square_pyramid(read_off_mesh(write("stcn.off", replaced(kPyramid, "OFF", "STCNOFF"))));
}

TEST_F(OffMeshReader, EachRefusalNamesTheLineAndTheReason) {
  struct Case {
    const char* text;
    const char* reason;
  };
  const Case cases[] = {
      {"", ":1: empty OFF file: no counts line"},
      {"4OFF\n3 1 0\n", ":1: OFF keyword '4OFF' is none of [ST][C][N]OFF"},
      {"OFF BINARY\n", ":1: the OFF counts line has vertex count 'BINARY', not a count >= 0"},
      {"OFF\n3 -1 0\n", ":2: the OFF counts line has face count '-1', not a count >= 0"},
      {"OFF\n\n3 1\n0 0 0\n1 0 0\n0 x 0\n3 0 1 2\n", ":6: vertex 2 is not three numbers"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1e39 0\n3 0 1 2\n",
       ":5: vertex 2 (0, inf, 0) has a NaN or infinite coordinate"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n# no more vertices here\n", ":6: the file ends before vertex 2"},
      {"OFF\n3 2\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 # one face, though the counts say 2\n",
       ":7: the file ends before face 1"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n2 0 1 # an edge\n",
       ":6: face 0 does not start with a vertex count of 3 or more ('2')"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
       ":6: face 0 indexes vertex 3, the file has 3 vertices"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n99999999999 0 1 2\n",
       ":6: face 0 does not start with a vertex count of 3 or more ('99999999999')"},
  };
  for (const Case& c : cases) {
    const auto path = write("bad.off", c.text);
    expect_one_line_naming(error_of([&] { read_off_mesh(path); }), path, c.reason);
  }
}

// A header claiming more than the file can hold is refused before anything is reserved.
TEST_F(OffMeshReader, CountsBeyondTheFilesBytesAreRefusedBeforeAnyAllocation) {
  EXPECT_NE(read_error("v.off", "OFF\n5000000000 0\n")
                .find(":2: the header claims 5000000000 vertices, more than its 1 bytes"),
            std::string::npos);
  EXPECT_NE(read_error("f.off", "OFF\n1 3\n0 0 0\n3 0 0 0\n")
                .find(":2: the header claims 3 faces, more than its 15 bytes"),
            std::string::npos);
}

}  // namespace
}  // namespace cosmos
