// Moved to geometry/import/import.h. This forwarder stays until src/render and
// tests/render (edited on another branch during the regrouping) include the new path.
#pragma once
#include "geometry/import/import.h"
