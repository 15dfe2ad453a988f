#include "sinew/mesh/gmsh_content.hpp"

namespace sinew::gmsh {

TypeUse type_use(int type)
{
    switch (type) {
    case kTetrahedronType:
    case kTriangleType: return TypeUse::keep;
    case 15:  // point
    case 1:   // 2-node line
    case 8:   // 3-node line
    case 26:  // 4-node line
    case 27:  // 5-node line
    case 28:  // 6-node line
        return TypeUse::ignore;
    default: return TypeUse::reject;
    }
}

int kept_type_nodes(int type)
{
    return type == kTetrahedronType ? 4 : 3;
}

std::string type_name(int type)
{
    switch (type) {
    case 3: return "4-node quadrangle";
    case 5: return "8-node hexahedron";
    case 6: return "6-node prism";
    case 7: return "5-node pyramid";
    case 9: return "6-node second-order triangle";
    case 10: return "9-node second-order quadrangle";
    case 11: return "10-node second-order tetrahedron";
    case 12: return "27-node second-order hexahedron";
    case 16: return "8-node second-order quadrangle";
    case 17: return "20-node second-order hexahedron";
    default: return "type " + std::to_string(type);
    }
}

void require_entry(TextLineReader& in, const std::string& section, const std::string& what)
{
    in.require_next(what + " in " + section);
    if (in.token(0)[0] == '$')
        in.fail(section + " ends before " + what + " (the counts promise more entries)");
}

void require_section_end(TextLineReader& in, const std::string& section)
{
    const std::string end = "$End" + section.substr(1);
    in.require_next(end);
    if (in.token(0) != end)
        in.fail("expected " + end + " after the entries the counts promise, found '" + in.token(0) + "'");
}

void skip_section(TextLineReader& in, const std::string& section)
{
    const std::string end = "$End" + section.substr(1);
    do
        in.require_next(end);
    while (in.token(0) != end);
}

void require_distinct_node_tags(const TextLineReader& in, const std::vector<int>& node_tags)
{
    for (std::size_t i = 0; i < node_tags.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (node_tags[i] == node_tags[j])
                in.fail("node tag " + std::to_string(node_tags[i]) + " appears twice in the element");
}

void read_physical_names(TextLineReader& in, Content& content)
{
    const std::string section = "$PhysicalNames";
    require_entry(in, section, "the number of names");
    in.expect_token_count(1, "number of physical names");
    const int count = in.integer(0, "number of physical names");
    for (int i = 0; i < count; ++i) {
        require_entry(in, section, "physical name " + std::to_string(i + 1) + " of " + std::to_string(count));
        const auto open = in.text().find('"');
        const auto close = in.text().rfind('"');
        if (in.token_count() < 3 || open == std::string::npos || close == open)
            in.fail("physical name: expected '<dimension> <tag> \"<name>\"'");
        const int dimension = in.integer(0, "physical dimension");
        const int tag = in.integer(1, "physical tag");
        content.physical_names[{dimension, tag}] = in.text().substr(open + 1, close - open - 1);
    }
    require_section_end(in, section);
}

} // namespace sinew::gmsh
