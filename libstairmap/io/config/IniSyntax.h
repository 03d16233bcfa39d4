#pragma once
// A strict lexer for the MRPT-style INI files stairmap reads. MRPT's CConfigFile silently ignores
// lines it cannot parse (`detector]`, `leaf_size_m 0.02`), so every file is lexed here first and a
// malformed line is an error naming the file and the line.
//
// Accepted lines (leading/trailing blanks ignored), as CConfigFile reads them:
//   blank; comments starting with '#', ';' or '//'; `@define NAME value` (MRPT's preprocessor);
//   `[section]` (optionally followed by a comment); `key = value` (value may be empty; a trailing
//   `// comment` is MRPT's to strip). Keys are letters, digits, '_', '-', '.'.
// Section and key names are compared case-insensitively (as CConfigFile does): the lexer returns
// them lower-cased.

#include <string>
#include <vector>

namespace stairmap::io {

/// One `[section]` header (key empty) or one `key = value` line of an INI file.
struct IniLine {
    int line = 0;         ///< 1-based line number
    std::string section;  ///< lower-cased section name
    std::string key;      ///< lower-cased key; empty for a section header
};

/// Lexes `text`; `source` names it in errors. Throws std::runtime_error
/// "<source>:<line>: <problem> '<line text>'" for a malformed line or a key before any section.
std::vector<IniLine> lexIni(const std::string& text, const std::string& source);

/// Reads and lexes the file at `path` (errors name the path).
std::vector<IniLine> lexIniFile(const std::string& path);

}  // namespace stairmap::io
