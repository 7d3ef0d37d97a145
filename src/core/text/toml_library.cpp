// toml++'s implementation, compiled once for the whole game against core/text/toml.h, which
// replaces a lookup with undefined behaviour on some non-ASCII input (see that header).
#define TOML_IMPLEMENTATION
#include "core/text/toml.h"
