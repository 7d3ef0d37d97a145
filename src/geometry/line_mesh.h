// Moved to geometry/line_mesh/line_mesh.h. This forwarder stays until src/render and
// tests/render (edited on another branch during the regrouping) include the new path.
#pragma once
#include "geometry/line_mesh/line_mesh.h"
