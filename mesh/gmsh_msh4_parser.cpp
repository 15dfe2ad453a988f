// MSH 4.1 ASCII. $Entities gives the physical tags of each geometric entity;
// $Nodes and $Elements come in blocks, one per entity:
//   $Nodes:    "<#blocks> <#nodes> <min tag> <max tag>", then per block
//              "<entity dim> <entity tag> <parametric> <#nodes in block>",
//              the block's node tags one per line, then its coordinates
//              "<x> <y> <z> [<u> [<v> [<w>]]]" one per line;
//   $Elements: "<#blocks> <#elements> <min tag> <max tag>", then per block
//              "<entity dim> <entity tag> <type> <#elements in block>" and
//              "<tag> <node tags…>" per element.
// Node tags may be sparse; gmsh_reader.cpp maps them.
#include "sinew/mesh/gmsh_content.hpp"

namespace sinew::gmsh {
namespace {

using EntityPhysicals = std::map<std::pair<int, int>, std::vector<int>>;  ///< (dim, tag) → physical tags

void read_entities(TextLineReader& in, EntityPhysicals& physicals)
{
    const std::string section = "$Entities";
    require_entry(in, section, "the entity counts");
    in.expect_token_count(4, "entity counts (points, curves, surfaces, volumes)");
    int counts[4];
    for (int dimension = 0; dimension < 4; ++dimension)
        counts[dimension] = in.integer(dimension, "number of entities");
    for (int dimension = 0; dimension < 4; ++dimension)
        for (int i = 0; i < counts[dimension]; ++i) {
            // Points: "<tag> <x> <y> <z> <#physicals> …"; curves, surfaces,
            // volumes: "<tag> <bounding box: 6 values> <#physicals> …".
            const std::string what = "entity " + std::to_string(i + 1) + " of dimension " + std::to_string(dimension);
            require_entry(in, section, what);
            const std::size_t physical_count_at = dimension == 0 ? 4 : 7;
            in.expect_at_least(physical_count_at + 1, what);
            const int tag = in.integer(0, "entity tag");
            const int physical_count = in.integer(physical_count_at, "number of physical tags");
            if (physical_count < 0)
                in.fail("number of physical tags is " + std::to_string(physical_count));
            in.expect_at_least(physical_count_at + 1 + physical_count, what);
            std::vector<int>& tags = physicals[{dimension, tag}];
            for (int k = 0; k < physical_count; ++k)
                tags.push_back(in.integer(physical_count_at + 1 + k, "physical tag"));
        }
    require_section_end(in, section);
}

void read_nodes(TextLineReader& in, Content& content)
{
    const std::string section = "$Nodes";
    require_entry(in, section, "the node counts");
    in.expect_token_count(4, "node counts (blocks, nodes, min tag, max tag)");
    const int blocks = in.integer(0, "number of node blocks");
    const int total = in.integer(1, "number of nodes");
    int read = 0;
    for (int b = 0; b < blocks; ++b) {
        require_entry(in, section, "node block " + std::to_string(b + 1) + " of " + std::to_string(blocks));
        in.expect_token_count(4, "node block header (entity dim, entity tag, parametric, nodes)");
        const int entity_dimension = in.integer(0, "entity dimension");
        const int parametric = in.integer(2, "parametric flag");
        const int count = in.integer(3, "number of nodes in block");
        if (parametric != 0 && parametric != 1)
            in.fail("parametric flag is " + std::to_string(parametric) + ", expected 0 or 1");
        if (entity_dimension < 0 || entity_dimension > 3)
            in.fail("entity dimension is " + std::to_string(entity_dimension) + ", expected 0 to 3");
        if (count < 0)
            in.fail("number of nodes in block is " + std::to_string(count));
        const std::size_t first = content.nodes.size();
        for (int i = 0; i < count; ++i) {
            require_entry(in, section, "node tag " + std::to_string(i + 1) + " of block " + std::to_string(b + 1));
            in.expect_token_count(1, "node tag");
            Node node;
            node.tag = in.integer(0, "node tag");
            content.nodes.push_back(node);
        }
        const std::size_t values = 3 + (parametric == 1 ? entity_dimension : 0);
        for (int i = 0; i < count; ++i) {
            Node& node = content.nodes[first + i];
            require_entry(in, section, "coordinates of node tag " + std::to_string(node.tag));
            in.expect_token_count(values, "coordinates of node tag " + std::to_string(node.tag));
            for (int k = 0; k < 3; ++k)
                node.x[k] = in.number(k, std::string("coordinate ") + "xyz"[k] + " of node tag " + std::to_string(node.tag));
            node.line = in.line_number();
        }
        read += count;
    }
    if (read != total)
        in.fail("the node blocks hold " + std::to_string(read) + " nodes, the $Nodes header says " +
                std::to_string(total));
    require_section_end(in, section);
}

int physical_tag_of(const EntityPhysicals& physicals, int dimension, int entity, const TextLineReader& in)
{
    const auto found = physicals.find({dimension, entity});
    if (found == physicals.end() || found->second.empty())
        return 0;
    if (found->second.size() > 1)
        in.fail("entity " + std::to_string(entity) + " of dimension " + std::to_string(dimension) + " is in " +
                std::to_string(found->second.size()) +
                " physical groups; sinew gives each element exactly one group");
    return found->second.front();
}

void read_elements(TextLineReader& in, const EntityPhysicals& physicals, Content& content)
{
    const std::string section = "$Elements";
    require_entry(in, section, "the element counts");
    in.expect_token_count(4, "element counts (blocks, elements, min tag, max tag)");
    const int blocks = in.integer(0, "number of element blocks");
    const int total = in.integer(1, "number of elements");
    int read = 0;
    for (int b = 0; b < blocks; ++b) {
        require_entry(in, section, "element block " + std::to_string(b + 1) + " of " + std::to_string(blocks));
        in.expect_token_count(4, "element block header (entity dim, entity tag, type, elements)");
        const int entity_dimension = in.integer(0, "entity dimension");
        const int entity = in.integer(1, "entity tag");
        const int type = in.integer(2, "element type");
        const int count = in.integer(3, "number of elements in block");
        if (entity_dimension < 0 || entity_dimension > 3)
            in.fail("entity dimension is " + std::to_string(entity_dimension) + ", expected 0 to 3");
        if (count < 0)
            in.fail("number of elements in block is " + std::to_string(count));
        const TypeUse use = type_use(type);
        if (use == TypeUse::reject)
            in.fail("element type " + std::to_string(type) + " (" + type_name(type) +
                    ") is not supported: sinew reads 4-node tetrahedra and 3-node triangles");
        const int physical = use == TypeUse::keep ? physical_tag_of(physicals, entity_dimension, entity, in) : 0;
        for (int i = 0; i < count; ++i) {
            require_entry(in, section, "element " + std::to_string(i + 1) + " of block " + std::to_string(b + 1));
            if (use == TypeUse::ignore)
                continue;
            const int corners = kept_type_nodes(type);
            in.expect_token_count(1 + corners, "element of type " + std::to_string(type));
            in.integer(0, "element tag");
            Element element;
            element.type = type;
            element.physical_tag = physical;
            for (int k = 0; k < corners; ++k)
                element.node_tags.push_back(in.integer(1 + k, "node tag"));
            require_distinct_node_tags(in, element.node_tags);
            element.line = in.line_number();
            content.elements.push_back(element);
        }
        read += count;
    }
    if (read != total)
        in.fail("the element blocks hold " + std::to_string(read) + " elements, the $Elements header says " +
                std::to_string(total));
    require_section_end(in, section);
}

} // namespace

Content parse_msh4(TextLineReader& in)
{
    Content content;
    EntityPhysicals physicals;
    while (in.next()) {
        const std::string section = in.token(0);
        if (section == "$PhysicalNames")
            read_physical_names(in, content);
        else if (section == "$Entities")
            read_entities(in, physicals);
        else if (section == "$Nodes")
            read_nodes(in, content);
        else if (section == "$Elements")
            read_elements(in, physicals, content);
        else if (section == "$PartitionedEntities")
            in.fail("partitioned MSH files are not supported: save the mesh unpartitioned");
        else if (section[0] == '$')
            skip_section(in, section);
        else
            in.fail("expected a section ($Nodes, $Elements, ...), found '" + section + "'");
    }
    return content;
}

} // namespace sinew::gmsh
