#pragma once

namespace bz::app {

// Caps the process's data segment (heap and anonymous mappings) so that a hostile model file
// that makes a loader reserve hundreds of gigabytes fails with bad_alloc, which the loader
// reports as an error, instead of swapping the machine to death. The cap is
// BEAMZONE_MEMORY_LIMIT_MB (default 8192; 0 = no cap).
void limit_memory_for_untrusted_input();

}  // namespace bz::app
