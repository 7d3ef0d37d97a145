// toml++'s implementation compiled into the fuzz target, so the parser itself carries
// coverage and sanitizer instrumentation (the packaged shared library has neither).
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>
