// Moved to geometry/reference/reference.h. This forwarder stays until src/render and
// tests/render (edited on another branch during the regrouping) include the new path.
#pragma once
#include "geometry/reference/reference.h"
