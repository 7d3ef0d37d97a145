#pragma once
// The command layouts of GL's indirect draws, as glDrawElementsIndirect and
// glMultiDrawElementsIndirect read them from a buffer: written by the CPU (the prepass's
// cluster draws) or by a shader (the edge buffer's quad draws).
#include <cstdint>

namespace bz::gl {

// DrawElementsIndirectCommand.
struct DrawElementsIndirectCommand {
    std::uint32_t count = 0;
    std::uint32_t instance_count = 1;
    std::uint32_t first_index = 0;
    std::int32_t base_vertex = 0;
    std::uint32_t base_instance = 0;
};
static_assert(sizeof(DrawElementsIndirectCommand) == 20, "the GL command layout");

}  // namespace bz::gl
