#pragma once
// The TOML scanner lives in core so the settings file (platform) can use the same guards as
// the level loader; these names keep the level code reading as before.
#include "core/text/toml_scan.h"

namespace bz::level {
using bz::DeepKey;
using bz::find_deep_key;
using bz::find_unsafe_char;
using bz::line_start;
using bz::scan;
using bz::ScanState;
using bz::UnsafeChar;
}  // namespace bz::level
