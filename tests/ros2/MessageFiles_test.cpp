// The shipped ROS 2 package (ros2/stairmap_msgs/msg/*.msg) and the IDL stairmap compiles
// (libstairmap/ros2/idl/StairmapMessages.idl) must list the same fields in the same order with
// the same types: a ROS node builds its types from the .msg files, stairmap from the IDL, and DDS
// only compares type names.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace {

const std::string kSource = STAIRMAP_SOURCE_DIR;

std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// .msg type -> IDL type as written in StairmapMessages.idl.
std::string idlType(const std::string& msg_type) {
    static const std::map<std::string, std::string> basic = {
        {"bool", "boolean"}, {"uint8", "octet"}, {"int32", "long"}, {"uint32", "unsigned long"},
        {"float32", "float"}, {"float64", "double"}, {"string", "string"}};
    std::string base = msg_type, suffix;
    const auto bracket = base.find('[');
    if (bracket != std::string::npos) {
        suffix = base.substr(bracket);
        base = base.substr(0, bracket);
    }
    std::string idl;
    if (basic.count(base)) idl = basic.at(base);
    else if (base.find('/') != std::string::npos)
        idl = std::regex_replace(base, std::regex("(\\w+)/(\\w+)"), "$1::msg::dds_::$2_");
    else idl = base + "_";  // a type of this package
    if (suffix == "[]") return "sequence<" + idl + ">";
    return suffix.empty() ? idl : idl + suffix;
}

/// "type name" per field of a .msg file (comments, blank lines and constants skipped).
std::vector<std::string> msgFields(const std::string& name) {
    std::istringstream in(readText(kSource + "/ros2/stairmap_msgs/msg/" + name + ".msg"));
    std::vector<std::string> fields;
    std::string line;
    while (std::getline(in, line)) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::string type, field;
        if (!(words >> type >> field) || field.find('=') != std::string::npos) continue;
        std::string idl = idlType(type);
        const auto bracket = idl.find('[');  // fixed arrays: the size goes after the name in IDL
        if (bracket != std::string::npos) {
            field += idl.substr(bracket);
            idl = idl.substr(0, bracket);
        }
        fields.push_back(idl + " " + field);
    }
    return fields;
}

/// "type name" per member of struct `name`_ in the IDL.
std::vector<std::string> idlFields(const std::string& name) {
    const std::string idl = readText(kSource + "/libstairmap/ros2/idl/StairmapMessages.idl");
    std::smatch m;
    if (!std::regex_search(idl, m, std::regex("struct " + name + "_ \\{([^}]*)\\}"))) return {};
    std::vector<std::string> fields;
    std::istringstream members(m[1].str());
    std::string member;
    while (std::getline(members, member, ';')) {
        member = std::regex_replace(member, std::regex("^\\s+|\\s+$"), "");
        member = std::regex_replace(member, std::regex("\\s+"), " ");
        if (!member.empty()) fields.push_back(member);
    }
    return fields;
}

TEST(MessageFiles, MsgAndIdlAgreeFieldForField) {
    for (const char* name : {"StairStep", "Floor", "Staircase", "StaircaseArray"}) {
        const auto from_msg = msgFields(name);
        EXPECT_GT(from_msg.size(), 2u) << name;
        EXPECT_EQ(from_msg, idlFields(name)) << name;
    }
}

}  // namespace
