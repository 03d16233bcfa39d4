#pragma once
// Test-side reader of ROS map_server maps (PGM + YAML), written from the format's description and
// independent of the library's writer: trinary interpretation p = (255 - value) / 255 (negate 0),
// occupied if p > occupied_thresh, free if p < free_thresh, unknown otherwise; the image's
// bottom-left pixel sits at `origin`.

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace stairmap::test {

struct MapServerMap {
    std::map<std::string, std::string> yaml;  ///< raw "key: value" pairs
    double resolution = 0.0, origin_x = 0.0, origin_y = 0.0, occupied_thresh = 0.0,
           free_thresh = 0.0;
    int width = 0, height = 0;
    std::vector<unsigned char> pixels;  ///< row-major, row 0 = top of the image

    /// -1 unknown, 0 free, 100 occupied at world (x, y); -2 outside the image.
    int occupancyAt(double x, double y) const {
        const int col = static_cast<int>(std::floor((x - origin_x) / resolution));
        const int row_from_bottom = static_cast<int>(std::floor((y - origin_y) / resolution));
        if (col < 0 || row_from_bottom < 0 || col >= width || row_from_bottom >= height) return -2;
        const unsigned char v =
            pixels[static_cast<std::size_t>(height - 1 - row_from_bottom) * width + col];
        const double p = (255.0 - v) / 255.0;
        if (p > occupied_thresh) return 100;
        if (p < free_thresh) return 0;
        return -1;
    }
};

inline std::string nextPgmToken(std::istream& in) {
    std::string token;
    while (in >> token) {
        if (token[0] != '#') return token;
        std::string rest;
        std::getline(in, rest);  // a comment runs to the end of the line
    }
    throw std::runtime_error("PGM header truncated");
}

inline std::vector<double> yamlNumbers(const std::string& text) {
    std::string t = text;
    for (char& c : t) {
        if (c == '[' || c == ']' || c == ',') c = ' ';
    }
    std::istringstream in(t);
    std::vector<double> out;
    double v;
    while (in >> v) out.push_back(v);
    return out;
}

inline MapServerMap readMapServerMap(const std::string& yaml_path) {
    MapServerMap m;
    std::ifstream y(yaml_path);
    if (!y) throw std::runtime_error(yaml_path + ": cannot open");
    std::string line;
    while (std::getline(y, line)) {
        if (line.empty() || line[0] == '#') continue;
        const auto colon = line.find(':');
        if (colon == std::string::npos) continue;
        std::string value = line.substr(colon + 1);
        value.erase(0, value.find_first_not_of(' '));
        m.yaml[line.substr(0, colon)] = value;
    }
    m.resolution = std::stod(m.yaml.at("resolution"));
    const auto origin = yamlNumbers(m.yaml.at("origin"));
    m.origin_x = origin.at(0);
    m.origin_y = origin.at(1);
    m.occupied_thresh = std::stod(m.yaml.at("occupied_thresh"));
    m.free_thresh = std::stod(m.yaml.at("free_thresh"));
    const std::string dir = yaml_path.substr(0, yaml_path.find_last_of('/') + 1);
    std::ifstream pgm(dir + m.yaml.at("image"), std::ios::binary);
    if (nextPgmToken(pgm) != "P5") throw std::runtime_error("not a binary PGM");
    m.width = std::stoi(nextPgmToken(pgm));
    m.height = std::stoi(nextPgmToken(pgm));
    if (std::stoi(nextPgmToken(pgm)) != 255) throw std::runtime_error("maxval is not 255");
    pgm.get();  // the single whitespace after maxval
    m.pixels.resize(static_cast<std::size_t>(m.width) * m.height);
    pgm.read(reinterpret_cast<char*>(m.pixels.data()),
             static_cast<std::streamsize>(m.pixels.size()));
    if (pgm.gcount() != static_cast<std::streamsize>(m.pixels.size())) {
        throw std::runtime_error("PGM pixel data truncated");
    }
    return m;
}

}  // namespace stairmap::test
