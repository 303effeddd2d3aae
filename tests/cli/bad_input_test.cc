// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Bad input, end to end through the `isovdb` binary: each case must give a
// one-line error naming the file and the problem, a non-zero exit code and no
// output file.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "support/test_support.h"

namespace isovdb::test {
namespace {

std::string nrrdHeader(const std::string& fields) { return "NRRD0004\n" + fields + "\n"; }

class CliBadInput : public ::testing::Test {
 protected:
  TempDir in, out;
  std::string outPly() const { return (out / "mesh.ply").string(); }
};

TEST_F(CliBadInput, MissingFile) {
  expectCleanFailure(runCli("extract " + (in / "nope.nrrd").string() + " -o " + outPly()),
                     {"nope.nrrd", "no such file"}, out);
}

TEST_F(CliBadInput, OutputsThatWouldOverwriteEachOtherOrTheInputOrCannotBeWritten) {
  // A 2^3 mask: any valid input will do, the files are refused before any work.
  writeFile(in / "v.nrrd",
            nrrdHeader("type: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n") + std::string(8, '\1'));
  const std::string volume = (in / "v.nrrd").string();
  expectCleanFailure(runCli("extract " + volume + " -o " + outPly() + " --stats " + outPly()),
                     {"mesh.ply", "--stats and -o name the same file"}, out);
  expectCleanFailure(runCli("convert " + volume + " -o " + volume), {"v.nrrd", "-o and the input name the same file"},
                     out);
  EXPECT_EQ(readFile(in / "v.nrrd").size(),
            8u + nrrdHeader("type: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n").size());
  // morph made the mesh and the .vdb, then failed on a --save-slices folder it could not make.
  expectCleanFailure(runCli("morph " + volume + " -o " + outPly() + " --vdb " + (out / "s.vdb").string() +
                            " --save-slices " + (in / "v.nrrd" / "planes").string()),
                     {"--save-slices", "is a file, not a folder"}, out);
  // The statistics' folder is checked before the mesh is written (reservoir wrote the mesh, then failed).
  const std::string deck = (dataDir() / "reservoir/fault_test/regular27cell.DATA").string();
  expectCleanFailure(runCli("reservoir " + deck + " --property PORO --iso 0.3 -o " + outPly() + " --stats " +
                            (out / "nodir" / "s.json").string()),
                     {"nodir"}, out);
}

TEST_F(CliBadInput, RawSizeDoesNotMatchDimensions) {
  writeFile(in / "v.raw", std::string(999, '\1'));
  expectCleanFailure(runCli("extract " + (in / "v.raw").string() + " --dims 10,10,10 --type uint8 -o " + outPly()),
                     {"v.raw", "1000", "999"}, out);
}

TEST_F(CliBadInput, ZeroNegativeAndOverflowingDimensions) {
  writeFile(in / "v.raw", std::string(1000, '\1'));
  for (const std::string dims : {"0,10,10", "10,-10,10", "4294967296,4294967296,4294967296"}) {
    SCOPED_TRACE(dims);
    expectCleanFailure(
        runCli("extract " + (in / "v.raw").string() + " --dims " + dims + " --type uint8 -o " + outPly()),
        {"v.raw", "dim"}, out);
  }
}

TEST_F(CliBadInput, UnknownSampleType) {
  writeFile(in / "v.raw", std::string(1000, '\1'));
  expectCleanFailure(runCli("extract " + (in / "v.raw").string() + " --dims 10,10,10 --type complex64 -o " + outPly()),
                     {"v.raw", "complex64"}, out);
  writeFile(in / "t.nrrd",
            nrrdHeader("type: quaternion\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n") + std::string(8, '\0'));
  expectCleanFailure(runCli("extract " + (in / "t.nrrd").string() + " -o " + outPly()), {"t.nrrd", "quaternion"}, out);
}

TEST_F(CliBadInput, NrrdMissingField) {
  writeFile(in / "m.nrrd", nrrdHeader("type: uint8\ndimension: 3\nencoding: raw\n") + std::string(8, '\0'));
  expectCleanFailure(runCli("extract " + (in / "m.nrrd").string() + " -o " + outPly()), {"m.nrrd", "sizes"}, out);
}

TEST_F(CliBadInput, NrrdContradictoryFields) {
  writeFile(in / "c.nrrd", nrrdHeader("type: uint8\ndimension: 3\nsizes: 2 2\nencoding: raw\n") + std::string(4, '\0'));
  expectCleanFailure(runCli("extract " + (in / "c.nrrd").string() + " -o " + outPly()), {"c.nrrd", "sizes"}, out);
}

TEST_F(CliBadInput, VdbWithoutTheNamedGridOrOfTheWrongType) {
  openvdb::initialize();
  auto vectors = openvdb::Vec3SGrid::create();
  vectors->setName("velocity");
  vectors->tree().setValueOn(openvdb::Coord(1, 2, 3), openvdb::Vec3s(1, 0, 0));
  openvdb::io::File((in / "v.vdb").string()).write({vectors});
  expectCleanFailure(runCli("extract " + (in / "v.vdb").string() + " --grid density -o " + outPly()),
                     {"v.vdb", "no grid named 'density'"}, out);
  expectCleanFailure(runCli("extract " + (in / "v.vdb").string() + " --grid velocity -o " + outPly()),
                     {"v.vdb", "vec3s"}, out);
}

TEST_F(CliBadInput, NanAndInfInFloatVolumes) {
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    std::vector<float> values(4 * 4 * 4, 0.f);
    values[(2 * 4 + 1) * 4 + 3] = bad;  // voxel (3, 1, 2)
    std::string bytes(values.size() * sizeof(float), '\0');
    std::memcpy(bytes.data(), values.data(), bytes.size());
    writeFile(in / "f.raw", bytes);
    expectCleanFailure(runCli("extract " + (in / "f.raw").string() + " --dims 4,4,4 --type float32 -o " + outPly()),
                       {"f.raw", "3", "1", "2"}, out);
  }
}

TEST_F(CliBadInput, OutputPathNotWritable) {
  writeFile(in / "v.raw", std::string(1000, '\1'));
  const std::string target = (out / "missing-dir" / "mesh.ply").string();
  expectCleanFailure(runCli("extract " + (in / "v.raw").string() + " --dims 10,10,10 --type uint8 -o " + target),
                     {"missing-dir/mesh.ply"}, out);
}

TEST_F(CliBadInput, UnknownMeshFormat) {
  writeFile(in / "v.raw", std::string(1000, '\1'));
  expectCleanFailure(
      runCli("extract " + (in / "v.raw").string() + " --dims 10,10,10 --type uint8 -o " + (out / "mesh.stl").string()),
      {"mesh.stl", ".ply or .obj"}, out);
}

}  // namespace
}  // namespace isovdb::test
