#include "io/cloud/PcdHeader.h"

#include <istream>
#include <limits>
#include <map>
#include <stdexcept>

#include "io/cloud/CloudFile.h"
#include "io/cloud/CloudFileParsing.h"

namespace stairmap::io::detail {

namespace {

constexpr std::size_t kMaxHeaderLines = 256;
constexpr std::size_t kMaxElementsPerField = 100000;
constexpr std::size_t kMaxFields = 10000;

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error("bad PCD header: " + what); }

std::size_t countOf(const std::string& key, std::string_view word) {
    std::size_t value = 0;
    if (!parseCount(word, value)) fail(key + " '" + std::string(word.substr(0, 40)) + "' is not a count");
    return value;
}

/// Raw keyword -> words table of the header; stops after the DATA line.
std::map<std::string, std::vector<std::string>> readHeaderTable(std::istream& in) {
    std::map<std::string, std::vector<std::string>> table;
    std::string line;
    for (std::size_t n = 0; n < kMaxHeaderLines && readLine(in, line); ++n) {
        if (!line.empty() && line[0] == '#') continue;
        const auto words = splitWords(line);
        if (words.empty()) continue;
        const std::string key(words[0].substr(0, 40));
        static const char* kKnown[] = {"VERSION", "FIELDS", "SIZE", "TYPE", "COUNT",
                                       "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
        bool known = false;
        for (const char* k : kKnown) known = known || key == k;
        if (!known) fail("unknown keyword '" + key + "' (is this a PCD file?)");
        if (table.count(key)) fail("keyword " + key + " appears twice");
        auto& values = table[key];
        for (std::size_t i = 1; i < words.size(); ++i) values.emplace_back(words[i]);
        if (key == "DATA") return table;
    }
    fail("no DATA line (file truncated or not a PCD file)");
}

const std::vector<std::string>& required(const std::map<std::string, std::vector<std::string>>& t,
                                         const std::string& key) {
    const auto it = t.find(key);
    if (it == t.end() || it->second.empty()) fail("missing " + key);
    return it->second;
}

std::vector<PcdField> parseFields(const std::map<std::string, std::vector<std::string>>& t) {
    const auto& names = required(t, "FIELDS");
    const auto& sizes = required(t, "SIZE");
    const auto& types = required(t, "TYPE");
    const std::vector<std::string> ones(names.size(), "1");
    const auto& counts = t.count("COUNT") ? t.at("COUNT") : ones;
    if (names.size() > kMaxFields) fail("more than " + std::to_string(kMaxFields) + " FIELDS");
    if (sizes.size() != names.size() || types.size() != names.size() || counts.size() != names.size()) {
        fail("FIELDS, SIZE, TYPE and COUNT list different numbers of entries");
    }
    std::vector<PcdField> fields(names.size());
    for (std::size_t i = 0; i < names.size(); ++i) {
        PcdField& f = fields[i];
        f.name = names[i];
        f.size = countOf("SIZE", sizes[i]);
        f.count = countOf("COUNT", counts[i]);
        f.type = types[i].size() == 1 ? types[i][0] : '?';
        const bool int_ok = (f.type == 'I' || f.type == 'U') &&
                            (f.size == 1 || f.size == 2 || f.size == 4 || f.size == 8);
        const bool float_ok = f.type == 'F' && (f.size == 4 || f.size == 8);
        if (!int_ok && !float_ok) fail("field " + f.name + " has unsupported TYPE/SIZE " + types[i] + "/" + sizes[i]);
        if (f.count == 0 || f.count > kMaxElementsPerField) fail("field " + f.name + " has COUNT " + counts[i]);
    }
    return fields;
}

void locateXyz(PcdHeader& h) {
    const char* names[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
        std::size_t found = h.fields.size();
        for (std::size_t i = 0; i < h.fields.size(); ++i) {
            if (h.fields[i].name == names[k]) found = i;
        }
        if (found == h.fields.size()) fail(std::string("FIELDS has no '") + names[k] + "'");
        if (h.fields[found].count != 1) fail(std::string("field ") + names[k] + " must have COUNT 1");
        h.xyz_field[k] = found;
    }
}

void parseCounts(PcdHeader& h, const std::map<std::string, std::vector<std::string>>& t) {
    const std::size_t width = countOf("WIDTH", required(t, "WIDTH")[0]);
    const std::size_t height = t.count("HEIGHT") && !t.at("HEIGHT").empty() ? countOf("HEIGHT", t.at("HEIGHT")[0]) : 1;
    if (height != 0 && width > std::numeric_limits<std::size_t>::max() / height) fail("WIDTH*HEIGHT overflows");
    h.num_points = width * height;
    if (t.count("POINTS") && !t.at("POINTS").empty()) {
        const std::size_t points = countOf("POINTS", t.at("POINTS")[0]);
        if (points != h.num_points) {
            fail("POINTS " + std::to_string(points) + " differs from WIDTH*HEIGHT " + std::to_string(h.num_points));
        }
    }
    if (h.point_bytes > 0 && h.num_points > std::numeric_limits<std::size_t>::max() / h.point_bytes) {
        fail("POINTS too large");
    }
}

}  // namespace

PcdHeader readPcdHeader(std::istream& in) {
    const auto table = readHeaderTable(in);
    PcdHeader h;
    h.fields = parseFields(table);
    for (PcdField& f : h.fields) {
        f.offset = h.point_bytes;
        f.column = h.point_columns;
        h.point_bytes += f.size * f.count;
        h.point_columns += f.count;
        // One record is read at a time at least: bound it (sizes <= 8, counts <= 1e5: no overflow).
        if (h.point_bytes > kMaxPcdPointBytes) {
            fail("a point record is larger than " + std::to_string(kMaxPcdPointBytes) + " bytes");
        }
    }
    locateXyz(h);
    parseCounts(h, table);
    const std::string& data = required(table, "DATA")[0];
    if (data == "ascii") {
        h.encoding = PcdEncoding::Ascii;
    } else if (data == "binary") {
        h.encoding = PcdEncoding::Binary;
    } else if (data == "binary_compressed") {
        throw std::runtime_error("PCD DATA binary_compressed is not supported (save as ascii or binary)");
    } else {
        fail("unknown DATA encoding '" + data.substr(0, 40) + "'");
    }
    return h;
}

}  // namespace stairmap::io::detail
