// MSH 2.2 ASCII: $Nodes lists "<tag> <x> <y> <z>"; $Elements lists
// "<tag> <type> <#tags> <tags…> <node tags…>" where the first tag is the
// physical group (0: none) and the second the elementary entity.
#include "sinew/mesh/gmsh_content.hpp"

namespace sinew::gmsh {
namespace {

void read_nodes(TextLineReader& in, Content& content)
{
    const std::string section = "$Nodes";
    require_entry(in, section, "the number of nodes");
    in.expect_token_count(1, "number of nodes");
    const int count = in.integer(0, "number of nodes");
    for (int i = 0; i < count; ++i) {
        require_entry(in, section, "node " + std::to_string(i + 1) + " of " + std::to_string(count));
        in.expect_token_count(4, "node");
        Node node;
        node.tag = in.integer(0, "node tag");
        for (int k = 0; k < 3; ++k)
            node.x[k] = in.number(1 + k, std::string("coordinate ") + "xyz"[k] + " of node " + std::to_string(node.tag));
        node.line = in.line_number();
        content.nodes.push_back(node);
    }
    require_section_end(in, section);
}

void read_elements(TextLineReader& in, Content& content)
{
    const std::string section = "$Elements";
    require_entry(in, section, "the number of elements");
    in.expect_token_count(1, "number of elements");
    const int count = in.integer(0, "number of elements");
    for (int i = 0; i < count; ++i) {
        require_entry(in, section, "element " + std::to_string(i + 1) + " of " + std::to_string(count));
        in.expect_at_least(3, "element");
        in.integer(0, "element tag");
        const int type = in.integer(1, "element type");
        const TypeUse use = type_use(type);
        if (use == TypeUse::ignore)
            continue;
        if (use == TypeUse::reject)
            in.fail("element type " + std::to_string(type) + " (" + type_name(type) +
                    ") is not supported: sinew reads 4-node tetrahedra and 3-node triangles");
        const int tags = in.integer(2, "number of tags");
        if (tags < 0 || static_cast<std::size_t>(tags) > in.token_count())
            in.fail("number of tags is " + std::to_string(tags) + ", the line has " +
                    std::to_string(in.token_count()) + " values");
        const int corners = kept_type_nodes(type);
        in.expect_token_count(3 + static_cast<std::size_t>(tags) + corners, "element of type " + std::to_string(type) + " with " +
                                                      std::to_string(tags) + " tags");
        Element element;
        element.type = type;
        element.physical_tag = tags > 0 ? in.integer(3, "physical tag") : 0;
        for (int k = 0; k < corners; ++k)
            element.node_tags.push_back(in.integer(3 + tags + k, "node tag"));
        require_distinct_node_tags(in, element.node_tags);
        element.line = in.line_number();
        content.elements.push_back(element);
    }
    require_section_end(in, section);
}

} // namespace

Content parse_msh2(TextLineReader& in)
{
    Content content;
    while (in.next()) {
        const std::string section = in.token(0);
        if (section == "$PhysicalNames")
            read_physical_names(in, content);
        else if (section == "$Nodes")
            read_nodes(in, content);
        else if (section == "$Elements")
            read_elements(in, content);
        else if (section[0] == '$')
            skip_section(in, section);
        else
            in.fail("expected a section ($Nodes, $Elements, ...), found '" + section + "'");
    }
    return content;
}

} // namespace sinew::gmsh
