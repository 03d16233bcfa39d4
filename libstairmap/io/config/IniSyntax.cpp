#include "io/config/IniSyntax.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace stairmap::io {
namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

bool isComment(const std::string& s) {
    return s.empty() || s[0] == '#' || s[0] == ';' || startsWith(s, "//");
}

bool isName(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) {
        return std::isalnum(c) || c == '_' || c == '-' || c == '.';
    });
}

/// Throws "<source>:<line>: <what> '<text>' (<hint>)".
[[noreturn]] void malformed(const std::string& source, int line, const std::string& what,
                            const std::string& text) {
    throw std::runtime_error(source + ":" + std::to_string(line) + ": " + what + " '" + text +
                             "' (expected [section], key = value, or a comment: # ; //)");
}

/// "[name]" with an optional trailing comment -> lower-cased name.
std::string sectionName(const std::string& s, const std::string& source, int line) {
    const auto close = s.find(']');
    if (close == std::string::npos) malformed(source, line, "section header without ']':", s);
    const std::string name = trim(s.substr(1, close - 1));
    if (!isName(name)) malformed(source, line, "bad section name in", s);
    if (!isComment(trim(s.substr(close + 1))))
        malformed(source, line, "text after the section header:", s);
    return lower(name);
}

/// A line with no '=': a section header missing its '[' or a key missing its '='.
[[noreturn]] void missingEquals(const std::string& source, int line, const std::string& section,
                                const std::string& s) {
    if (s.back() == ']') malformed(source, line, "section header without '[':", s);
    const std::string first = s.substr(0, s.find_first_of(" \t"));
    if (!isName(first)) malformed(source, line, "malformed line", s);
    malformed(source, line,
              (section.empty() ? "" : "[" + section + "] ") + first + ": no '=' after the key in",
              s);
}

}  // namespace

std::vector<IniLine> lexIni(const std::string& text, const std::string& source) {
    std::vector<IniLine> lines;
    std::istringstream in(text);
    std::string section;
    bool in_section = false;
    int number = 0;
    for (std::string raw; std::getline(in, raw);) {
        ++number;
        const std::string s = trim(raw);
        if (isComment(s) || startsWith(s, "@define ")) continue;
        if (s[0] == '[') {
            section = sectionName(s, source, number);
            in_section = true;
            lines.push_back({number, section, ""});
            continue;
        }
        const auto eq = s.find('=');
        if (eq == std::string::npos) missingEquals(source, number, section, s);
        const std::string key = trim(s.substr(0, eq));
        if (!isName(key)) malformed(source, number, "bad key name in", s);
        if (!in_section) malformed(source, number, "key before any [section]:", s);
        lines.push_back({number, section, lower(key)});
    }
    return lines;
}

std::vector<IniLine> lexIniFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) throw std::runtime_error(path + ": config file cannot be read");
    return lexIni(text.str(), path);
}

}  // namespace stairmap::io
