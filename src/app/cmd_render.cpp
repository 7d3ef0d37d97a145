#include <cstdio>

#include "app/commands.h"

namespace bz::app {

int cmd_render(Args) {
    std::fprintf(stderr, "beamzone render: not built yet\n");
    return 2;
}

}  // namespace bz::app
