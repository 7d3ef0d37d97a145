#include "geometry/import/import_gltf.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <unordered_map>
#include <vector>

namespace bz::geo::detail {
namespace {

using nlohmann::json;

std::uint32_t le32(const unsigned char* p) {
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

bool read_at(int fd, void* out, std::size_t bytes, off_t at) {
    auto* p = static_cast<char*>(out);
    std::size_t got = 0;
    while (got < bytes) {
        const ssize_t n = ::pread(fd, p + got, bytes - got, at + static_cast<off_t>(got));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        got += static_cast<std::size_t>(n);
    }
    return true;
}

// The graph as child lists by node index; glTF 1.0 names nodes by id strings instead.
struct Graph {
    std::vector<std::vector<std::size_t>> children;
    std::vector<std::size_t> roots;
    std::vector<std::string> names;  // for messages
};

std::optional<std::size_t> node_ref(const json& ref, const Graph& g,
                                    const std::unordered_map<std::string, std::size_t>& ids) {
    if (ref.is_number_unsigned()) {
        const auto i = ref.get<std::uint64_t>();
        if (i < g.children.size()) return static_cast<std::size_t>(i);
    } else if (ref.is_string()) {
        if (auto it = ids.find(ref.get<std::string>()); it != ids.end()) return it->second;
    }
    return std::nullopt;  // a bad reference: Assimp reports it
}

Graph read_graph(const json& doc) {
    Graph g;
    const json* nodes = doc.is_object() && doc.contains("nodes") ? &doc["nodes"] : nullptr;
    std::unordered_map<std::string, std::size_t> ids;
    std::vector<const json*> node_list;
    if (nodes && nodes->is_array()) {
        for (const json& n : *nodes) node_list.push_back(&n);
        for (std::size_t i = 0; i < node_list.size(); ++i) g.names.push_back(std::to_string(i));
    } else if (nodes && nodes->is_object()) {  // glTF 1.0
        for (const auto& [id, n] : nodes->items()) {
            ids.emplace(id, node_list.size());
            g.names.push_back("'" + id.substr(0, 40) + "'");
            node_list.push_back(&n);
        }
    }
    g.children.resize(node_list.size());
    std::vector<bool> is_child(node_list.size(), false);
    for (std::size_t i = 0; i < node_list.size(); ++i) {
        const json& n = *node_list[i];
        if (!n.is_object() || !n.contains("children") || !n["children"].is_array()) continue;
        for (const json& c : n["children"]) {
            if (auto k = node_ref(c, g, ids)) {
                g.children[i].push_back(*k);
                is_child[*k] = true;
            }
        }
    }
    // Every scene's roots (an importer takes one scene; counting all of them is on the safe
    // side), or without scenes every node no one lists as a child.
    if (doc.contains("scenes")) {
        auto add_scene = [&](const json& s) {
            if (!s.is_object() || !s.contains("nodes") || !s["nodes"].is_array()) return;
            for (const json& r : s["nodes"]) {
                if (auto k = node_ref(r, g, ids)) g.roots.push_back(*k);
            }
        };
        const json& scenes = doc["scenes"];
        if (scenes.is_array()) {
            for (const json& s : scenes) add_scene(s);
        } else if (scenes.is_object()) {
            for (const auto& item : scenes.items()) add_scene(item.value());
        }
    }
    if (g.roots.empty()) {
        for (std::size_t i = 0; i < node_list.size(); ++i) {
            if (!is_child[i]) g.roots.push_back(i);
        }
    }
    return g;
}

enum class Mark : std::uint8_t { unseen, open, done };

// Instances of each node's subtree (itself included), saturating just past the budget, by an
// explicit-stack depth-first walk (a deep chain cannot overflow our stack). A node reached
// again while still open is its own ancestor.
struct Counter {
    Counter(const Graph& graph, std::uint64_t saturate_at)
        : g(graph),
          cap(saturate_at),
          mark(graph.children.size(), Mark::unseen),
          count(graph.children.size(), 0) {}

    const Graph& g;
    std::uint64_t cap;
    std::vector<Mark> mark;
    std::vector<std::uint64_t> count;
    std::optional<std::size_t> cycle_at;

    std::uint64_t add(std::uint64_t a, std::uint64_t b) const { return a + b > cap ? cap : a + b; }

    std::uint64_t of(std::size_t root) {
        if (mark[root] == Mark::done) return count[root];
        struct Frame {
            std::size_t node;
            std::size_t next_child;
        };
        std::vector<Frame> stack{{root, 0}};
        mark[root] = Mark::open;
        while (!stack.empty()) {
            Frame& f = stack.back();
            const auto& kids = g.children[f.node];
            if (f.next_child < kids.size()) {
                const std::size_t k = kids[f.next_child++];
                if (mark[k] == Mark::open) {
                    cycle_at = k;
                    return cap;
                }
                if (mark[k] == Mark::unseen) {
                    mark[k] = Mark::open;
                    stack.push_back({k, 0});
                }
                continue;
            }
            std::uint64_t total = 1;
            for (std::size_t k : kids) total = add(total, count[k]);
            count[f.node] = total;
            mark[f.node] = Mark::done;
            stack.pop_back();
        }
        return count[root];
    }
};

}  // namespace

bool looks_like_glb(std::string_view head) {
    return head.substr(0, 4) == "glTF";
}

std::optional<std::string> glb_json_chunk(int fd, std::uintmax_t file_size) {
    unsigned char header[20];
    if (file_size < sizeof header || !read_at(fd, header, sizeof header, 0)) return std::nullopt;
    const std::uint32_t version = le32(header + 4);
    std::uint64_t length = 0;
    if (version == 1) {
        // glTF 1.0 binary: content length and format (0 = JSON) after the 12-byte header.
        length = le32(header + 12);
        if (le32(header + 16) != 0) return std::nullopt;
    } else {
        length = le32(header + 12);
        if (std::memcmp(header + 16, "JSON", 4) != 0) return std::nullopt;
    }
    if (length > file_size - sizeof header) return std::nullopt;
    std::string text(static_cast<std::size_t>(length), '\0');
    if (!read_at(fd, text.data(), text.size(), sizeof header)) return std::nullopt;
    return text;
}

std::optional<std::string> gltf_nodes_over_limit(std::string_view text,
                                                 std::uint64_t max_instances) {
    // Depth is bounded by nlohmann's parser callback-free recursion on nesting; cap it first so
    // a document of a million '[' cannot overflow the stack.
    std::size_t depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (char c : text) {
        if (in_string) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                in_string = false;
            continue;
        }
        if (c == '"')
            in_string = true;
        else if (c == '[' || c == '{')
            deepest = std::max(deepest, ++depth);
        else if ((c == ']' || c == '}') && depth > 0)
            --depth;
    }
    if (deepest > 256) return "glTF JSON nested " + std::to_string(deepest) + " levels deep";
    const json doc = json::parse(text, nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) return std::nullopt;
    const Graph g = read_graph(doc);
    Counter counter(g, max_instances + 1);
    std::uint64_t total = 0;
    for (std::size_t r : g.roots) {
        total = counter.add(total, counter.of(r));
        if (counter.cycle_at) {
            return "glTF node " + g.names[*counter.cycle_at] + " is its own ancestor";
        }
        if (total > max_instances) {
            return "glTF scene graph reaches more than " + std::to_string(max_instances) +
                   " node instances (" + std::to_string(g.children.size()) +
                   " nodes, shared by several parents)";
        }
    }
    return std::nullopt;
}

}  // namespace bz::geo::detail
