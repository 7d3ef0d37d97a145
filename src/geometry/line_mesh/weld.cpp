#include "geometry/line_mesh/weld.h"

#include <bit>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/line_mesh/hash_mix.h"

namespace bz::geo {
namespace {

constexpr std::uint32_t kEmptySlot = std::numeric_limits<std::uint32_t>::max();

// The key is the position's bit pattern, with -0.0 folded onto +0.0 so both weld together.
struct PositionKey {
    std::uint32_t x, y, z;
    bool operator==(const PositionKey&) const = default;
};

std::uint32_t canonical_bits(float f) {
    return f == 0.0f ? 0u : std::bit_cast<std::uint32_t>(f);
}

PositionKey key_of(const glm::vec3& p) {
    return {canonical_bits(p.x), canonical_bits(p.y), canonical_bits(p.z)};
}

// Open addressing with linear probing over welded ids; keys are compared against the welded
// positions. Slots are 4 bytes so the table stays small enough to be cheap to allocate and
// mostly cache-resident.
class PositionTable {
  public:
    PositionTable(std::size_t max_items, const std::vector<glm::vec3>& welded)
        : slots_(detail::table_size_for(max_items), kEmptySlot),
          shift_(64 - std::countr_zero(slots_.size())),
          welded_(welded) {}

    // Returns the id of the welded vertex at key, or kEmptySlot after reserving a slot for
    // `next_id`, which the caller must then append to the welded positions.
    std::uint32_t find_or_insert(const PositionKey& key, std::uint32_t next_id) {
        const std::size_t mask = slots_.size() - 1;
        std::size_t i = detail::hash3(key.x, key.y, key.z) >> shift_;
        for (;; i = (i + 1) & mask) {
            const std::uint32_t id = slots_[i];
            if (id == kEmptySlot) {
                slots_[i] = next_id;
                return kEmptySlot;
            }
            if (key_of(welded_[id]) == key) return id;
        }
    }

  private:
    std::vector<std::uint32_t> slots_;
    int shift_;
    const std::vector<glm::vec3>& welded_;
};

void check_shape(const TriMesh& mesh) {
    if (mesh.indices.size() % 3 != 0) {
        throw std::invalid_argument("weld_positions: index count " +
                                    std::to_string(mesh.indices.size()) +
                                    " is not a multiple of 3");
    }
    if (mesh.positions.size() >= kEmptySlot) {
        throw std::invalid_argument("weld_positions: too many vertices");
    }
}

[[noreturn]] void throw_bad_index(std::uint32_t v, std::size_t count) {
    throw std::invalid_argument("weld_positions: index " + std::to_string(v) + " out of range (" +
                                std::to_string(count) + " vertices)");
}

}  // namespace

WeldedMesh weld_positions(const TriMesh& mesh) {
    check_shape(mesh);
    const std::size_t vertex_count = mesh.positions.size();
    std::vector<std::uint32_t> remap(vertex_count, kEmptySlot);
    WeldedMesh out;
    PositionTable table(vertex_count, out.positions);
    out.triangles.resize(mesh.indices.size());
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        const std::uint32_t v = mesh.indices[i];
        if (v >= vertex_count) throw_bad_index(v, vertex_count);
        std::uint32_t id = remap[v];
        if (id == kEmptySlot) {
            const auto next = static_cast<std::uint32_t>(out.positions.size());
            id = table.find_or_insert(key_of(mesh.positions[v]), next);
            if (id == kEmptySlot) {
                id = next;
                out.positions.push_back(mesh.positions[v]);
            }
            remap[v] = id;
        }
        out.triangles[i] = id;
    }
    return out;
}

}  // namespace bz::geo
