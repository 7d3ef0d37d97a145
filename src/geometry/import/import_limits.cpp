#include "geometry/import/import_limits.h"

#include <cerrno>
#include <cstdlib>

namespace bz::geo {

ImportLimits default_import_limits() {
    ImportLimits limits;
    if (const char* env = std::getenv("BEAMZONE_MEMORY_LIMIT_MB"); env && *env) {
        errno = 0;
        char* end = nullptr;
        const unsigned long long mb = std::strtoull(env, &end, 10);
        // A malformed value keeps the default rather than silently lifting the cap.
        if (errno == 0 && end && *end == '\0' && mb < (1ull << 40)) limits.memory_bytes = mb << 20;
    }
    return limits;
}

}  // namespace bz::geo
