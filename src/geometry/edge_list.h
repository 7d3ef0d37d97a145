// Moved to geometry/derived/edge_list.h. This forwarder stays until src/render and
// tests/render (edited on another branch during the regrouping) include the new path.
#pragma once
#include "geometry/derived/edge_list.h"
