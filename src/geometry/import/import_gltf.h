#pragma once
// glTF scene graphs may share nodes: a node listed as a child of several parents. Assimp
// copies a shared node once per path from a root, so 40 levels of two parents sharing one
// child become 2^40 nodes (a 1.3 KB .glb took the game past 11 GB in 32 s). The node
// instances are counted here from the JSON before Assimp sees the file, with a budget.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace bz::geo::detail {

// True when the file is a binary glTF (.glb) by its magic number.
bool looks_like_glb(std::string_view head);

// The JSON chunk of a .glb file, or nullopt when the container is malformed (Assimp then
// reports what is wrong).
std::optional<std::string> glb_json_chunk(int fd, std::uintmax_t file_size);

// Given a glTF document (1.0 or 2.0), returns why it is refused: a node that is its own
// ancestor, or more node instances reachable from the roots than `max_instances`. nullopt
// when it is within the budget or is not JSON at all (Assimp reports that).
std::optional<std::string> gltf_nodes_over_limit(std::string_view json,
                                                 std::uint64_t max_instances);

}  // namespace bz::geo::detail
