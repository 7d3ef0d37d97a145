#pragma once
// The one place that includes the generated loader. Only src/gl, src/render and
// src/platform include this; game and level code never see GL.
#include <glad/gl.h>
