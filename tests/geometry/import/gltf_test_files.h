#pragma once
// Small glTF 2.0 files for the import tests: one triangle in a buffer, nodes as given.
#include <cstdint>
#include <cstring>
#include <string>

namespace bz::geo::test {

// 3 float3 positions then 3 uint16 indices: 42 bytes.
inline std::string triangle_buffer() {
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint16_t idx[3] = {0, 1, 2};
    std::string bin(42, '\0');
    std::memcpy(bin.data(), pos, sizeof pos);
    std::memcpy(bin.data() + 36, idx, sizeof idx);
    return bin;
}

// A glTF document with one triangle mesh; `buffer` is the buffer's JSON (its uri, if any),
// `nodes` and `scene_nodes` the JSON arrays.
inline std::string gltf_json(const std::string& buffer, const std::string& nodes,
                             const std::string& scene_nodes) {
    return R"({"asset": {"version": "2.0"},
  "buffers": [)" +
           buffer + R"(],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36, "target": 34962},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6, "target": 34963}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
  "nodes": )" +
           nodes + R"(,
  "scenes": [{"nodes": )" +
           scene_nodes + R"(}],
  "scene": 0})";
}

inline void append_u32(std::string& s, std::uint32_t v) {
    s.append(reinterpret_cast<const char*>(&v), 4);
}

// A .glb container: the JSON chunk and the triangle buffer as its BIN chunk.
inline std::string glb(std::string json) {
    while (json.size() % 4) json.push_back(' ');
    std::string bin = triangle_buffer();
    while (bin.size() % 4) bin.push_back('\0');
    std::string out = "glTF";
    append_u32(out, 2);
    append_u32(out, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    append_u32(out, static_cast<std::uint32_t>(json.size()));
    out += "JSON";
    out += json;
    append_u32(out, static_cast<std::uint32_t>(bin.size()));
    out += std::string("BIN\0", 4);
    out += bin;
    return out;
}

// `levels` levels of two nodes each; both nodes of a level share both nodes of the next as
// children, so the paths from the roots double with every level. The last level has the mesh.
inline std::string dag_nodes(int levels) {
    std::string nodes = "[";
    for (int level = 0; level < levels; ++level) {
        for (int k = 0; k < 2; ++k) {
            if (level || k) nodes += ",";
            if (level + 1 < levels) {
                const int next = 2 * (level + 1);
                nodes += "{\"children\": [" + std::to_string(next) + "," +
                         std::to_string(next + 1) + "]}";
            } else {
                nodes += "{\"mesh\": 0}";
            }
        }
    }
    return nodes + "]";
}

}  // namespace bz::geo::test
