#include "io/cloud/PlyHeader.h"

#include <istream>
#include <stdexcept>
#include <string_view>

#include "io/cloud/CloudFileParsing.h"

namespace stairmap::io::detail {

namespace {

constexpr std::size_t kMaxHeaderLines = 1024;

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error("bad PLY header: " + what); }

std::string clip(std::string_view word) { return std::string(word.substr(0, 40)); }

PlyScalar scalarOf(std::string_view name) {
    struct Named { const char* a; const char* b; PlyScalar type; };
    static const Named kTypes[] = {
        {"char", "int8", {'I', 1}},   {"uchar", "uint8", {'U', 1}},   {"short", "int16", {'I', 2}},
        {"ushort", "uint16", {'U', 2}}, {"int", "int32", {'I', 4}},   {"uint", "uint32", {'U', 4}},
        {"float", "float32", {'F', 4}}, {"double", "float64", {'F', 8}}};
    for (const Named& t : kTypes) {
        if (name == t.a || name == t.b) return t.type;
    }
    fail("unknown property type '" + clip(name) + "'");
}

void parseFormat(const std::vector<std::string_view>& words, PlyHeader& h) {
    if (words.size() != 3) fail("malformed format line");
    if (words[1] == "ascii") {
        h.encoding = PlyEncoding::Ascii;
    } else if (words[1] == "binary_little_endian") {
        h.encoding = PlyEncoding::BinaryLittleEndian;
    } else if (words[1] == "binary_big_endian") {
        throw std::runtime_error("PLY format binary_big_endian is not supported (use ascii or binary_little_endian)");
    } else {
        fail("unknown format '" + clip(words[1]) + "'");
    }
}

void parseProperty(const std::vector<std::string_view>& words, PlyHeader& h) {
    if (h.elements.empty()) fail("property before any element");
    PlyProperty p;
    if (words.size() == 5 && words[1] == "list") {
        p.is_list = true;
        p.list_count = scalarOf(words[2]);
        if (p.list_count.kind == 'F') fail("list length type must be an integer type");
        p.value = scalarOf(words[3]);
        p.name = words[4];
    } else if (words.size() == 3) {
        p.value = scalarOf(words[1]);
        p.name = words[2];
    } else {
        fail("malformed property line");
    }
    h.elements.back().properties.push_back(p);
}

void locateVertexXyz(PlyHeader& h) {
    std::size_t v = h.elements.size();
    for (std::size_t i = 0; i < h.elements.size(); ++i) {
        if (h.elements[i].name == "vertex") v = i;
    }
    if (v == h.elements.size()) fail("no 'vertex' element");
    h.vertex_element = v;
    const auto& props = h.elements[v].properties;
    const char* names[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
        std::size_t found = props.size();
        for (std::size_t i = 0; i < props.size(); ++i) {
            if (props[i].name == names[k]) found = i;
        }
        if (found == props.size()) fail(std::string("vertex has no property '") + names[k] + "'");
        if (props[found].is_list) fail(std::string("vertex property ") + names[k] + " is a list");
        h.xyz_property[k] = found;
    }
}

}  // namespace

PlyHeader readPlyHeader(std::istream& in) {
    std::string line;
    if (!readLine(in, line) || splitWords(line).size() != 1 || splitWords(line)[0] != "ply") {
        fail("the file does not start with 'ply' (not a PLY file?)");
    }
    PlyHeader h;
    bool have_format = false;
    for (std::size_t n = 0; n < kMaxHeaderLines && readLine(in, line); ++n) {
        const auto words = splitWords(line);
        if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
        if (words[0] == "end_header") {
            if (!have_format) fail("no format line");
            locateVertexXyz(h);
            return h;
        }
        if (words[0] == "format") {
            parseFormat(words, h);
            have_format = true;
        } else if (words[0] == "element") {
            PlyElement e;
            if (words.size() != 3 || !parseCount(words[2], e.count)) fail("malformed element line");
            e.name = words[1];
            h.elements.push_back(e);
        } else if (words[0] == "property") {
            parseProperty(words, h);
        } else {
            fail("unknown keyword '" + clip(words[0]) + "'");
        }
    }
    fail("no end_header (file truncated or not a PLY file)");
}

}  // namespace stairmap::io::detail
