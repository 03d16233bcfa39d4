#pragma once
// MRPT exceptions span many lines (message, location, call stack); keep the line that says what
// went wrong, for one-line error messages (rawlog reading, sensor drivers).

#include <exception>
#include <string>

namespace stairmap::io {

inline std::string mrptErrorText(const std::exception& e) {
    const std::string what = e.what();
    const auto msg = what.find("Message:");
    const std::size_t start = msg == std::string::npos ? 0 : msg + 8;
    const std::size_t end = what.find('\n', start);
    std::string line = what.substr(start, end == std::string::npos ? std::string::npos : end - start);
    const auto first = line.find_first_not_of(' ');
    return first == std::string::npos ? std::string("unknown error") : line.substr(first);
}

}  // namespace stairmap::io
