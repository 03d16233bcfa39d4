#pragma once
// Opening an input file so that every failure names it: a directory given where a file was
// expected would otherwise open fine and fail on the first read with a text naming nothing
// ("basic_filebuf::underflow error reading the file: Is a directory").

#include <fstream>
#include <string>

namespace stairmap::io {

/// Opens `path` for binary reading. Throws std::runtime_error "<path>: is a directory, not <what>"
/// or "<path>: cannot open <what>: <reason>" (e.g. No such file or directory).
/// `what` says what was expected, e.g. "a landmarks.json file".
std::ifstream openInputFile(const std::string& path, const std::string& what);

}  // namespace stairmap::io
