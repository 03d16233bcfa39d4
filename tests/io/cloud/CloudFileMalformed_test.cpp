// Cloud files: every kind of bad input gives a std::runtime_error that starts with the path and
// says what is wrong; random and truncated bytes never crash a reader.

#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "CloudFileTestUtil.h"
#include "io/cloud/CloudFile.h"

namespace stairmap::io {
namespace {

using test::bytesOf;
using test::expectReadError;
using test::scratchDir;
using test::writeRaw;

/// Writes `bytes` to <scratch>/<file> and expects readCloudFile to fail saying `phrase`.
void expectFileError(const std::string& file, const std::string& bytes, const std::string& phrase) {
    const std::string path = scratchDir("CloudFileMalformed", file) + "/" + file;
    writeRaw(path, bytes);
    SCOPED_TRACE(file);
    expectReadError([&] { readCloudFile(path); }, path + ": ", phrase);
}

const std::string kPcdHeader3 =
    "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 1\nPOINTS 3\n";
const std::string kPlyBinaryHeader3 =
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nend_header\n";

std::string floats(std::initializer_list<float> values) {
    std::string s;
    for (float v : values) s += bytesOf(v);
    return s;
}

TEST(CloudFileMalformed, MissingFileDirectoryAndUnknownExtension) {
    const std::string dir = scratchDir("CloudFileMalformed", "missing");
    expectReadError([&] { readCloudFile(dir + "/nope.pcd"); }, dir + "/nope.pcd: ", "does not exist");
    expectReadError([&] { readCloudFile(dir + "/nope.rawlog"); }, dir + "/nope.rawlog: ", "does not exist");
    std::filesystem::create_directories(dir + "/folder.ply");
    expectReadError([&] { readCloudFile(dir + "/folder.ply"); }, dir + "/folder.ply: ", "not a regular file");
    writeRaw(dir + "/cloud.las", "1 2 3\n");
    expectReadError([&] { readCloudFile(dir + "/cloud.las"); }, dir + "/cloud.las: ", "unknown point-cloud file extension");
}

TEST(CloudFileMalformed, EmptyFiles) {
    for (const char* name : {"e.xyz", "e.pcd", "e.ply", "e.rawlog"}) expectFileError(name, "", "file is empty");
}

TEST(CloudFileMalformed, XyzProblems) {
    expectFileError("text.xyz", "1 2 3\n4 five 6\n", "line 2: 'five' is not a number");
    expectFileError("cols.xyz", "1 2 3\n4 5\n", "line 2: expected at least 3 numbers");
    expectFileError("glued.xyz", "1 2 3.0.0\n", "is not a number");
    expectFileError("nan.xyz", "nan 1 2\n1 inf 2\n1 2 -inf\n", "contains no finite points");
}

TEST(CloudFileMalformed, PcdHeaderProblems) {
    expectFileError("nothdr.pcd", "hello world\n", "bad PCD header: unknown keyword 'hello'");
    expectFileError("nodata.pcd", kPcdHeader3, "no DATA line");
    expectFileError("noz.pcd", "FIELDS x y\nSIZE 4 4\nTYPE F F\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2\n",
                    "FIELDS has no 'z'");
    expectFileError("sizes.pcd", "FIELDS x y z\nSIZE 4 4\nTYPE F F F\nWIDTH 1\nDATA ascii\n1 2 3\n",
                    "different numbers of entries");
    expectFileError("type.pcd", "FIELDS x y z\nSIZE 4 4 3\nTYPE F F F\nWIDTH 1\nDATA ascii\n1 2 3\n",
                    "unsupported TYPE/SIZE");
    expectFileError("width.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH -1\nDATA ascii\n1 2 3\n",
                    "WIDTH '-1' is not a count");
    expectFileError("points.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nPOINTS 3\nDATA ascii\n",
                    "differs from WIDTH*HEIGHT");
    expectFileError("huge.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 99999999999999999999\nDATA binary\n",
                    "WIDTH '99999999999999999999' is not a count");
    expectFileError("overflow.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 4294967296\nHEIGHT 4294967296\n"
                    "DATA binary\n", "WIDTH*HEIGHT overflows");
}

TEST(CloudFileMalformed, PcdDataProblems) {
    expectFileError("compressed.pcd", kPcdHeader3 + "DATA binary_compressed\n" + std::string(20, 'x'),
                    "binary_compressed is not supported");
    expectFileError("encoding.pcd", kPcdHeader3 + "DATA zipped\n", "unknown DATA encoding 'zipped'");
    expectFileError("short.pcd", kPcdHeader3 + "DATA ascii\n1 2 3\n4 5 6\n", "declares 3 points but the data has 2");
    expectFileError("long.pcd", kPcdHeader3 + "DATA ascii\n1 2 3\n4 5 6\n7 8 9\n1 1 1\n", "more point lines");
    expectFileError("cols.pcd", kPcdHeader3 + "DATA ascii\n1 2 3\n4 5\n7 8 9\n", "point 1: expected 3 values");
    expectFileError("text.pcd", kPcdHeader3 + "DATA ascii\n1 2 3\n4 x 6\n7 8 9\n", "'x' is not a number");
    expectFileError("trunc.pcd", kPcdHeader3 + "DATA binary\n" + floats({1, 2, 3, 4, 5, 6, 7}),
                    "truncated binary data");
    expectFileError("extra.pcd", kPcdHeader3 + "DATA binary\n" + floats({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}),
                    "data continues after");
    const float nan = std::numeric_limits<float>::quiet_NaN();
    expectFileError("nan.pcd", kPcdHeader3 + "DATA binary\n" + floats({nan, 2, 3, 4, nan, 6, 7, 8, nan}),
                    "contains no finite points (3 points read");
}

TEST(CloudFileMalformed, PlyProblems) {
    expectFileError("magic.ply", "plx\nformat ascii 1.0\n", "does not start with 'ply'");
    expectFileError("bigendian.ply",
                    "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float x\nend_header\n",
                    "binary_big_endian is not supported");
    expectFileError("noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "no end_header");
    expectFileError("novertex.ply", "ply\nformat ascii 1.0\nelement face 0\nend_header\n", "no 'vertex' element");
    expectFileError("noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "end_header\n1 2\n", "vertex has no property 'z'");
    expectFileError("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
                    "unknown property type 'float128'");
    expectFileError("count.ply", "ply\nformat ascii 1.0\nelement vertex -2\nend_header\n", "malformed element line");
    const std::string ascii3 = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nend_header\n";
    expectFileError("short.ply", ascii3 + "1 2 3\n4 5 6\n", "truncated data: element 'vertex' declares 3");
    expectFileError("text.ply", ascii3 + "1 2 3\n4 5 six\n7 8 9\n", "vertex 1: 'six' is not a number");
    expectFileError("cols.ply", ascii3 + "1 2 3\n4 5 6 7\n7 8 9\n", "vertex 1: expected 3 values, found 4");
    expectFileError("trunc.ply", kPlyBinaryHeader3 + floats({1, 2, 3, 4, 5, 6, 7, 8}), "truncated data");
    // A huge element without properties holds no data: it must neither hang nor be mistaken for data.
    expectFileError("huge_empty_element.ply",
                    "ply\nformat binary_little_endian 1.0\nelement junk 18446744073709551615\nelement vertex 3\n"
                    "property float x\nproperty float y\nproperty float z\nend_header\n" + floats({1, 2, 3}),
                    "truncated data: element 'vertex' declares 3");
    expectFileError("inf.ply", ascii3 + "inf 1 1\n1 -inf 1\nnan nan nan\n", "contains no finite points");
}

TEST(CloudFileMalformed, RawlogThatIsNotARawlog) {
    expectFileError("junk.rawlog", "this is not an MRPT archive at all, just text\n", "not a valid MRPT rawlog");
}

/// Feeds `bytes` to a stream reader: success or std::runtime_error are fine, nothing else is.
void expectNoCrash(PointCloud (*reader)(std::istream&), const std::string& bytes) {
    std::istringstream in(bytes);
    try {
        reader(in);
    } catch (const std::runtime_error&) {
    } catch (const std::exception& e) {
        ADD_FAILURE() << "unexpected exception type: " << e.what();
    }
}

TEST(CloudFileMalformed, RandomAndTruncatedBytesNeverCrash) {
    std::stringstream pcd_a, pcd_b, ply_a, ply_b, xyz;
    const PointCloud cloud = test::randomCloud(20, 11);
    writePcd(pcd_a, cloud, CloudFileEncoding::Ascii);
    writePcd(pcd_b, cloud, CloudFileEncoding::Binary);
    writePly(ply_a, cloud, CloudFileEncoding::Ascii);
    writePly(ply_b, cloud, CloudFileEncoding::Binary);
    writeXyz(xyz, cloud);
    const std::pair<PointCloud (*)(std::istream&), std::string> valid[] = {
        {readPcd, pcd_a.str()}, {readPcd, pcd_b.str()}, {readPly, ply_a.str()},
        {readPly, ply_b.str()}, {readXyz, xyz.str()}};
    std::mt19937 rng(2024);
    std::uniform_int_distribution<int> byte(0, 255);
    for (const auto& [reader, text] : valid) {
        for (std::size_t len = 0; len <= text.size(); len += 3) expectNoCrash(reader, text.substr(0, len));
        for (int trial = 0; trial < 300; ++trial) {  // flip a few bytes of a valid file
            std::string mutated = text;
            for (int k = 0; k < 4; ++k) mutated[rng() % mutated.size()] = static_cast<char>(byte(rng));
            expectNoCrash(reader, mutated);
        }
        for (int trial = 0; trial < 100; ++trial) {  // valid header line + random bytes
            std::string junk = text.substr(0, text.find('\n') + 1);
            for (int k = 0; k < 200; ++k) junk += static_cast<char>(byte(rng));
            expectNoCrash(reader, junk);
        }
    }
}

TEST(CloudFileMalformed, RandomBytesInFilesGiveErrorsNamingTheFile) {
    const std::string dir = scratchDir("CloudFileMalformed", "random_files");
    std::mt19937 rng(99);
    for (const char* ext : {".xyz", ".pcd", ".ply", ".rawlog"}) {
        for (int trial = 0; trial < 5; ++trial) {
            std::string bytes(64 + rng() % 512, '\0');
            for (char& c : bytes) c = static_cast<char>(rng() & 0xff);
            bytes[0] = '\x01';  // a leading '#' would make a valid all-comment (empty) .xyz file
            const std::string path = dir + "/random" + std::to_string(trial) + ext;
            writeRaw(path, bytes);
            SCOPED_TRACE(path);
            expectReadError([&] { readCloudFile(path); }, path + ": ", "");
        }
    }
}

}  // namespace
}  // namespace stairmap::io
