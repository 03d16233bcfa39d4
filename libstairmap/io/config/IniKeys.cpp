#include "io/config/IniKeys.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace stairmap::io {
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

/// Levenshtein distance (names are short: O(|a| |b|) is nothing).
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

/// " (did you mean X?)" for the closest name within 2 edits (more for long names), else "".
template <class Names, class Fmt>
std::string suggestion(const std::string& name, const Names& names, Fmt format) {
    std::string best;
    std::size_t best_distance = std::max<std::size_t>(3, name.size() / 3 + 1);
    for (const std::string& candidate : names) {
        const std::size_t d = editDistance(name, candidate);
        if (d < best_distance) best_distance = d, best = candidate;
    }
    return best.empty() ? "" : " (did you mean " + format(best) + "?)";
}

std::string joined(const std::set<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "(none)" : out;
}

}  // namespace

void KeyRecorder::getAllSections(std::vector<std::string>& sections) const {
    inner_.getAllSections(sections);
}

void KeyRecorder::getAllKeys(const std::string& section, std::vector<std::string>& keys) const {
    inner_.getAllKeys(section, keys);
}

void KeyRecorder::clear() { throw std::logic_error("KeyRecorder is read-only"); }

void KeyRecorder::writeString(const std::string&, const std::string&, const std::string&) {
    throw std::logic_error("KeyRecorder is read-only");
}

std::string KeyRecorder::readString(const std::string& section, const std::string& name,
                                    const std::string& default_str, bool fail_if_not_found) const {
    keys_[lower(section)].insert(lower(name));
    return inner_.read_string(section, name, default_str, fail_if_not_found);
}

void checkIniKeys(const std::vector<IniLine>& lines, const IniKeys& known,
                  const std::string& source) {
    std::set<std::string> sections;
    for (const auto& [name, keys] : known) sections.insert(name);
    for (const IniLine& l : lines) {
        const std::string where = source + ":" + std::to_string(l.line) + ": ";
        const auto section = known.find(l.section);
        if (section == known.end()) {
            throw std::runtime_error(
                where + "unknown section [" + l.section + "]" +
                suggestion(l.section, sections,
                           [](const std::string& s) { return "[" + s + "]"; }) +
                "; valid sections: " + joined(sections));
        }
        if (l.key.empty() || section->second.count(l.key) == 1) continue;
        throw std::runtime_error(
            where + "[" + l.section + "] " + l.key + ": unknown key" +
            suggestion(l.key, section->second, [](const std::string& k) { return k; }) +
            "; valid keys of [" + l.section + "]: " + joined(section->second));
    }
}

}  // namespace stairmap::io
