#include "app/resource_limits.h"

#include <sys/resource.h>

#include <cstdlib>
#include <string>

namespace bz::app {

void limit_memory_for_untrusted_input() {
#if defined(__SANITIZE_ADDRESS__)
    // ASan maps its shadow memory and allocator arenas up front, which a data-segment cap
    // would starve; sanitizer runs cap allocations with ASAN_OPTIONS=max_allocation_size_mb.
    return;
#endif
    unsigned long long mb = 8192;
    if (const char* env = std::getenv("BEAMZONE_MEMORY_LIMIT_MB"); env && *env) {
        mb = std::strtoull(env, nullptr, 10);
    }
    if (mb == 0) return;
    rlimit current{};
    if (getrlimit(RLIMIT_DATA, &current) != 0) return;
    const rlim_t want = static_cast<rlim_t>(mb) << 20;
    if (current.rlim_cur != RLIM_INFINITY && current.rlim_cur <= want) return;
    rlimit next = current;
    next.rlim_cur = want;
    setrlimit(RLIMIT_DATA, &next);
}

}  // namespace bz::app
